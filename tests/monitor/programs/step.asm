; Single-step target in RAM: instructions of 4 to 18 T-states, a call and a HLT.
        INCLUDE "../../../firmware/monitor/monitor.inc" ; SAVEA, SAVEPC, ... for scripts
        ORG     1000H
        MVI     A,01H           ; 1000H  7 T-states
        INR     A               ; 1002H  4
        NOP                     ; 1003H  4
        CALL    SUB             ; 1004H 18
        HLT                     ; 1007H  5
SUB:    PUSH    B               ; 1008H 12
        POP     B               ; 1009H 10
        RET                     ; 100AH 10
        END
