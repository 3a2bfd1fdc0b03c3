; GO target in the user EPROM: writes "HELL0" with the monitor's ANWAZL and AUS, waits for a key
; (ANWEIN), loads known registers and returns to the monitor with RST 1. Started again (GO,
; EXEC), it stores A at 1000H and returns once more.
        INCLUDE "../../../firmware/monitor/monitor.inc"
        ORG     0800H
HELLO:  CALL    ANWAZL
        MVI     B,80H           ; digit 0
        MVI     A,76H           ; H
        CALL    AUS
        MVI     A,79H           ; E
        CALL    AUS
        MVI     A,38H           ; L
        CALL    AUS
        CALL    AUS             ; L again: AUS keeps A
        MVI     A,3FH           ; 0
        CALL    AUS
WAIT:   CALL    ANWEIN
        JZ      WAIT
        LXI     H,0EFD5H        ; A = EFH, flags = D5H (S Z AC P CY)
        PUSH    H
        POP     PSW
        LXI     B,1234H
        LXI     D,5678H
        LXI     H,9ABCH
        RST     1
AGAIN:  STA     1000H
        RST     1
        HLT
        END
