; Board test: the 8155 timer in continuous pulse mode, its TIMER OUT wired to TRAP.
; Every terminal count traps to 0024H, which counts the traps in TRAPS (1000H-1001H).
RIOCMD  EQU     0F8H            ; 8155 command/status
TIMLO   EQU     0FCH            ; timer count, low byte
TIMHI   EQU     0FDH            ; timer count high 6 bits, mode in bits 7-6
TRAPS   EQU     1000H
COUNT   EQU     1000            ; terminal count every 1000 T-states

        ORG     0000H
        JMP     START
        ORG     0024H           ; TRAP
        PUSH    H
        LHLD    TRAPS
        INX     H
        SHLD    TRAPS
        POP     H
        RET

        ORG     0040H
START:  LXI     SP,20B0H
        LXI     H,0
        SHLD    TRAPS
        MVI     A,LOW COUNT
        OUT     TIMLO
        MVI     A,(HIGH COUNT) OR 0C0H  ; M2 M1 = 11: continuous pulse
        OUT     TIMHI
        MVI     A,0C0H          ; command: START the timer, ports A and B input
        OUT     RIOCMD
LOOP:   JMP     LOOP            ; 10 T-states: divides the 1000-T-state period evenly
        END
