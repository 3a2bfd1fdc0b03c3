; The five monitor entry points called as the thesis firmware calls them. Each section loads
; known registers and flags, calls, and halts: the test reads the display, presses VECT INTR
; (the monitor saves the registers at 20B0H-20BCH), then GO EXEC continues with the next section.
; docs/monitor.md gives each routine's contract; the expected values are in the tests.
        INCLUDE "../../../firmware/monitor/monitor.inc"

; A and flags together: PUSH H / POP PSW puts H in A and L in the flags.
SETAF   MACRO   AF
        LXI     H,AF
        PUSH    H
        POP     PSW
        ENDM
SETREGS MACRO   BC
        LXI     B,BC
        LXI     D,5678H
        LXI     H,9ABCH
        ENDM

        ORG     0800H
; 1. ANWAZL blanks a full display; keeps every register and the flags.
S1:     MVI     A,90H           ; 8279: write display RAM from digit 0, auto-increment
        OUT     0E1H
        MVI     A,7FH           ; "88888888"
        REPT    8
        OUT     0E0H
        ENDM
        SETAF   0A5D5H          ; A = A5H, flags S Z AC P CY
        SETREGS 1234H
        CALL    ANWAZL
        HLT

; 2. AUS right after the thesis's start-up command (OUT E1H with 0D1H, clear all): digit 0.
S2:     MVI     A,0D1H
        OUT     0E1H
        SETAF   7695H           ; A = 76H ("H"), flags S AC P CY
        SETREGS 8034H           ; B = 80H: digit 0
        CALL    AUS
        HLT

; 3. BITTI as the thesis writes it: five codes from digit 2, B never reloaded.
S3:     CALL    ANWAZL
        MVI     B,20H
        MVI     A,7FH
        CALL    AUS
        MVI     A,04H
        CALL    AUS
        MVI     A,78H
        CALL    AUS
        CALL    AUS
        MVI     A,04H
        CALL    AUS
        HLT

; 4. AUS wraps from digit 7 to digit 0; B = 0 writes nothing.
S4:     MVI     B,01H
        MVI     A,5BH           ; "2" on digit 7
        CALL    AUS
        MVI     A,66H           ; "4" on digit 0
        CALL    AUS
        MVI     B,0
        MVI     A,7FH
        CALL    AUS
        HLT

; 5. UMW for the sixteen digits (codes to 1100H-110FH), then A5H: bits 7-4 are ignored.
N       SET     0
S5:     REPT    16
        MVI     A,N
        CALL    UMW
        STA     1100H+N
N       SET     N+1
        ENDM
        SETREGS 1234H
        MVI     A,0A5H
        CALL    UMW
        HLT

; 6. ANWAUS: "C" on digit 6, then 3FH ("F", bits 7-4 ignored) on digit 7, B wraps to 80H.
S6:     CALL    ANWAZL
        SETAF   0CD5H
        SETREGS 0234H           ; B = 02H: digit 6
        CALL    ANWAUS
        HLT
S7:     SETAF   3F95H
        LXI     H,9ABCH
        CALL    ANWAUS
        HLT

; 8. ANWEIN with nothing in the FIFO: returns at once, Z.
S8:     SETAF   0FF00H
        SETREGS 1234H
        CALL    ANWEIN
        HLT

; 9, 10. ANWEIN polled as BASLA does: the test presses 0, then EXEC.
S9:     SETREGS 1234H
S9A:    CALL    ANWEIN
        JZ      S9A
        HLT
S10:    CALL    ANWEIN
        JZ      S10
        HLT
        RST     1
        END
