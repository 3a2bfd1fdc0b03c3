; 200 X steps at 600 steps/s from standstill, then HLT: above the motor's start-stop limit of
; about 405 steps/s (docs/machine.md), so the physical motor loses steps.
; One step is exactly 5120 T-states (3.072 MHz / 600):
;   MOV 4 + ORI 7 + OUT 10 + LXI 10 + (24 x 105 - 3) + MOV 4 + OUT 10 + MVI 7 + LXI 10
;   + (24 x 105 - 3) + DCX 6 + MOV 4 + ORA 4 + JNZ 10 = 80 + 24 x 210 = 5120,
; each wait pass being DCX B 6 + MOV A,B 4 + ORA C 4 + JNZ 10 = 24 (the last JNZ 7).
PORTA   EQU     0F9H
WAIT    EQU     105

        ORG     0000H
START:  LXI     SP,20B0H
        MVI     A,01H           ; 8155: port A output, port B input
        OUT     0F8H
        MVI     D,02H           ; X direction +
        MOV     A,D
        OUT     PORTA
        LXI     H,200
STEP:   MOV     A,D
        ORI     01H
        OUT     PORTA           ; X pulse high: the step
        LXI     B,WAIT
W1:     DCX     B
        MOV     A,B
        ORA     C
        JNZ     W1
        MOV     A,D
        OUT     PORTA           ; pulse low
        MVI     A,0             ; padding: 7 T-states
        LXI     B,WAIT
W2:     DCX     B
        MOV     A,B
        ORA     C
        JNZ     W2
        DCX     H
        MOV     A,H
        ORA     L
        JNZ     STEP
DONE:   HLT
        END     START
