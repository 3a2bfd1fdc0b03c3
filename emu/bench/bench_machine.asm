; The machine-tool benchmark (alp85 bench machine): all three axes step together, 10 000 steps
; each at 400 steps/s (25 s of machine time), in ten strokes of 1000 steps, + and - in turn so that
; every table stays inside its travel (Z has 100 mm = 2000 steps), then HLT. Port A (F9H) as
; emu/board/board_map.h wires it: pulses on bits 0, 2, 4, directions on bits 1, 3, 5 (1 = +).
;
; One step is exactly 7680 T-states (2.5 ms at 3.072 MHz):
;   high: MOV 4 + ORI 7 + OUT 10 + LXI 10 + (24 x 158 - 3)                           = 3820
;   low:  MOV 4 + OUT 10 + MVI 7 + 4 x NOP 4 + LXI 10 + (24 x 158 - 3)
;         + DCX 6 + MOV 4 + ORA 4 + JNZ 10                                           = 3860
; each wait pass being DCX B 6 + MOV A,B 4 + ORA C 4 + JNZ 10 = 24 (the last JNZ 7).
PORTA   EQU     0F9H
DIRS    EQU     2AH             ; X, Y, Z directions +
PULSES  EQU     15H             ; the three pulse bits
WAIT    EQU     158

        ORG     0800H
START:  LXI     SP,20B0H
        MVI     A,01H           ; 8155: port A output, port B input
        OUT     0F8H
        MVI     D,DIRS          ; the first stroke goes +
        MVI     E,10            ; strokes
STROKE: MOV     A,D
        OUT     PORTA           ; the new direction, pulses low
        LXI     H,1000
STEP:   MOV     A,D
        ORI     PULSES
        OUT     PORTA           ; the rising edges: every axis steps
        LXI     B,WAIT
W1:     DCX     B
        MOV     A,B
        ORA     C
        JNZ     W1
        MOV     A,D
        OUT     PORTA           ; the pulses low
        MVI     A,0             ; padding: 23 T-states
        NOP
        NOP
        NOP
        NOP
        LXI     B,WAIT
W2:     DCX     B
        MOV     A,B
        ORA     C
        JNZ     W2
        DCX     H
        MOV     A,H
        ORA     L
        JNZ     STEP
        MOV     A,D
        XRI     DIRS            ; the other way
        MOV     D,A
        DCR     E
        JNZ     STROKE
DONE:   HLT
        END     START
