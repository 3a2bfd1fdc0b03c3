; Drives Y 120 steps in - from the power-on position: the low end stop sits 5 mm = 100 steps below
; it (docs/machine.md, Table), so the last 20 steps are lost against the stop. Port A as in axes.asm.
; One step: MVI 7 + OUT 10 + MVI 7 + OUT 10 + MVI 7 + CALL 18 + DL(2) + MVI 7 + OUT 10 + MVI 7
; + CALL 18 + DL(2) + DCR 4 + JNZ 10 = 115 + 2 x 6147 = 12409 T-states (248 steps/s).
PORTA   EQU     0F9H

        ORG     0000H
START:  LXI     SP,20B0H
        MVI     A,01H           ; 8155: port A output, port B input
        OUT     0F8H
        MVI     C,120
STEP:   MVI     A,00H           ; Y direction - (bit 3 low), pulse low
        OUT     PORTA
        MVI     A,04H           ; Y pulse high: the step
        OUT     PORTA
        MVI     A,2
        CALL    DL
        MVI     A,00H
        OUT     PORTA
        MVI     A,2
        CALL    DL
        DCR     C
        JNZ     STEP
DONE:   HLT

        INCLUDE ../../firmware/lib/dl.inc
        END     START
