; The 8155's timer as a continuous square wave of 101 clocks (one a T-state: TIMER IN is CLK):
; TIMER OUT is high for the first, larger half, ceil(101/2) = 51 T-states, low for 50 (8155 data
; sheet, timer modes; peripherals/i8155.h). TIMER OUT is TRAP on the ALP 85: the handler at
; 0024H returns at once. tests/signals/timer.alp.
        ORG     0000H
        LXI     SP,20B0H
        MVI     A,65H           ; count 101, low byte
        OUT     0FCH
        MVI     A,40H           ; mode 01: continuous square wave; count high bits 0
        OUT     0FDH
        MVI     A,0C0H          ; start the timer; ports A, B, C as inputs
        OUT     0F8H
IDLE:   JMP     IDLE
        ORG     0024H
        RET
