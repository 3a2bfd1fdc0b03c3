; A program that starts the 8155 timer itself (continuous pulses, TIMER OUT on TRAP): the first
; TRAP enters the monitor, which stops the timer so no other TRAP reaches it.
        ORG     1000H
        MVI     A,LOW 1000      ; 1000H: a terminal count every 1000 T-states
        OUT     0FCH
        MVI     A,(HIGH 1000) OR 0C0H  ; M2 M1 = 11: continuous pulse
        OUT     0FDH
        MVI     A,0C1H          ; START, port A output
        OUT     0F8H
LOOP:   JMP     LOOP            ; 100CH
        END
