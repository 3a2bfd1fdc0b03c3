; The fixed workload of `alp85 bench cpu`: an endless loop of what the thesis firmware spends its
; time on, plus a CRC. Runs from 0000H in 64 KiB of RAM; OUT to port F9H (the motor port) goes to
; an unmapped port. Deterministic: the same T-states give the same instruction count every time.
;   1. DL, the firmware's 1 ms delay loop (3070 T-states per pass at 8085 timing), 2 passes
;   2. a 16 x 16 -> 32-bit shift-and-add multiply
;   3. an 8-digit BCD addition with DAA
;   4. CRC-16/CCITT, bit by bit, over 256 bytes
;   5. a motor half-step pattern written to port F9H
MOTOR   EQU     0F9H
        INCLUDE crc16.inc       ; CRC16BITS

        ORG     0
        LXI     SP,0FF00H
        LXI     H,DATA          ; fill the CRC buffer with a fixed pattern
        MVI     B,0
        MVI     A,5AH
FILL:   MOV     M,A
        ADI     3BH
        RLC
        INX     H
        DCR     B
        JNZ     FILL

MAIN:   MVI     A,2
        CALL    DL
        LHLD    MCAND
        XCHG
        LHLD    MPLIER
        MOV     B,H
        MOV     C,L
        CALL    MUL16
        SHLD    PROD
        LHLD    MPLIER          ; vary the operands from pass to pass
        INX     H
        SHLD    MPLIER
        CALL    BCDADD
        CALL    CRC16
        SHLD    CRC
        MVI     A,01H           ; X pulse high then low, as the firmware's step routine does
        OUT     MOTOR
        XRA     A
        OUT     MOTOR
        JMP     MAIN

        INCLUDE dl.inc          ; DL: wait A milliseconds
        INCLUDE mul16.inc       ; MUL16: HL:PRODLO = DE x BC

; SUM = SUM + ADDEND, 4 bytes of packed BCD, least significant byte first
BCDADD: LXI     H,SUM
        LXI     D,ADDEND
        MVI     B,4
        ORA     A
BCDL:   LDAX    D
        ADC     M
        DAA
        MOV     M,A
        INX     H
        INX     D
        DCR     B
        JNZ     BCDL
        RET

; HL = CRC-16/CCITT (polynomial 1021H, initial FFFFH) of the 256 bytes at DATA
CRC16:  LXI     H,0FFFFH
        LXI     D,DATA
        MVI     C,0
CRCB:   LDAX    D
        XRA     H
        MOV     H,A
        CRC16BITS
        INX     D
        DCR     C
        JNZ     CRCB
        RET

MCAND:  DW      1234H
MPLIER: DW      5678H
PROD:   DW      0
PRODLO: DW      0
CRC:    DW      0
SUM:    DB      0,0,0,0
ADDEND: DB      67H,45H,23H,01H
DATA:   DS      256
        END
