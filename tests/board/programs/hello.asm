; Board test: program the 8279, show HELLO, read one key by polling and one by RST 5.5.
; Results: KEY1 (1000H) the polled FIFO entry, KEY2 (1001H) the one read by the interrupt
; routine, DONE (1002H) = 55H when both are in.
KDATA   EQU     0E0H            ; 8279 data (A0 = 0)
KCMD    EQU     0E1H            ; 8279 command/status (A0 = 1)
KEY1    EQU     1000H
KEY2    EQU     1001H
DONE    EQU     1002H

        ORG     0000H
        JMP     START
        ORG     002CH           ; RST 5.5: the 8279's IRQ
        JMP     KEYINT

        ORG     0040H
START:  LXI     SP,20B0H
        XRA     A
        STA     KEY1
        STA     KEY2
        STA     DONE
        MVI     A,00H           ; mode set: 8 digits, left entry, encoded scan, 2-key lockout
        OUT     KCMD
        MVI     A,3FH           ; clock: prescaler 31 (3.072 MHz / 31 = 99.1 kHz)
        OUT     KCMD
        MVI     A,0D1H          ; clear all: display RAM to 00H, FIFO emptied
        OUT     KCMD
WAITDU: IN      KCMD            ; wait while the display is unavailable (DU)
        ANI     80H
        JNZ     WAITDU
        MVI     A,90H           ; write display RAM from address 0, auto-increment
        OUT     KCMD
        LXI     H,HELLO
        MVI     B,8
SHOW:   MOV     A,M
        OUT     KDATA
        INX     H
        DCR     B
        JNZ     SHOW
POLL:   IN      KCMD            ; FIFO count in bits 0-2
        ANI     07H
        JZ      POLL
        MVI     A,40H           ; read FIFO
        OUT     KCMD
        IN      KDATA
        STA     KEY1
        MVI     A,0EH           ; SIM: MSE, unmask RST 5.5 only
        SIM
        EI
WAIT:   HLT                     ; until the next key
        LDA     KEY2
        ORA     A
        JZ      WAIT
        MVI     A,55H
        STA     DONE
        DI
STOP:   HLT

KEYINT: PUSH    PSW
        MVI     A,40H
        OUT     KCMD
        IN      KDATA
        STA     KEY2
        POP     PSW
        EI
        RET

; Segments, bit0 = a ... bit6 = g: H = b c e f g, E = a d e f g, L = d e f, O = a b c d e f.
HELLO:  DB      76H, 79H, 38H, 38H, 3FH, 00H, 00H, 00H
        END
