; Arithmetic the way the thesis firmware does it, checked by the program itself and printed:
;   1. 16 x 16 -> 32-bit unsigned multiply by shift and add: 1234H x 5678H = 0626 0060H
;   2. 4-digit BCD addition with DAA: 4795 + 3867 = 8662 (BCD), carry 0
;   3. 16-bit subtraction with borrow: 1000H - 0FFFH = 0001H; 0000H - 0001H = 0FFFFH, borrow
; Prints "MUL 06260060 BCD 8662 SUB 0001 FFFF" and a verdict, then warm boots. On a wrong
; result it prints "FAIL" and halts (alp85 cpm then exits non-zero).
BDOS    EQU     5

        ORG     100H
START:  LXI     SP,STACK
; ---- 1. multiply: DE x BC -> HL:IX (high word in HL, low word in PRODLO)
        LXI     D,1234H
        LXI     B,5678H
        CALL    MUL16
        SHLD    PRODHI
        MVI     C,9
        LXI     D,MSGMUL
        CALL    BDOS
        LHLD    PRODHI
        CALL    PHEX16
        LHLD    PRODLO
        CALL    PHEX16
; ---- 2. BCD add: 4795 + 3867
        MVI     A,95H
        ADI     67H
        DAA
        STA     BCD
        MVI     A,47H
        ACI     38H
        DAA
        STA     BCD+1
        RAL                     ; the decimal carry into bit 0
        ANI     1
        STA     BCDCY
        MVI     C,9
        LXI     D,MSGBCD
        CALL    BDOS
        LHLD    BCD
        CALL    PHEX16
; ---- 3. 16-bit subtraction
        LXI     H,1000H
        LXI     D,0FFFH
        CALL    SUB16
        SHLD    DIFF1
        LXI     H,0
        LXI     D,1
        CALL    SUB16
        SHLD    DIFF2
        RAL
        ANI     1
        STA     BORROW
        MVI     C,9
        LXI     D,MSGSUB
        CALL    BDOS
        LHLD    DIFF1
        CALL    PHEX16
        MVI     E,' '
        MVI     C,2
        CALL    BDOS
        LHLD    DIFF2
        CALL    PHEX16
; ---- verdict
        LXI     H,CHECKS
        LXI     D,PRODHI
        MVI     B,CHKLEN
CHK:    LDAX    D
        CMP     M
        JNZ     FAIL
        INX     H
        INX     D
        DCR     B
        JNZ     CHK
        MVI     C,9
        LXI     D,MSGOK
        CALL    BDOS
        JMP     0
FAIL:   MVI     C,9
        LXI     D,MSGBAD
        CALL    BDOS
        HLT

; HL = HL - DE, CY = borrow
SUB16:  MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     H,A
        RET

        INCLUDE mul16.inc       ; MUL16: HL:PRODLO = DE x BC

; print HL as four hex digits
PHEX16: MOV     A,H
        CALL    PHEX8
        MOV     A,L
PHEX8:  PUSH    PSW
        RRC
        RRC
        RRC
        RRC
        CALL    PNIB
        POP     PSW
PNIB:   ANI     0FH
        ADI     90H             ; the classic DAA trick: 0-9 -> '0'-'9', A-F -> 'A'-'F'
        DAA
        ACI     40H
        DAA
        PUSH    H
        MOV     E,A
        MVI     C,2
        CALL    BDOS
        POP     H
        RET

MSGMUL: DB      'MUL $'
MSGBCD: DB      ' BCD $'
MSGSUB: DB      ' SUB $'
MSGOK:  DB      13,10,'ARITH OK',13,10,'$'
MSGBAD: DB      13,10,'ARITH FAIL',13,10,'$'

; expected values, worked out by hand, in the order of the results below
CHECKS: DW      0626H, 0060H    ; 1234H x 5678H = 06260060H
        DW      8662H           ; 4795 + 3867 = 8662
        DB      0               ; no decimal carry
        DW      0001H, 0FFFFH   ; the two differences
        DB      1               ; the second borrowed
CHKLEN  EQU     $-CHECKS

PRODHI: DW      0
PRODLO: DW      0
BCD:    DW      0
BCDCY:  DB      0
DIFF1:  DW      0
DIFF2:  DW      0
BORROW: DB      0

        DS      64
STACK:
        END     START
