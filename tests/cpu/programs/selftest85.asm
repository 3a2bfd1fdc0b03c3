; A self-checking test of what only an 8085 does: the undocumented instructions and flags
; (docs/cpu.md), RIM/SIM, bit 3 of PSW and ANA's AC. Prints "8085 SELF-TEST OK" and warm boots;
; on the first wrong result prints "FAIL nn" (the check number) and halts. Expected values are
; worked out by hand in the comments. Assemble with --cpu 8085u.
BDOS    EQU     5

        ORG     100H
START:  LXI     SP,STACK
; 1: DSUB  1234H - 0235H = 0FFFH
        MVI     A,1
        STA     TESTNO
        LXI     H,1234H
        LXI     B,0235H
        DSUB
        LXI     D,0FFFH
        CALL    CMPHD
; 2: ARHL  8003H -> 0C001H, CY = 1
        MVI     A,2
        STA     TESTNO
        LXI     H,8003H
        ORA     A               ; CY = 0 first
        ARHL
        JNC     FAIL
        LXI     D,0C001H
        CALL    CMPHD
; 3: RDEL  4001H with CY = 1 -> 8003H, CY = 0
        MVI     A,3
        STA     TESTNO
        LXI     D,4001H
        STC
        RDEL
        JC      FAIL
        XCHG
        LXI     D,8003H
        CALL    CMPHD
; 4: LDHI  12F5H + 10H -> DE = 1305H
        MVI     A,4
        STA     TESTNO
        LXI     H,12F5H
        LDHI    10H
        XCHG
        LXI     D,1305H
        CALL    CMPHD
; 5: LDSI  DE = SP + 2
        MVI     A,5
        STA     TESTNO
        LDSI    2
        LXI     H,2
        DAD     SP
        CALL    CMPHD
; 6: SHLX / LHLX through DE
        MVI     A,6
        STA     TESTNO
        LXI     D,BUF
        LXI     H,0BEEFH
        SHLX
        LXI     H,0
        LHLX
        LXI     D,0BEEFH
        CALL    CMPHD
        LDA     BUF
        CPI     0EFH
        JNZ     FAIL
; 7: K after a signed compare: -3 < 5 sets K, 5 < -3 does not
        MVI     A,7
        STA     TESTNO
        MVI     A,0FDH
        CPI     5
        JNK     FAIL
        MVI     A,5
        CPI     0FDH
        JK      FAIL
        MVI     A,80H           ; -128 < 1 although 80H - 01H overflows
        CPI     1
        JNK     FAIL
; 8: K after INX/DCX: the 16-bit carry and borrow
        MVI     A,8
        STA     TESTNO
        LXI     H,0FFFFH
        INX     H
        JNK     FAIL
        DCX     H
        JNK     FAIL
        INX     H
        INX     H
        DCX     H
        JK      FAIL
; 9: RSTV calls 0040H only when V is set
        MVI     A,9
        STA     TESTNO
        MVI     A,0C3H          ; JMP VHAND at 0040H
        STA     40H
        LXI     H,VHAND
        SHLD    41H
        XRA     A
        STA     VHIT
        MVI     A,1
        ADI     1               ; no overflow
        RSTV
        LDA     VHIT
        ORA     A
        JNZ     FAIL
        MVI     A,70H
        ADI     10H             ; +112 + 16 overflows: V = 1
        RSTV
        LDA     VHIT
        ORA     A
        JZ      FAIL
; 10: PSW bit 3 does not exist on the 8085; V and K do
        MVI     A,10H
        STA     TESTNO
        LXI     H,0FFFFH
        PUSH    H
        POP     PSW
        PUSH    PSW
        POP     H
        MOV     A,L
        CPI     0F7H
        JNZ     FAIL
; 11: RIM after reset: IE off, all three masked; SIM sets masks with MSE
        MVI     A,11H
        STA     TESTNO
        RIM
        ANI     0FH
        CPI     07H
        JNZ     FAIL
        MVI     A,0BH           ; MSE, M6.5 and M5.5 set, M7.5 clear
        SIM
        RIM
        ANI     07H
        CPI     03H
        JNZ     FAIL
        MVI     A,0FH           ; mask all again
        SIM
; 12: ANA/ANI always set AC on the 8085
        MVI     A,12H
        STA     TESTNO
        MVI     A,0F0H
        ANI     80H
        PUSH    PSW
        POP     H
        MOV     A,L
        ANI     10H
        JZ      FAIL
; all passed
        MVI     C,9
        LXI     D,MSGOK
        CALL    BDOS
        JMP     0

VHAND:  MVI     A,1
        STA     VHIT
        RET

; fail unless HL = DE
CMPHD:  MOV     A,H
        CMP     D
        JNZ     FAIL
        MOV     A,L
        CMP     E
        JNZ     FAIL
        RET

FAIL:   MVI     C,9
        LXI     D,MSGBAD
        CALL    BDOS
        LDA     TESTNO
        PUSH    PSW
        RRC
        RRC
        RRC
        RRC
        CALL    PNIB
        POP     PSW
        CALL    PNIB
        HLT

PNIB:   ANI     0FH
        ADI     90H
        DAA
        ACI     40H
        DAA
        MOV     E,A
        MVI     C,2
        JMP     BDOS

MSGOK:  DB      '8085 SELF-TEST OK',13,10,'$'
MSGBAD: DB      'FAIL $'
TESTNO: DB      0
VHIT:   DB      0
BUF:    DW      0
        DS      64
STACK:
        END     START
