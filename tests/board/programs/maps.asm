; Board test: the memory and I/O maps. Writes patterns, reads them back, and tries to write
; the EPROMs; the C++ test checks the results left in RAM at 1100H.
RES     EQU     1100H           ; results, one byte each

        ORG     0000H
        LXI     SP,20B0H
        ; RAM at both ends of 1000H-1FFFH
        MVI     A,0A5H
        STA     1000H
        MVI     A,5AH
        STA     1FFFH
        LDA     1000H
        STA     RES+0           ; expect A5H
        LDA     1FFFH
        STA     RES+1           ; expect 5AH
        ; 8155 RAM at both ends of 2000H-20FFH
        MVI     A,3CH
        STA     2000H
        MVI     A,0C3H
        STA     20FFH
        LDA     2000H
        STA     RES+2           ; expect 3CH
        LDA     20FFH
        STA     RES+3           ; expect C3H
        ; EPROM write protection: the monitor EPROM (here: this program) and the user EPROM
        LDA     PATTERN
        MOV     B,A
        CMA
        STA     PATTERN         ; ignored
        LDA     PATTERN
        STA     RES+4           ; expect 96H, the programmed byte
        MVI     A,11H
        STA     0800H           ; ignored: user EPROM
        LDA     0800H
        STA     RES+5           ; expect what was programmed there (EEH)
        ; unmapped memory and ports read FFH
        LDA     3000H
        STA     RES+6           ; expect FFH
        LDA     0FFFFH
        STA     RES+7           ; expect FFH
        IN      00H
        STA     RES+8           ; expect FFH
        IN      0E8H
        STA     RES+9           ; expect FFH
        ; the stack lives in the 8155 RAM
        LXI     B,1234H
        PUSH    B
        LDA     20AFH
        STA     RES+10          ; expect 12H (high byte pushed first, at SP-1)
        LDA     20AEH
        STA     RES+11          ; expect 34H
        HLT
PATTERN: DB     96H
        ORG     0800H
        DB      0EEH
        END
