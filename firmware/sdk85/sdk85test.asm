; SDK-85 test program: a 2 KB ROM for Intel's SDK-85 as ALP85 emulates it, written for this
; project (it is not Intel's monitor and takes nothing from it). It checks the three things
; Intel's monitor leans on: the memory-mapped 8279 (keys in, digits out), the single step
; (the 8155's timer pulse on TRAP after exactly one user instruction) and a serial line
; bit-banged on SID and SOD. docs/sdk85.md runs it:
;       alp85 run --board sdk85 --rom build/firmware/sdk85/sdk85test.hex
;
; ---- the board (the SDK-85's memory and I/O map, docs/sdk85.md) -------------------------------
;   0000H-07FFH ROM (the 8355): this program, ORG 0000H
;   1800H       8279 data (memory-mapped: A8 low)    1900H  8279 command / status (A8 high)
;   2000H-20FFH 8155 RAM (IO/M low)
;   20H 8155 command/status, 21H PA, 22H PB, 23H PC, 24H timer low, 25H timer high + mode
;   8155 TIMER OUT -> TRAP (0024H); VECT INTR key -> RST 7.5 (003CH); RESET key -> RESET IN
;   8085 at 3.072 MHz (6.144 MHz crystal); the 8155's TIMER IN is CLK OUT: one count per T-state
;   Display: six digits on the 8279's positions 0-5, 0 the leftmost: 0-3 the address field, 4-5
;   the data field. A segment is lit by a 0 bit: a = bit 4, b = 5, c = 6, d = 7, e = 0, f = 1,
;   g = 2, dp = 3 (the SDK-85's wiring of the 8279's outputs A0-A3, B0-B3; SEGA..SEGDP below).
;
; ---- entry points ----------------------------------------------------------------------------
;   0000H RESET     initialises SOD (mark), the 8279 and the RAM counters, then runs the step test
;   0008H RST 1     RET: one of the stepped instructions (RST 1 from USER lands here)
;   0024H TRAP      the step test's handler (TRAPH): records the user's PC, steps again
;   0038H RST 7     JMP START: a stray FFH (unprogrammed ROM) restarts the program
;   003CH RST 7.5   VECT INTR: runs the step test again (the display then shows its result)
;   STEPT           the step test (sdk85test.json, the build's map, names every label's address)
;   IDLE            the idle loop: polls SID for a start bit and the 8279 for a key
;
; ---- what it does --------------------------------------------------------------------------
; 1. RESET and VECT INTR run the step test: the user program USER..UEND (in this ROM) is
;    single-stepped from USER with SP = USTACK, all other registers 0. After each TRAP the
;    user's PC is recorded in STEPPC (one word each, in order); the test stops when the PC
;    reaches UEND, or after STEPMAX steps. The records are then compared with EXPECT (the
;    address of the next instruction after each one, in the order they run): STEPOK counts the
;    records that match, from the first up to the first that does not. The display then shows
;    "00nn kk": nn = STEPN (steps taken), kk = STEPOK. A pass is nn = kk = NSTEPS = 1CH (28).
; 2. Each key pressed is read from the 8279's FIFO and shown: the address field gives KEYCNT
;    (keys read since RESET) in hex, the data field the FIFO byte (the key's code) in hex.
;    After RESET and three keys the display reads "0003 cc", cc the third key's FIFO byte.
;    The SDK-85's keypad puts 0-7 on scan row 0, 8-F on row 1, and EXEC, NEXT, GO, SUBST MEM,
;    EXAM REG, SINGLE STEP on row 2 (return lines 0-5), so the FIFO byte is
;    CNTL SHIFT r r r c c c = row * 8 + line, plus C0H if the board ties CNTL and SHIFT high:
;       keys 0-F: 00H-0FH; EXEC 10H, NEXT 11H, GO 12H, SUBST MEM 13H, EXAM REG 14H,
;       SINGLE STEP 15H (RESET and VECT INTR are not in the matrix).
; 3. A character received on SID is echoed on SOD: 2400 baud, 8 data bits, no parity, one stop
;    bit (8N1), least significant bit first, the line idle at mark = 1. The kit's TTY driver
;    inverts SOD (one transistor into the 20 mA loop), so SOD is low at mark and high at space;
;    SID follows the loop, high at mark (docs/board.md, "The SDK-85").
;    A character whose stop bit is a space (framing error, break) is not echoed. The program
;    receives a whole character, then sends it back, then listens again: leave a character's
;    time between characters (alp85 run --serial does by default). Keys and characters are
;    served one at a time.
;
; ---- RAM (the 8155's, 2000H-20FFH) -----------------------------------------------------------
STEPPC  EQU     2000H           ; 2000H-203FH: the user's PC after each step, a word each
STEPN   EQU     2040H           ; byte: steps taken (TRAPs recorded)
STEPOK  EQU     2041H           ; byte: records that match EXPECT, counted from the first
KEYCNT  EQU     2042H           ; word: keys read from the 8279 since RESET
LASTKY  EQU     2044H           ; byte: the FIFO byte of the last key
LASTCH  EQU     2045H           ; byte: the last character received (and echoed)
RXCNT   EQU     2046H           ; word: characters received and echoed since RESET
DISPBF  EQU     2048H           ; 6 bytes: the digits shown, 00H-0FH, left to right
SAVEHL  EQU     2050H           ; word: the stepped program's HL
SAVEPC  EQU     2052H           ; word: its PC
SAVESP  EQU     2054H           ; word: its SP
TMPSP   EQU     2056H           ; word: its SP less 2, where RESUME puts its PC for RET
FRAME   EQU     2058H           ; 6 bytes: its E D, C B, flags A, as POP D, POP B, POP PSW take them
UDATA   EQU     2060H           ; 2060H-206FH: the stepped program's data
USTACK  EQU     2080H           ; 2070H-207FH: its stack (SP = 2080H at the start)
MONSP   EQU     2100H           ; 2080H-20FFH: this program's own stack

STEPMAX EQU     32              ; room in STEPPC

        CPU     8085

; ---- board -----------------------------------------------------------------------------------
KDCDAT  EQU     1800H           ; 8279 data
KDCCMD  EQU     1900H           ; 8279 command (write) / status (read)
RIOCMD  EQU     20H             ; 8155 command / status
RIOPA   EQU     21H             ; 8155 port A
TIMLO   EQU     24H             ; 8155 count length, low byte
TIMHI   EQU     25H             ; 8155 count length, high 6 bits; timer mode in bits 7-6

; 8279 commands (8279 data sheet): clock 001PPPPP, mode 000DDKKK, clear 110CCCFA.
KCLOCK  EQU     20H+31          ; prescaler 31: 3.072 MHz / 31 = 99.1 kHz, the nearest to the
                                ; data sheet's 100 kHz internal clock not above it
KMODE   EQU     00H             ; DD 00: 8 8-bit digits, left entry; KKK 000: encoded scan, 2-key lockout
KCLEAR  EQU     0DDH            ; 110 1 11 0 1: clear all, display RAM to FFH (every segment dark)
KRDFIFO EQU     40H             ; read FIFO
KWRAI   EQU     90H             ; write display RAM from position 0, auto-increment
KSTCNT  EQU     07H             ; status bits 2-0: characters in the FIFO

; 8155 command: ports A, B input, port C ALT1 (all input), interrupts off; bits 7-6 the timer.
RIOSTART EQU    0C0H            ; 11: START
TPULSE  EQU     80H             ; count length bits 15-14 = 10: a single low pulse at terminal count

; Segments, lit by a 0 bit (see the top).
SEGA    EQU     10H
SEGB    EQU     20H
SEGC    EQU     40H
SEGD    EQU     80H
SEGE    EQU     01H
SEGF    EQU     02H
SEGG    EQU     04H
SEGDP   EQU     08H
DARK    EQU     0FFH

; ---- single step: the timer count --------------------------------------------------------------
; RESUME starts the timer with OUT RIOCMD; from that OUT's first T-state to the first T-state of
; the user's instruction (8085 data sheet T-states):
;       OUT RIOCMD 10, POP PSW 10, LHLD TMPSP 16, SPHL 6, LHLD SAVEHL 16, RET 10  = 68 T-states
; The 8155 takes START in OUT's I/O write machine cycle, which begins 7 T-states after OUT's
; first T-state (opcode fetch 4, port address read 3). From there it counts N TIMER IN pulses,
; one per T-state: terminal count at 7 + N; in the single-pulse mode TIMER OUT is low for one
; count, and its rising edge, the TRAP edge, comes at 7 + N + 1 (docs/peripherals.md, "Exact
; timer timing"). TRAP is recognised at the end of the instruction during which its edge
; comes. The user's instruction runs from T-state 68 to 68 + 4 at least (the shortest, NOP and
; MOV r,r, take 4), so the edge must come at 69..71 (one T-state into it, before its last one):
; one instruction, no more, whatever its length (4 to 18 T-states). The middle of that window,
; 70, leaves a clock either way for the timer's edge: 7 + N + 1 = 70, N = 62.
STEPTS  EQU     10+10+16+6+16+10        ; 68
STEPCNT EQU     STEPTS+2-8              ; 62 = 3EH

; ---- serial: 2400 baud, 8N1 -------------------------------------------------------------------
; A bit lasts 3 072 000 / 2400 = 1280 T-states exactly. Every wait below is
;       LXI H,n (10) / W: DCX H (6) / MOV A,H (4) / ORA L (4) / JNZ W (10, 7 the last time)
; = 24·n + 7 T-states; the rest of each loop is counted next to it.
;   receive, RIM to RIM:  34 + (24·RXN + 7) + 15 of padding = 24·RXN + 56 = 1280 with RXN = 51
;   send, SIM to SIM:     73 + (24·TXN + 7)                = 24·TXN + 80 = 1280 with TXN = 50
;   start bit: IDLE polls SID every 45 T-states (RIM 4, ORA 4, JP 7, LDA 13, ANI 7, JZ 10), so it
;   sees the falling edge 0-44 T-states late; the RIM at the start bit's middle comes
;   18 + 4 + (24·RXH + 7) = 24·RXH + 29 = 629 T-states after the RIM that saw it (RXH = 25), so
;   629..673 after the edge: 640 is the middle, the error at most 33 T-states (2.6 % of a bit).
;   Each data bit is then sampled 1280 T-states after the last, at the same place in its bit.
BITT    EQU     1280
RXN     EQU     51
TXN     EQU     50
RXH     EQU     25

; ---- vectors -----------------------------------------------------------------------------------
        ORG     0000H
        JMP     START           ; RESET

        ORG     0008H           ; RST 1: stepped as a user instruction (USER's S22)
R1VEC:  RET

        ORG     0024H           ; TRAP: the step test's timer pulse
        JMP     TRAPH

        ORG     0038H           ; RST 7 (FFH): restart
        JMP     START

        ORG     003CH           ; RST 7.5: VECT INTR
        LXI     SP,MONSP
        JMP     STEPT

; ---- RESET ----------------------------------------------------------------------------------------
START:  LXI     SP,MONSP
        MVI     A,40H           ; SOD enable and SOD = 0: the (inverted) serial line idles at mark
        SIM
        CALL    KDCINI
        LXI     H,0
        SHLD    KEYCNT
        SHLD    RXCNT
        XRA     A
        STA     LASTKY
        STA     LASTCH
        ; falls into the step test

; ---- the step test ------------------------------------------------------------------------------
STEPT:  DI                      ; TRAP needs no enable; nothing else may come in between
        LXI     SP,MONSP
        LXI     H,STEPPC        ; the records from an earlier run are wiped
        MVI     B,2*STEPMAX
        XRA     A
CLRREC: MOV     M,A
        INX     H
        DCR     B
        JNZ     CLRREC
        STA     STEPN
        STA     STEPOK
        LXI     H,0             ; the stepped program starts with every register 0
        SHLD    SAVEHL
        SHLD    FRAME
        SHLD    FRAME+2
        SHLD    FRAME+4
        LXI     H,USER
        SHLD    SAVEPC
        LXI     H,USTACK
        SHLD    SAVESP
        ; falls into RESUME

; Back into the stepped program at SAVEPC with its registers, the timer armed to trap after one
; instruction (the count above).
RESUME: LHLD    SAVESP
        DCX     H
        DCX     H
        SHLD    TMPSP           ; its SP less 2: its PC goes there, for the RET
        XCHG
        LHLD    SAVEPC
        XCHG
        MOV     M,E
        INX     H
        MOV     M,D
        MVI     A,STEPCNT AND 0FFH
        OUT     TIMLO
        MVI     A,TPULSE OR (STEPCNT SHR 8)
        OUT     TIMHI
        LXI     SP,FRAME
        POP     D
        POP     B
        MVI     A,RIOSTART
        OUT     RIOCMD          ; 10  START: the count begins 7 T-states in
        POP     PSW             ; 10
        LHLD    TMPSP           ; 16
        SPHL                    ;  6
        LHLD    SAVEHL          ; 16
        RET                     ; 10  = 68: the user's instruction begins

; TRAP: the timer's pulse, after one user instruction. Saves its registers, records its PC.
TRAPH:  SHLD    SAVEHL
        POP     H               ; the PC TRAP pushed
        SHLD    SAVEPC
        PUSH    PSW             ; A and flags, through HL into the frame
        POP     H
        SHLD    FRAME+4
        LXI     H,0
        DAD     SP              ; its SP as it was before TRAP
        SHLD    SAVESP
        LXI     SP,FRAME+4
        PUSH    B
        PUSH    D
        LXI     SP,MONSP
        LDA     STEPN           ; STEPPC + 2·STEPN (STEPPC is page-aligned)
        ADD     A
        MOV     L,A
        MVI     H,STEPPC SHR 8
        LDA     SAVEPC
        MOV     M,A
        INX     H
        LDA     SAVEPC+1
        MOV     M,A
        LDA     STEPN
        INR     A
        STA     STEPN
        CPI     STEPMAX
        JNC     STEPEND         ; the table is full: stop
        LHLD    SAVEPC
        MOV     A,L
        CPI     UEND AND 0FFH
        JNZ     RESUME
        MOV     A,H
        CPI     UEND SHR 8
        JNZ     RESUME
        ; at UEND: done

; The records against EXPECT; the result on the display; then the idle loop.
STEPEND: LXI    SP,MONSP
        LXI     H,STEPPC
        LXI     D,EXPECT
        LDA     STEPN
        MOV     B,A
        MVI     C,0
CMPL:   MOV     A,B
        ORA     A
        JZ      CMPD
        DCR     B
        LDAX    D               ; low bytes
        CMP     M
        INX     H
        INX     D
        JNZ     CMPD
        LDAX    D               ; high bytes
        CMP     M
        INX     H
        INX     D
        JNZ     CMPD
        INR     C
        JMP     CMPL
CMPD:   MOV     A,C
        STA     STEPOK
        LDA     STEPN
        MOV     L,A
        MVI     H,0
        LDA     STEPOK
        CALL    SHOW            ; "00nn kk"
        MVI     A,1BH           ; SIM: RST 7.5 open (its latch cleared), 6.5 and 5.5 masked
        SIM
        EI
        JMP     IDLE

; ---- the stepped program: every length (1-3 bytes) and timing (4-18 T-states) ----------------
; Each instruction's label is the PC the TRAP after the one before records; EXPECT lists them in
; the order they run. T-states from the 8085 data sheet.
USER:   NOP                     ;  4
S01:    MOV     B,C             ;  4
S02:    MVI     A,5AH           ;  7
S03:    LXI     H,UDATA         ; 10
S04:    STA     UDATA           ; 13
S05:    LHLD    UDATA           ; 16
S06:    SHLD    UDATA+2         ; 16
S07:    PUSH    B               ; 12
S08:    XTHL                    ; 16
S09:    POP     H               ; 10
S10:    CALL    USUB            ; 18  -> USUB (S11), RET 10
S12:    JMP     S13             ; 10
        HLT                     ;     never runs
S13:    XRA     A               ;  4  A = 0, Z = 1
S14:    JZ      S15             ; 10  taken
        HLT
S15:    JNZ     USER            ;  7  not taken
S16:    CNZ     USER            ;  9  not taken
S17:    CZ      USUBZ           ; 18  taken -> USUBZ (S18)
S20:    LXI     H,S22           ; 10
S21:    PCHL                    ;  6
        HLT
S22:    RST     1               ; 12  -> 0008H (S23), RET 10
S24:    INX     H               ;  6
S25:    DAD     B               ; 10
S26:    IN      RIOPA           ; 10
S27:    DI                      ;  4
UEND:   HLT                     ;     the test stops here, before it runs

USUB:   RET                     ; 10  (S11)
USUBZ:  RNZ                     ;  6  not taken (S18)
S19:    RZ                      ; 12  taken

EXPECT: DW      S01, S02, S03, S04, S05, S06, S07, S08, S09, S10
        DW      USUB, S12, S13, S14, S15, S16, S17, USUBZ, S19, S20
        DW      S21, S22, R1VEC, S24, S25, S26, S27, UEND
NSTEPS  EQU     ($-EXPECT)/2    ; 28 = 1CH

; ---- the idle loop: a start bit on SID, or a key in the 8279's FIFO -------------------------------
IDLE:   RIM                     ;  4  SID is bit 7
        ORA     A               ;  4  S = SID
        JP      RXSTART         ;  7  (10 taken) space: a start bit
        LDA     KDCCMD          ; 13  8279 status
        ANI     KSTCNT          ;  7  characters in the FIFO
        JZ      IDLE            ; 10  = 45 T-states a round

; A key: its FIFO byte in the data field, the count of keys in the address field.
KEY:    MVI     A,KRDFIFO
        STA     KDCCMD
        LDA     KDCDAT
        STA     LASTKY
        LHLD    KEYCNT
        INX     H
        SHLD    KEYCNT
        CALL    SHOW
        JMP     IDLE

; ---- receive a character, least significant bit first, and echo it -----------------------------
RXSTART: DI                     ;  4  nothing may stretch a bit
        LXI     H,RXH           ; 10
RXHW:   DCX     H               ;  6
        MOV     A,H             ;  4
        ORA     L               ;  4
        JNZ     RXHW            ; 10  (24·RXH - 3 in all)
        RIM                     ;  4  the start bit's middle
        ORA     A               ;  4
        JM      IDLEI           ;  7  mark again: a glitch, not a start bit
        MVI     B,9             ;  7  8 data bits, then the stop bit
        NOP                     ;  4  from this RIM to the next: 4+4+7+7+12 + 24·RXN+7 + 15
        NOP                     ;  4  = 24·RXN + 56, as in the loop below
        NOP                     ;  4
; C takes each bit in at the top; after the ninth (the stop bit) C holds stop, d7..d1 and CY d0.
RXBIT:  LXI     H,RXN           ; 10
RXW:    DCX     H               ;  6
        MOV     A,H             ;  4
        ORA     L               ;  4
        JNZ     RXW             ; 10  (24·RXN + 7 with the LXI)
        NOP                     ;  4  15 T-states of padding
        NOP                     ;  4
        MVI     A,0             ;  7
        RIM                     ;  4  the bit's middle
        RAL                     ;  4  CY = SID
        MOV     A,C             ;  4
        RAR                     ;  4  the bit into C's bit 7
        MOV     C,A             ;  4
        DCR     B               ;  4
        JNZ     RXBIT           ; 10  (34 from RIM to the LXI)
        MOV     A,C
        RAL                     ; A = the character (d7..d1, d0 from CY), CY = the stop bit
        JNC     FRAMER          ; a stop bit at space: not a character
        MOV     C,A
        STA     LASTCH
        LHLD    RXCNT
        INX     H
        SHLD    RXCNT
        CALL    TXCHR           ; echo it
IDLEI:  EI
        JMP     IDLE

FRAMER: RIM                     ; a framing error, a break, or no terminal at all (SID held
        ORA     A               ; low, as the kit's switch S25 holds it with the keypad as the
        JM      IDLEI           ; console): wait for mark, then listen again, serving the keys
        LDA     KDCCMD          ; meanwhile
        ANI     KSTCNT
        JZ      FRAMER
        JMP     KEY

; ---- send C: start bit, 8 data bits least significant first, stop bit ---------------------------
; Each bit goes out on SOD at a SIM, 1280 T-states after the last:
;   SIM 4, DCR 4, RZ 6, LXI + wait 24·TXN + 7, padding 18, STC 4, MOV 4, RAR 4, MOV 4, JMP 10,
;   CMC 4, MVI 7, RAR 4 = 24·TXN + 80.
; It returns as soon as the stop bit is on the line; the line stays at mark after it.
TXCHR:  MVI     B,10            ;  7  start bit, 8 data bits, stop bit
        XRA     A               ;  4  CY = 0: the start bit (space)
TXBIT:  CMC                     ;  4  the driver inverts SOD: SOD = the bit's complement
        MVI     A,80H           ;  7
        RAR                     ;  4  A = CY·80H + 40H: SOD = not the bit, SOD enable set
        SIM                     ;  4  the bit on SOD
        DCR     B               ;  4
        RZ                      ;  6  the stop bit is out: done (12 when it returns)
        LXI     H,TXN           ; 10
TXW:    DCX     H               ;  6
        MOV     A,H             ;  4
        ORA     L               ;  4
        JNZ     TXW             ; 10  (24·TXN + 7 with the LXI)
        MVI     A,0             ;  7  18 T-states of padding
        MVI     A,0             ;  7
        NOP                     ;  4
        STC                     ;  4  a 1 comes in behind the data: the stop bit
        MOV     A,C             ;  4
        RAR                     ;  4  CY = the next bit
        MOV     C,A             ;  4
        JMP     TXBIT           ; 10

; ---- the 8279 -------------------------------------------------------------------------------------
KDCINI: MVI     A,KCLOCK
        STA     KDCCMD
        MVI     A,KMODE
        STA     KDCCMD
        MVI     A,KCLEAR
        STA     KDCCMD
KDCWT:  LDA     KDCCMD          ; status bit 7 (DU): the display RAM is still being cleared
        ORA     A
        JM      KDCWT
        RET

; HL in the address field, A in the data field, as hex digits (DISPBF, then the 8279).
SHOW:   PUSH    PSW
        LXI     D,DISPBF
        MOV     A,H
        CALL    SPLIT
        MOV     A,L
        CALL    SPLIT
        POP     PSW
        CALL    SPLIT
        MVI     A,KWRAI
        STA     KDCCMD
        LXI     D,DISPBF
        MVI     B,6
SHOWL:  LDAX    D
        LXI     H,SEGTAB
        ADD     L
        MOV     L,A
        MVI     A,0
        ADC     H
        MOV     H,A
        MOV     A,M
        STA     KDCDAT
        INX     D
        DCR     B
        JNZ     SHOWL
        RET

; A's two hex digits to DE, DE+1 (high first); DE moves on by two.
SPLIT:  PUSH    PSW
        RRC
        RRC
        RRC
        RRC
        ANI     0FH
        STAX    D
        INX     D
        POP     PSW
        ANI     0FH
        STAX    D
        INX     D
        RET

; The hex digits 0-F as segments.
SEGTAB: DB      DARK XOR (SEGA OR SEGB OR SEGC OR SEGD OR SEGE OR SEGF)         ; 0
        DB      DARK XOR (SEGB OR SEGC)                                         ; 1
        DB      DARK XOR (SEGA OR SEGB OR SEGD OR SEGE OR SEGG)                 ; 2
        DB      DARK XOR (SEGA OR SEGB OR SEGC OR SEGD OR SEGG)                 ; 3
        DB      DARK XOR (SEGB OR SEGC OR SEGF OR SEGG)                         ; 4
        DB      DARK XOR (SEGA OR SEGC OR SEGD OR SEGF OR SEGG)                 ; 5
        DB      DARK XOR (SEGA OR SEGC OR SEGD OR SEGE OR SEGF OR SEGG)         ; 6
        DB      DARK XOR (SEGA OR SEGB OR SEGC)                                 ; 7
        DB      DARK XOR (SEGA OR SEGB OR SEGC OR SEGD OR SEGE OR SEGF OR SEGG) ; 8
        DB      DARK XOR (SEGA OR SEGB OR SEGC OR SEGD OR SEGF OR SEGG)         ; 9
        DB      DARK XOR (SEGA OR SEGB OR SEGC OR SEGE OR SEGF OR SEGG)         ; A
        DB      DARK XOR (SEGC OR SEGD OR SEGE OR SEGF OR SEGG)                 ; b
        DB      DARK XOR (SEGA OR SEGD OR SEGE OR SEGF)                         ; C
        DB      DARK XOR (SEGB OR SEGC OR SEGD OR SEGE OR SEGG)                 ; d
        DB      DARK XOR (SEGA OR SEGD OR SEGE OR SEGF OR SEGG)                 ; E
        DB      DARK XOR (SEGA OR SEGE OR SEGF OR SEGG)                         ; F

        END     START
