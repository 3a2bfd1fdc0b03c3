; The thesis firmware's millisecond delay (App. B, DL): with A = 10 it waits ten passes.
; 8085 T-states, by hand from the data sheet:
;   one pass, A not yet 0:  MVI 7 + 217 x (DCR 4 + JNZ 10) + DCR 4 + JNZ 7 + DCR 4 + JNZ 10 = 3070
;   the last pass:          the same with the final JNZ untaken (7)                          = 3067
;   whole program: MVI 7 + CALL 18 + 9 x 3070 + 3067 + RET 10 + JMP 10 + HLT 5 (at 0000H)   = 30747
;   instructions: 2 + 10 x (1 + 218 x 2 + 2) + RET + JMP + HLT                              = 4395
; 8080 T-states: pass = MVI 7 + 218 x (DCR 5 + JNZ 10) + DCR 5 + JNZ 10 = 3292 (taken or not);
;   whole program: 7 + CALL 17 + 10 x 3292 + RET 10 + JMP 10 + HLT 7                        = 32971

        ORG     100H
START:  MVI     A,10
        CALL    DL
        JMP     0               ; warm boot

        INCLUDE dl.inc          ; DL: MVI B,0DAH / IDI: DCR B / JNZ IDI / DCR A / JNZ DL / RET

        END     START
