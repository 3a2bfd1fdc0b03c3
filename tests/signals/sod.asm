; SOD high for one SIM and one MVI: from the first SIM's first T-state to the second's,
; SIM 4 + MVI 7 = 11 T-states (8085 data sheet instruction table). tests/signals/sod_scan.alp.
        ORG     0800H
        MVI     A,0C0H          ; SDE and SOD = 1
        SIM
        MVI     A,40H           ; SDE and SOD = 0
        SIM
HOLD:   JMP     HOLD
