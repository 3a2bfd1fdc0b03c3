; ALP85 demo: a bit-banged serial line on the 8085's own pins, SID in and SOD out (RIM and SIM),
; echoing every character it receives: 8 data bits, no parity, 1 stop bit (8N1), the line idle
; at mark (1). One program for three rates, chosen by where GO starts it:
;       R 7 0800 EXEC   9600 baud       alp85 run firmware/demo/echo85.asm --keys "R 7 0800 EXEC" --serial 9600
;       R 7 0810 EXEC   1200 baud       ... --keys "R 7 0810 EXEC" --serial 1200
;       R 7 0820 EXEC    110 baud       ... --keys "R 7 0820 EXEC" --serial 110
; It receives a whole character, then sends it back, then listens again: a character that
; starts while it is still sending is lost, so the sender leaves a character's time between
; characters (alp85 run --serial does by default, docs/signals.md).
;
; Timing, in T-states of the 3.072 MHz clock (T-states from the 8085 data sheet's instruction
; table). A bit lasts 3 072 000 / baud T-states:
;       9600 baud: 320         1200 baud: 2560         110 baud: 27 927.27
; Every bit of both loops below takes 24·n + 80 T-states: the wait loop
;       WAIT:   DCX H (6) / MOV A,H (4) / ORA L (4) / JNZ WAIT (10, 7 at the end)
; takes 24·n - 3 for a count n in HL, and the rest of each loop, padded where needed, 83.
;       rate    n       24·n + 80       rate error
;       9600    10        320            0
;       1200    103      2552           -0.31 %   (2560 - 8)
;        110    1160    27920           -0.026 %  (27 927.27 - 7.27)
; A UART samples each bit in its middle; at the stop bit, 9.5 bits after the start edge, these
; errors add up to 9.5 × 8 = 76 T-states at 1200 baud (3 % of a bit) and 69 at 110 (0.25 %),
; far inside the half bit (50 %) that would make it sample the wrong bit.
; The receiver finds the start bit by polling SID every 18 T-states (RIM 4, ORA 4, JM 10), so it
; sees the falling edge 0 to 18 T-states late, 9 on average, then waits h counts and samples the
; start bit's middle 24·h + 28 T-states after the RIM that saw it:
;       rate    h       9 + 24·h + 28   half a bit
;       9600    5         157             160
;       1200    52       1285            1280
;        110    580     13957           13963.6
        INCLUDE ../monitor/monitor.inc

BITN    EQU     1000H           ; RAM: the count n of a bit (word)
HALFN   EQU     1002H           ; RAM: the count h to the start bit's middle (word)

        ORG     0800H
E9600:  LXI     H,R9600
        JMP     START
        ORG     0810H
E1200:  LXI     H,R1200
        JMP     START
        ORG     0820H
E110:   LXI     H,R110
        JMP     START

; Per rate: n, then h (the tables above).
R9600:  DW      10, 5
R1200:  DW      103, 52
R110:   DW      1160, 580

START:  DI                      ; no interrupt may stretch a bit
        LXI     SP,USERSP
        MOV     E,M             ; the rate's n and h into RAM, where LHLD takes them
        INX     H
        MOV     D,M
        INX     H
        XCHG
        SHLD    BITN
        XCHG
        MOV     E,M
        INX     H
        MOV     D,M
        XCHG
        SHLD    HALFN
        MVI     A,0C0H          ; SOD enable (bit 6) and SOD = 1: the line idles at mark
        SIM

; ---- receive: wait for the start bit's falling edge ----------------------------------------
RXWAIT: RIM                     ; 4   SID is bit 7
        ORA     A               ; 4   S = SID
        JM      RXWAIT          ; 10  mark: keep polling (7 when the line is at space)
        LHLD    HALFN           ; 16
HWAIT:  DCX     H               ; 6
        MOV     A,H             ; 4
        ORA     L               ; 4
        JNZ     HWAIT           ; 10  (24·h - 3 in all)
        RIM                     ; 4   the start bit's middle
        ORA     A               ; 4
        JM      RXWAIT          ; 7   mark again: a glitch, not a start bit
        MVI     B,9             ; 7   8 data bits, then the stop bit
        NOP                     ; 4   from this RIM to the next: 4+4+7+7+12 + 16 + 24·n-3 + 33
        NOP                     ; 4   = 24·n + 80, as in the loop below
        NOP                     ; 4
; ---- receive: a bit every 24·n + 80 T-states, least significant first ----------------------
; C takes each bit in at the top; after the ninth (the stop bit) C holds stop, d7..d1 and CY d0.
RXBIT:  LHLD    BITN            ; 16
BWAIT:  DCX     H               ; 6
        MOV     A,H             ; 4
        ORA     L               ; 4
        JNZ     BWAIT           ; 10  (24·n - 3 in all)
        MVI     A,0             ; 7   33 T-states of padding: 34 + 16 + 24·n-3 + 33
        MVI     A,0             ; 7   = 24·n + 80 from RIM to RIM
        MVI     A,0             ; 7
        NOP                     ; 4
        NOP                     ; 4
        NOP                     ; 4
        RIM                     ; 4   the bit's middle
        RAL                     ; 4   CY = SID
        MOV     A,C             ; 4
        RAR                     ; 4   the bit into C's bit 7, C's bit 0 out to CY
        MOV     C,A             ; 4
        DCR     B               ; 4
        JNZ     RXBIT           ; 10
        MOV     A,C
        RAL                     ; A = the character (d7..d1, d0 from CY), CY = the stop bit
        JNC     FRAMER          ; a stop bit at space: not a character
        MOV     C,A
        CALL    TXCHR           ; echo it
        JMP     RXWAIT

FRAMER: RIM                     ; a framing error (or a break): wait for mark, then listen again
        ORA     A
        JP      FRAMER
        JMP     RXWAIT

; ---- send C: start bit, 8 data bits least significant first, stop bit ----------------------
; Each bit goes out on SOD at a SIM, 24·n + 80 T-states after the last:
;   7+4+4+4+6 + 16 + 24·n-3 + 16 + 4+4+4+4+10 = 24·n + 80.
; It returns as soon as the stop bit is on the line: the line stays at mark after it.
TXCHR:  MVI     B,10            ; 7   start bit, 8 data bits, stop bit
        XRA     A               ; 4   CY = 0: the start bit (space)
TXBIT:  MVI     A,80H           ; 7
        RAR                     ; 4   A = CY·80H + 40H: SOD = the bit, SOD enable set
        SIM                     ; 4   the bit on SOD
        DCR     B               ; 4
        RZ                      ; 6   the stop bit is out: done (12 when it returns)
        LHLD    BITN            ; 16
TWAIT:  DCX     H               ; 6
        MOV     A,H             ; 4
        ORA     L               ; 4
        JNZ     TWAIT           ; 10  (24·n - 3 in all)
        NOP                     ; 4   16 T-states of padding
        NOP                     ; 4
        NOP                     ; 4
        NOP                     ; 4
        STC                     ; 4   a 1 comes in behind the data: the stop bit
        MOV     A,C             ; 4
        RAR                     ; 4   CY = the next bit
        MOV     C,A             ; 4
        JMP     TXBIT           ; 10
        END
