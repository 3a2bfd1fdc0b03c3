; ALP85 demo: a user program started from the monitor with R 7 0800 EXEC (thesis Appendix C).
; It greets with "HELLO 85" through the monitor's AUS, then echoes each hex key on the right-
; most digit through ANWAUS; EXEC returns to the monitor with RST 1.
        INCLUDE ../monitor/monitor.inc

        ORG     0800H
START:  LXI     SP,USERSP
        CALL    ANWAZL          ; blank the display
        LXI     H,GREET
        MVI     B,80H           ; digit 0, the leftmost; AUS moves B on by itself
SHOW:   MOV     A,M
        CALL    AUS
        INX     H
        MOV     A,B
        ORA     A               ; B = 80H again after the eighth digit (01H rotates to 80H)
        JP      SHOW
KEY:    CALL    ANWEIN          ; Z while no key is waiting
        JZ      KEY
        CPI     KEXEC
        JZ      DONE
        CPI     10H             ; CY: a hex key (00H-0FH)
        JNC     KEY
        MVI     B,01H           ; digit 7, the rightmost
        CALL    ANWAUS          ; show the hex digit in A
        JMP     KEY
DONE:   RST     1               ; back to the monitor, registers saved

; H E L L O (blank) 8 5: segments a = bit 0 ... g = bit 6
GREET:  DB      76H, 79H, 38H, 38H, 3FH, 00H, 7FH, 6DH
        END
