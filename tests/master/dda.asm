; ; A software DDA for a line on the ALP 85, written for comparison (docs/contours.md, Fig. 10):
; ; each iteration adds the axes' increments to their 16-bit registers and sends a pulse for each
; ; carry, both in one OUT (port A: bit 0 X pulse, bit 1 X +, bit 2 Y pulse, bit 3 Y +). For a line
; ; of dx, dy steps the increments are dx/L, dy/L . 65536 (L the longer): one pulse on the major axis
; ; per iteration, so the iteration period is the step period at the highest feed (dX / S_r,max).
; ; tests/master/fig10_measure.py times the 100 iterations, DIT to DDONE, on the emulated 8085.
        ORG     1D00H
DXI     EQU     1D80H                   ; increments (0.16)
DYI     EQU     1D82H
RX      EQU     1D84H                   ; registers
RY      EQU     1D86H
DDA:    LXI     SP,20B0H
        LXI     H,0FFFFH                ; a line 25 x 11: X the major axis
        SHLD    DXI
        LXI     H,7099H                 ; 11/25 . 65536
        SHLD    DYI
        LXI     H,0000H
        SHLD    RX
        SHLD    RY
        LXI     B,100                   ; iterations
DIT:    PUSH    B
        MVI     C,0AH                   ; both directions +, no pulse yet
        LHLD    DXI
        XCHG
        LHLD    RX
        DAD     D
        SHLD    RX
        JNC     D1
        MOV     A,C
        ORI     01H
        MOV     C,A
D1:     LHLD    DYI
        XCHG
        LHLD    RY
        DAD     D
        SHLD    RY
        JNC     D2
        MOV     A,C
        ORI     04H
        MOV     C,A
D2:     MVI     A,0AH                   ; the pulses low, then the carries' pulses in one OUT
        OUT     0F9H
        MOV     A,C
        OUT     0F9H
        POP     B
        DCX     B
        MOV     A,B
        ORA     C
        JNZ     DIT
DDONE:  HLT
        END
