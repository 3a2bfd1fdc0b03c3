; The second workload of `alp85 bench cpu`: memory traffic on a flat 64 KiB of RAM (no device
; pages), the other half of what an interpreter does besides register arithmetic. Runs from 0000H;
; an endless loop, deterministic. 8080 instructions only (runs on both variants).
;   1. a 256-byte block copy through LDAX/STAX with INX
;   2. a bubble sort of 64 bytes through M (MOV/CMP/XCHG-free swaps), the data refilled each pass
;   3. stack traffic: CALL/RET, PUSH/POP of every pair, XTHL
;   4. a table lookup: DAD into a 256-entry table, LHLD/SHLD of a running sum
; The sort makes the branch pattern data dependent: a fair test of dispatch prediction.

        ORG     0
        LXI     SP,0FF00H
        LXI     H,SRC           ; fill the source with a fixed pseudo-random pattern
        MVI     B,0
        MVI     A,0A7H
FILL:   MOV     M,A
        RLC
        XRI     35H
        ADI     11H
        INX     H
        DCR     B
        JNZ     FILL

MAIN:   CALL    COPY
        CALL    SORT
        CALL    STACK
        CALL    LOOKUP
        LDA     SRC             ; vary the data from pass to pass
        INR     A
        STA     SRC
        JMP     MAIN

; DST = SRC, 256 bytes
COPY:   LXI     D,SRC
        LXI     H,DST
        MVI     C,0
COPYL:  LDAX    D
        MOV     M,A
        INX     D
        INX     H
        DCR     C
        JNZ     COPYL
        RET

; sort DST[0..63] ascending (unsigned), bubble sort through HL
SORT:   MVI     C,63            ; passes
SORTP:  LXI     H,DST
        MOV     B,C             ; compares in this pass
SORTC:  MOV     A,M
        INX     H
        CMP     M
        JC      SORTN           ; in order (A < next)
        JZ      SORTN
        MOV     D,M             ; swap the pair
        MOV     M,A
        DCX     H
        MOV     M,D
        INX     H
SORTN:  DCR     B
        JNZ     SORTC
        DCR     C
        JNZ     SORTP
        RET

; pushes and pops of every pair, calls 8 deep, XTHL
STACK:  MVI     A,32
STACKL: PUSH    B
        PUSH    D
        PUSH    H
        PUSH    PSW
        CALL    DEEP
        POP     PSW
        POP     H
        POP     D
        POP     B
        DCR     A
        JNZ     STACKL
        RET
DEEP:   CALL    DEEP1
        RET
DEEP1:  CALL    DEEP2
        RET
DEEP2:  XTHL
        XTHL
        RET

; SUM += TABLE[DST[i]] for i in 0..255 (16-bit entries)
LOOKUP: LXI     D,DST           ; DST is page-aligned: E runs 00H..FFH
LOOKL:  LDAX    D
        MOV     L,A
        MVI     H,0
        DAD     H
        LXI     B,TABLE
        DAD     B
        MOV     A,M
        INX     H
        MOV     H,M
        MOV     L,A
        XCHG
        LHLD    SUM
        DAD     D
        SHLD    SUM
        XCHG
        INX     D
        MOV     A,E
        ORA     A
        JNZ     LOOKL
        RET

SUM:    DW      0
        ORG     1000H
SRC:    DS      256
DST:    DS      256
TABLE:  DS      512
        END
