; A test program for the machine tool (not the thesis firmware): each axis 20 steps forward and
; 20 back, then a staircase of 10 X and 10 Y steps, then HLT. Port A (F9H) as the thesis wires it
; (emu/board/board_map.h): bit 0 X pulse, 1 X direction, 2 Y pulse, 3 Y direction, 4 Z pulse,
; 5 Z direction; the sequencer steps on the pulse's rising edge, direction 1 = +.
;
; One step (MOVE's loop): the direction with the pulse low, the pulse high for DL(2), low for DL(2):
;   MOV 4 + OUT 10 + ORA 4 + OUT 10 + MVI 7 + CALL 18 + DL(2) + MOV 4 + OUT 10 + MVI 7 + CALL 18
;   + DL(2) + DCR 4 + JNZ 10 = 106 + 2 DL(2), DL(2) = 3070 + 3067 + RET 10 = 6147 (firmware/lib/dl.inc)
;   = 12400 T-states = 4.036 ms a step, 248 steps/s: below the 400 steps/s start-stop limit of
;   thesis §5.1, so the physical motors lose no step.
PORTA   EQU     0F9H
CMD8155 EQU     0F8H

        ORG     0000H
START:  LXI     SP,20B0H
        MVI     A,01H           ; 8155 command: port A output, port B input, timer untouched
        OUT     CMD8155
        LXI     D,0201H         ; X +20
        CALL    MOVE20
XFWD:   LXI     D,0001H         ; X -20
        CALL    MOVE20
XBACK:  LXI     D,0804H         ; Y +20
        CALL    MOVE20
YFWD:   LXI     D,0004H         ; Y -20
        CALL    MOVE20
YBACK:  LXI     D,2010H         ; Z +20
        CALL    MOVE20
ZFWD:   LXI     D,0010H         ; Z -20
        CALL    MOVE20
ZBACK:  MVI     H,10            ; the staircase: (X +1, Y +1) ten times
STAIR:  LXI     D,0A01H
        MVI     C,1
        CALL    MOVE
        LXI     D,0A04H
        MVI     C,1
        CALL    MOVE
        DCR     H
        JNZ     STAIR
DONE:   HLT

MOVE20: MVI     C,20
; C steps; D = the direction bits (kept), E = the pulse bit.
MOVE:   MOV     A,D
        OUT     PORTA           ; direction, pulse low
        ORA     E
        OUT     PORTA           ; pulse high: the step
        MVI     A,2
        CALL    DL
        MOV     A,D
        OUT     PORTA           ; pulse low
        MVI     A,2
        CALL    DL
        DCR     C
        JNZ     MOVE
        RET

        INCLUDE ../../firmware/lib/dl.inc
        END     START
