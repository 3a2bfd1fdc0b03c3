; Breakpoint and VECT INTR target in RAM: counts its loops in COUNT for ever.
COUNT   EQU     1100H
        INCLUDE "../../../firmware/monitor/monitor.inc" ; SAVEA, SAVEPC, ... for scripts
        ORG     1000H
START:  LXI     H,0             ; 1000H
        SHLD    COUNT           ; 1003H
LOOP:   LHLD    COUNT           ; 1006H
        INX     H               ; 1009H
        SHLD    COUNT           ; 100AH
        JMP     LOOP            ; 100DH
        END
