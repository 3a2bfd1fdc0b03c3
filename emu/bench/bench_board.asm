; A CPU-bound workload for the board benchmark (alp85 bench board, tests/bench/board): the thesis firmware's kind of work (16-bit
; add/subtract through memory, the 1 ms delay loop DL) plus a CRC-16 loop, forever.
; Runs from the user EPROM with data in RAM and the stack in the 8155 RAM, as the firmware does.
        INCLUDE crc16.inc       ; CRC16BITS
        ORG     0800H
START:  LXI     SP,20B0H
MAIN:   LXI     H,0
        SHLD    1B00H
        MVI     C,200
ARITH:  LHLD    1B00H           ; 1B00H += 1234H, 1B02H -= 1B00H: the ADDSUB kind of work
        LXI     D,1234H
        DAD     D
        SHLD    1B00H
        XCHG
        LHLD    1B02H
        MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     H,A
        SHLD    1B02H
        PUSH    B
        CALL    CRC
        POP     B
        DCR     C
        JNZ     ARITH
        MVI     A,2             ; DL: 2 x 3070 T-states
        CALL    DL
        JMP     MAIN

; CRC-16/CCITT of the byte in L into 1B04H (bitwise, MSB first).
CRC:    LHLD    1B04H
        MOV     A,H
        XRA     L
        MOV     H,A
        CRC16BITS
        SHLD    1B04H
        RET

        INCLUDE dl.inc          ; the thesis's DL: A milliseconds at 3.072 MHz
        END
