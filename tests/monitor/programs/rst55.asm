; RST 5.5 (the 8279's IRQ) through the monitor's RAM vector at 20DEH: first as RESET leaves it
; (into the monitor), then with the program's own routine, which reads the key into 1100H.
        INCLUDE "../../../firmware/monitor/monitor.inc"
        ORG     1000H
DEFLT:  MVI     A,0EH           ; 1000H: RST 5.5 open, 6.5 and 7.5 masked
        SIM
        EI
LOOP1:  JMP     LOOP1           ; 1004H
OWN:    MVI     A,0C3H          ; 1007H: JMP KEYIN into the RAM vector
        STA     RV55
        LXI     H,KEYIN
        SHLD    RV55+1
        MVI     A,0EH
        SIM
        EI
LOOP2:  JMP     LOOP2
KEYIN:  PUSH    PSW
        MVI     A,40H           ; 8279: read FIFO
        OUT     0E1H
        IN      0E0H
        STA     1100H
        POP     PSW
        EI
        RET
        END
