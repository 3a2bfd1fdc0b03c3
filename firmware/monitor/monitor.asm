; ALP 85 monitor: the 2 KB EPROM at 0000H-07FFH.
;
; The original monitor (after Siemens' "Experimental Computer Board") is lost. This one keeps the
; five entry points the thesis firmware calls (AUS, UMW, ANWEIN, ANWAZL, ANWAUS, at the addresses
; its listing names) and gives the keypad the commands a trainer-board user expects: R + a
; command digit (R 7 = GO, as thesis Appendix C says), examine and modify memory and registers,
; GO, single step (8155 timer -> TRAP) and breakpoints (RST 1). docs/monitor.md is the manual.
;
; Board: 8279 at E0H (data) / E1H (command, status); 8155 at F8H-FDH, its TIMER OUT on TRAP;
; VECT INTR key on RST 7.5; 3.072 MHz. Digit 0 is the leftmost; segment bits 0-6 = a-g, 7 = dp.

        CPU     8085
        INCLUDE "monitor.inc"

; ---- board ----------------------------------------------------------------------------------
KDDAT   EQU     0E0H            ; 8279 data
KDCMD   EQU     0E1H            ; 8279 command / status
RIOCMD  EQU     0F8H            ; 8155 command / status
TIMLO   EQU     0FCH            ; 8155 timer count, low byte
TIMHI   EQU     0FDH            ; 8155 timer count, high 6 bits; mode in bits 7-6

KMODE   EQU     00H             ; 8 8-bit digits, left entry; encoded scan keyboard, 2-key lockout
KCLOCK  EQU     20H+31          ; prescaler 31: 3.072 MHz / 31 = 99 kHz internal clock
KCLEAR  EQU     0D1H            ; clear all: display RAM to 00H, FIFO emptied
KRDFIFO EQU     40H             ; read FIFO
KWRAI   EQU     90H             ; write display RAM from address 0, auto-increment
KWRDSP  EQU     80H             ; write display RAM at the address in bits 3-0
KSTDU   EQU     80H             ; status: display unavailable (being cleared)
KSTCNT  EQU     0FH             ; status: FIFO full (bit 3) and count (bits 2-0)

RIOPORTS EQU    01H             ; 8155: port A output (motors), B and C input; timer NOP
RIOSTART EQU    0C0H+RIOPORTS   ; the same ports, timer START
RIOSTOP EQU     40H+RIOPORTS    ; the same ports, timer STOP
TPULSE  EQU     80H             ; timer mode 10: a single low pulse at terminal count

USERPC  EQU     0800H           ; the user EPROM: GO's default address

; ---- single step ------------------------------------------------------------------------------
; STEPRUN starts the timer with OUT RIOCMD and falls into RESUME, which enters the user's
; instruction after a fixed number of T-states (8085 timings, asm/isa.h):
;   OUT 10, LXI SP 10, POP B 10, POP D 10, POP PSW 10, LHLD 16, SPHL 6, LHLD 16, JMP 10,
;   EI/NOP 4, JMP 10                                            = 112 T-states (STEPT)
; The 8155 latches START in OUT's I/O write cycle, 7 T-states after OUT's first T-state, and
; counts one per T-state (TIMER IN = CLK OUT): terminal count falls at 7 + N, TIMER OUT is low
; for one clock and its rising edge (the TRAP edge) comes at 7 + N + 1. With N = STEPT - 7 the
; edge falls one T-state into the user's instruction, so TRAP is taken when that one
; instruction (4 T-states or more) has finished.
STEPT   EQU     10+10+10+10+10+16+6+16+10+4+10
STEPN   EQU     STEPT-7         ; 105

; ---- monitor RAM: 20B0H-20FFH (the thesis firmware's stack grows down from 20B0H) -------------
; RSAVE .. SAVEIM (20B0H-20BCH), RV55, RV65: see monitor.inc
UHL     EQU     SAVEHL
USP     EQU     SAVESP
UPC     EQU     SAVEPC
UIM     EQU     SAVEIM
CAUSE   EQU     20BDH           ; why the monitor was entered: CRST, CTRAP, CVECT
GOFLAG  EQU     20BEH           ; 1: this TRAP ends the step over a breakpoint that starts a GO
BPFLAG  EQU     20BFH           ; word: BPMAGIC while breakpoints sit in the user's program
TRAMP   EQU     20C1H           ; EI or NOP, then JMP user PC: the last steps into the program
NBP     EQU     4
BPTAB   EQU     20C5H           ; NBP entries: address (0 = free), the user's byte
CURADR  EQU     20D1H           ; MEM's address
BPADR   EQU     20D3H           ; R 8's address
REGIX   EQU     20D5H           ; REG's register
DBUF    EQU     20D6H           ; the eight digits as the monitor shows them
VAREND  EQU     20E4H           ; end of the variables; the monitor's stack lies above
MSTACK  EQU     2100H

        IF      (RV55 NE DBUF+8) OR (RV65 NE RV55+3) OR (VAREND NE RV65+3) OR (BPTAB+3*NBP NE CURADR)
        ERROR   "monitor RAM layout does not match monitor.inc"
        ENDIF

CRST    EQU     1
CTRAP   EQU     2
CVECT   EQU     3
BPMAGIC EQU     0A55AH
RST1    EQU     0CFH            ; the breakpoint instruction
OPEI    EQU     0FBH
OPJMP   EQU     0C3H

; segment codes
S_BLANK EQU     00H
S_DASH  EQU     40H
S_DP    EQU     80H

; ---- restart and interrupt vectors ------------------------------------------------------------
        ORG     0000H
        JMP     COLD            ; RESET
        DS      0008H-$,0FFH
        JMP     RSTENT          ; RST 1: breakpoint, or the end of a user program
        DS      0010H-$,0FFH
        JMP     RSTENT          ; RST 2-7: as RST 1 (RST 7 = FFH, a run into empty EPROM)
        DS      0018H-$,0FFH
        JMP     RSTENT
        DS      0020H-$,0FFH
        JMP     RSTENT
        DS      0024H-$,0FFH
        JMP     TRPENT          ; TRAP: the 8155 timer, single step
        DS      0028H-$,0FFH
        JMP     RSTENT
        DS      002CH-$,0FFH
        JMP     RV55            ; RST 5.5: 8279 IRQ, through RAM
        DS      0030H-$,0FFH
        JMP     RSTENT
        DS      0034H-$,0FFH
        JMP     RV65            ; RST 6.5, through RAM
        DS      0038H-$,0FFH
        JMP     RSTENT
        DS      003CH-$,0FFH
        JMP     VECENT          ; RST 7.5: the VECT INTR key

; ---- entries from a user program ------------------------------------------------------------
; Each keeps HL, notes the cause and joins SAVE with the user's PC on the user's stack.
RSTENT: SHLD    UHL
        LXI     H,CAUSE
        MVI     M,CRST
        JMP     SAVE
TRPENT: SHLD    UHL
        LXI     H,CAUSE
        MVI     M,CTRAP
        JMP     SAVE
VECENT: SHLD    UHL
        LXI     H,CAUSE
        MVI     M,CVECT

; Saves the user's registers; only the two bytes below the user's SP are touched on its stack.
SAVE:   POP     H               ; the user's PC
        SHLD    UPC
        PUSH    PSW
        POP     H               ; H = A, L = flags
        SHLD    SAVEF
        RIM                     ; IE and masks (after a TRAP: IE as it was before the TRAP)
        DI
        ANI     0FH
        STA     UIM
        LXI     H,0
        DAD     SP
        SHLD    USP             ; SP as it was before the RST or interrupt
        LXI     SP,MSTACK
        MVI     A,RIOSTOP       ; a program's own timer would TRAP into the monitor: stop it
        OUT     RIOCMD
        MOV     H,B
        MOV     L,C
        SHLD    SAVEC
        XCHG
        SHLD    SAVEE
        CALL    BPREM           ; A = 1: breakpoints were in the program
        MOV     C,A
        LDA     CAUSE
        CPI     CTRAP
        JZ      TRAPPED
        CPI     CVECT
        JNZ     SAVE1
        LDA     UIM             ; RST 7.5 was taken, so IE was on; the acknowledge cleared it
        ORI     08H
        STA     UIM
        JMP     BREAK
SAVE1:  DCR     C               ; RST n: was the RST one of our breakpoints?
        JNZ     BREAK
        LHLD    UPC
        DCX     H
        CALL    BPFIND
        JNZ     BREAK
        SHLD    UPC             ; yes: the program stopped at the breakpoint's address
; Shows where the program stopped: PC and the byte there. Then the monitor waits for a command.
BREAK:  LHLD    UPC
        MOV     E,M
        CALL    SHOWAB
        JMP     CMDLOOP

TRAPPED: LDA    GOFLAG
        ORA     A
        JZ      STEPPED
        XRA     A               ; the step over a breakpoint is done: insert them all and go
        STA     GOFLAG
        JMP     GORUN
STEPPED: LHLD   UPC
        JMP     STPCMD1

; ---- reset ----------------------------------------------------------------------------------
COLD:   LXI     SP,MSTACK
        MVI     A,RIOPORTS
        OUT     RIOCMD
        MVI     A,KMODE
        OUT     KDCMD
        MVI     A,KCLOCK
        OUT     KDCMD
        MVI     A,KCLEAR
        OUT     KDCMD
        MVI     A,18H+03H       ; SIM: mask RST 5.5 and 6.5, open RST 7.5, forget a VECT press
        SIM
        CALL    BPREM           ; RESET during a run with breakpoints: give the bytes back
        LXI     H,RSAVE
        MVI     B,VAREND-RSAVE
        XRA     A
COLD1:  MOV     M,A
        INX     H
        DCR     B
        JNZ     COLD1
        LXI     H,USERSP
        SHLD    USP
        LXI     H,USERPC
        SHLD    UPC
        SHLD    CURADR
        SHLD    BPADR
        MVI     A,0BH           ; the user starts with IE on and RST 7.5 open (VECT breaks in)
        STA     UIM
        MVI     A,OPJMP
        STA     RV55
        STA     RV65
        LXI     H,VECENT        ; an interrupt: IE was on, the PC is where it struck
        SHLD    RV55+1
        SHLD    RV65+1
        LXI     H,SIGNON
        CALL    SHOWT

; ---- the command loop -------------------------------------------------------------------------
CMDLOOP: LXI    SP,MSTACK
        CALL    GETKEY
; A = a key to take as a command (from the loop, or the key that ended another command)
DISPATCH: LXI   SP,MSTACK
        CPI     KR
        JZ      RCMD
        CPI     KMEM
        JZ      MEMCMD
        CPI     KREG
        JZ      REGCMD
        CPI     KGO
        JZ      GOCMD
        CPI     KSTEP
        JZ      STPCMD
ERROR:  LXI     H,ERRTXT
        CALL    SHOWT
        JMP     CMDLOOP

PROMPT: LXI     H,PRMTXT
        CALL    SHOWT
        JMP     CMDLOOP

; R, then a command digit.
RCMD:   LXI     H,RTXT
        CALL    SHOWT
        CALL    GETKEY
        CPI     10H
        JNC     ERROR
        ADD     A
        MOV     E,A
        MVI     D,0
        LXI     H,RTAB
        DAD     D
        MOV     A,M
        INX     H
        MOV     H,M
        MOV     L,A
        PCHL
RTAB:   DW      ERROR, MEMCMD, REGCMD, ERROR, ERROR, STPCMD, ERROR, GOCMD
        DW      BPCMD, BPCLR, ERROR, ERROR, ERROR, ERROR, ERROR, ERROR

; ---- MEM (R 1): examine and modify memory -----------------------------------------------------
MEMCMD: LHLD    CURADR
        LXI     D,FBYTE
        CALL    GETADR
        SHLD    CURADR
        CPI     KNEXT
        JZ      MEM1
        CPI     KEXEC
        JNZ     DISPATCH
MEM1:   MVI     C,0             ; C = 1 once a digit was typed
        MOV     E,M
MEM2:   CALL    SHOWMD
        CALL    GETKEY
        CPI     10H
        JNC     MEM3
        CALL    DIGIT8
        JMP     MEM2
MEM3:   MOV     B,A
        DCR     C
        JNZ     MEM4
        MOV     M,E
        MOV     A,M
        CMP     E
        JNZ     ERROR           ; nothing there keeps the byte (EPROM, no memory)
MEM4:   MOV     A,B
        CPI     KNEXT
        JNZ     MEM5
        INX     H
        JMP     MEM6
MEM5:   CPI     KPREV
        JNZ     MEM7
        DCX     H
MEM6:   SHLD    CURADR
        JMP     MEM1
MEM7:   CPI     KEXEC
        JZ      PROMPT
        JMP     DISPATCH

; ---- REG (R 2): examine and modify the user's registers ---------------------------------------
NREGS   EQU     11
REGCMD: XRA     A
REG1:   STA     REGIX
        MOV     E,A             ; HL = REGTAB + 5 * index
        ADD     A
        ADD     A
        ADD     E
        MOV     E,A
        MVI     D,0
        LXI     H,REGTAB
        DAD     D
        MOV     A,M
        STA     DBUF
        INX     H
        MOV     A,M
        STA     DBUF+1
        INX     H
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        MOV     B,M             ; B = size in bytes
        XCHG                    ; HL = where the register is saved
        MOV     E,M
        INX     H
        MOV     D,M
        DCX     H               ; DE = its value
        MOV     A,B
        DCR     A
        JNZ     REG2
        MOV     D,A             ; one byte
REG2:   MVI     C,0
REG3:   CALL    SHOWRG
        CALL    GETKEY
        CPI     10H
        JNC     REG5
        XCHG
        CALL    DIGIT16
        XCHG
        MOV     A,B
        DCR     A
        JNZ     REG3
        MOV     D,A
        JMP     REG3
REG5:   PUSH    PSW
        DCR     C
        JNZ     REG6
        MOV     M,E
        DCR     B
        JZ      REG6
        INX     H
        MOV     M,D
REG6:   POP     PSW
        CPI     KNEXT
        JNZ     REG7
        LDA     REGIX
        INR     A
        CPI     NREGS
        JC      REG1
        XRA     A
        JMP     REG1
REG7:   CPI     KPREV
        JNZ     REG8
        LDA     REGIX
        DCR     A
        JP      REG1
        MVI     A,NREGS-1
        JMP     REG1
REG8:   CPI     KEXEC
        JZ      PROMPT
        JMP     DISPATCH

; name (two segment codes), where it is saved, size
REGDEF  MACRO   S1,S2,WHERE,SIZE
        DB      S1,S2
        DW      WHERE
        DB      SIZE
        ENDM
REGTAB: REGDEF  77H,00H,SAVEA,1         ; A
        REGDEF  7CH,00H,SAVEB,1         ; b
        REGDEF  39H,00H,SAVEC,1         ; C
        REGDEF  5EH,00H,SAVED,1         ; d
        REGDEF  79H,00H,SAVEE,1         ; E
        REGDEF  71H,00H,SAVEF,1         ; F (flags)
        REGDEF  30H,00H,SAVEIM,1        ; I (interrupt enable and masks, as RIM reads them)
        REGDEF  76H,00H,SAVEHL+1,1      ; H
        REGDEF  38H,00H,SAVEHL,1        ; L
        REGDEF  6DH,73H,SAVESP,2        ; SP
        REGDEF  73H,39H,SAVEPC,2        ; PC
        IF      $-REGTAB NE 5*NREGS
        ERROR   "REGTAB must have NREGS entries"
        ENDIF

; ---- GO (R 7) ---------------------------------------------------------------------------------
GOCMD:  LHLD    UPC
        LXI     D,FGO
        CALL    GETADR
        CPI     KEXEC
        JZ      GO1
        CPI     KNEXT
        JNZ     DISPATCH
GO1:    SHLD    UPC
        CALL    BPFIND          ; starting on a breakpoint: step over it first, then insert
        JNZ     GORUN
        MVI     A,1
        STA     GOFLAG
        JMP     STEPRUN
GORUN:  CALL    BPINS
        CALL    CLRDSP
        CALL    PREP
        JMP     RESUME

; ---- STEP (R 5): single step ------------------------------------------------------------------
STPCMD: LHLD    UPC
STPCMD1: LXI    D,FBYTE
        CALL    GETADR
        SHLD    UPC
        CPI     KNEXT
        JZ      STEP1
        CPI     KEXEC
        JZ      PROMPT
        JMP     DISPATCH
STEP1:  XRA     A
        STA     GOFLAG
STEPRUN: MVI    A,LOW STEPN
        OUT     TIMLO
        MVI     A,(HIGH STEPN) OR TPULSE
        OUT     TIMHI
        CALL    PREP
        MVI     A,RIOSTART
        OUT     RIOCMD          ; T = 0: the timer starts (see STEPN)
; Loads the user's registers and enters the program (112 T-states from the OUT above).
RESUME: LXI     SP,RSAVE
        POP     B
        POP     D
        POP     PSW
        LHLD    USP
        SPHL
        LHLD    UHL
        JMP     TRAMP

; Sets the user's interrupt masks and builds the trampoline: EI (if the user's IE was on) or NOP,
; then JMP to the user's PC. EI acts after the JMP, so the first instruction can be interrupted.
PREP:   LDA     UIM
        MOV     B,A
        ANI     07H
        ORI     18H             ; set the masks, forget a VECT press made in the monitor
        SIM
        MOV     A,B
        ANI     08H
        MVI     A,0
        JZ      PREP1
        MVI     A,OPEI
PREP1:  STA     TRAMP
        MVI     A,OPJMP
        STA     TRAMP+1
        LHLD    UPC
        SHLD    TRAMP+2
        RET

; ---- breakpoints (R 8 set/clear, R 9 clear all) ------------------------------------------------
BPCMD:  LHLD    BPADR
        LXI     D,FBP
        CALL    GETADR
        SHLD    BPADR
        CPI     KEXEC
        JZ      PROMPT
        CPI     KNEXT
        JNZ     DISPATCH
        CALL    BPFIND
        JNZ     BPC1
        XRA     A               ; set there: clear it
        STAX    D
        INX     D
        STAX    D
        JMP     BPCMD
BPC1:   CALL    RAMTST          ; RST 1 can only be written into RAM
        JNZ     ERROR
        PUSH    H
        LXI     H,0
        CALL    BPSRCH          ; a free entry
        POP     H
        JNZ     ERROR           ; all NBP in use
        MOV     A,L
        STAX    D
        INX     D
        MOV     A,H
        STAX    D
        JMP     BPCMD

BPCLR:  LXI     H,BPTAB
        MVI     B,3*NBP
        XRA     A
BPCLR1: MOV     M,A
        INX     H
        DCR     B
        JNZ     BPCLR1
        JMP     PROMPT

; HL = address: Z and DE = its entry when a breakpoint is set there. Keeps BC and HL.
BPFIND: MOV     A,H
        ORA     L
        JNZ     BPSRCH
        INR     A               ; 0000H is never a breakpoint (it marks a free entry): NZ
        RET
BPSRCH: PUSH    B
        LXI     D,BPTAB
        MVI     B,NBP
BPS1:   LDAX    D
        CMP     L
        JNZ     BPS2
        INX     D
        LDAX    D
        DCX     D
        CMP     H
        JZ      BPS3
BPS2:   INX     D
        INX     D
        INX     D
        DCR     B
        JNZ     BPS1
        ORI     1               ; not found: NZ
BPS3:   POP     B
        RET

; Puts RST 1 at every breakpoint, keeping the user's bytes.
BPINS:  LXI     H,BPTAB
        MVI     B,NBP
BPI1:   MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        MOV     A,E
        ORA     D
        JZ      BPI2
        LDAX    D
        MOV     M,A
        MVI     A,RST1
        STAX    D
BPI2:   INX     H
        DCR     B
        JNZ     BPI1
        LXI     H,BPMAGIC
        SHLD    BPFLAG
        RET

; Gives the user's bytes back (where the program has not itself changed the RST 1).
; A = 1 when the breakpoints were in, else 0.
BPREM:  LHLD    BPFLAG
        MOV     A,L
        CPI     LOW BPMAGIC
        JNZ     BPR0
        MOV     A,H
        CPI     HIGH BPMAGIC
        JNZ     BPR0
        LXI     H,0
        SHLD    BPFLAG
        LXI     H,BPTAB
        MVI     B,NBP
BPR1:   MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        MOV     A,E
        ORA     D
        JZ      BPR2
        LDAX    D
        CPI     RST1
        JNZ     BPR2
        MOV     A,M
        STAX    D
BPR2:   INX     H
        DCR     B
        JNZ     BPR1
        MVI     A,1
        RET
BPR0:   XRA     A
        RET

; Z when the byte at HL can be written (RAM); the byte is left as it was. Keeps all but A, flags.
RAMTST: MOV     A,M
        CMA
        MOV     M,A
        XRA     M               ; 0 when the complement was stored
        MOV     A,M
        CMA                     ; CMA and MOV leave the flags alone
        MOV     M,A
        RET

; ---- keypad entry ----------------------------------------------------------------------------
; Waits for a key: A = its code.
GETKEY: CALL    ANWEIN
        JZ      GETKEY
        RET

; Address entry: HL = the address shown, DE = routine that fills digits 4-7 for HL. Hex keys
; type a new address (the first one starts it afresh); any other key ends: A = the key, HL =
; the address. The dp on digit 3 marks the field being typed.
GETADR: MVI     C,0
GETA1:  PUSH    D
        LXI     D,DBUF
        CALL    PWORD
        LDA     DBUF+3
        ORI     S_DP
        STA     DBUF+3
        POP     D
        PUSH    D
        CALL    CALLDE
        POP     D
        CALL    SHOW
        CALL    GETKEY
        CPI     10H
        RNC
        CALL    DIGIT16
        JMP     GETA1

CALLDE: PUSH    D
        RET

; A = hex digit: HL = HL * 16 + A, or A alone when C = 0 (the first digit); then C = 1.
DIGIT16: INR    C
        DCR     C
        JNZ     DIG1
        LXI     H,0
DIG1:   DAD     H
        DAD     H
        DAD     H
        DAD     H
        ORA     L
        MOV     L,A
        MVI     C,1
        RET

; A = hex digit: E = E * 16 + A (a byte), or A alone when C = 0; then C = 1. Keeps HL, B.
DIGIT8: INR     C
        DCR     C
        JNZ     DIG81
        MVI     E,0
DIG81:  MOV     D,A
        MOV     A,E
        RLC
        RLC
        RLC
        RLC
        ANI     0F0H
        ORA     D
        MOV     E,A
        MVI     C,1
        RET

; Data fields for GETADR (digits 4-7 for the address in HL). They keep C, H, L.
FBYTE:  LXI     D,DBUF+4        ; "  dd": the byte at HL
        XRA     A
        STAX    D
        INX     D
        STAX    D
        INX     D
        MOV     A,M
        JMP     PBYTE
FGO:    LXI     D,GOTXT         ; "  Go"
        JMP     FTXT
FBP:    CALL    BPFIND          ; "  bP" when a breakpoint is set at HL, else "  --"
        LXI     D,BPTXT
        JZ      FTXT
        LXI     D,NBPTXT
FTXT:   PUSH    H
        LXI     H,DBUF+4
        MVI     B,4
FTXT1:  LDAX    D
        MOV     M,A
        INX     D
        INX     H
        DCR     B
        JNZ     FTXT1
        POP     H
        RET

; ---- display --------------------------------------------------------------------------------
; A -> two hex digits at DE; DE += 2. Keeps BC, HL.
PBYTE:  PUSH    PSW
        RRC
        RRC
        RRC
        RRC
        CALL    UMW
        STAX    D
        INX     D
        POP     PSW
        CALL    UMW
        STAX    D
        INX     D
        RET

; HL -> four hex digits at DE; DE += 4. Keeps BC, HL.
PWORD:  MOV     A,H
        CALL    PBYTE
        MOV     A,L
        JMP     PBYTE

; "aaaa  dd": address HL, byte E, nothing marked (where a program stopped). Keeps all but A, F.
SHOWAB: CALL    SHAD
        JMP     SHOW
; "aaaa  dd.": address HL, byte E being typed (dp on digit 7). Keeps all but A, F.
SHOWMD: CALL    SHAD
        LDA     DBUF+7
        ORI     S_DP
        STA     DBUF+7
        JMP     SHOW
SHAD:   PUSH    D
        MOV     A,E
        PUSH    PSW
        LXI     D,DBUF
        CALL    PWORD
        XRA     A
        STAX    D
        INX     D
        STAX    D
        INX     D
        POP     PSW
        CALL    PBYTE
        POP     D
        RET

; Register display: name in DBUF 0-1 (already there), value DE (B = 1: E only), dp on digit 7.
SHOWRG: PUSH    H
        PUSH    D
        XCHG
        LXI     D,DBUF+2
        XRA     A
        STAX    D
        INX     D
        STAX    D
        INX     D
        MOV     A,B
        CPI     2
        JZ      SHRG1
        XRA     A
        STAX    D
        INX     D
        STAX    D
        INX     D
        MOV     A,L
        CALL    PBYTE
        JMP     SHRG2
SHRG1:  CALL    PWORD
SHRG2:  LDA     DBUF+7
        ORI     S_DP
        STA     DBUF+7
        POP     D
        POP     H
        JMP     SHOW

; HL -> eight segment codes: copy them to DBUF and show them.
SHOWT:  LXI     D,DBUF
        MVI     B,8
SHOWT1: MOV     A,M
        STAX    D
        INX     H
        INX     D
        DCR     B
        JNZ     SHOWT1
; DBUF -> the display. Keeps all but A and flags.
SHOW:   PUSH    H
        PUSH    B
        CALL    DUWAIT
        MVI     A,KWRAI
        OUT     KDCMD
        LXI     H,DBUF
        MVI     B,8
SHOW1:  MOV     A,M
        OUT     KDDAT
        INX     H
        DCR     B
        JNZ     SHOW1
        POP     B
        POP     H
        RET

; Waits while the 8279 clears its display RAM (after a clear command, e.g. the thesis's 0D1H).
DUWAIT: IN      KDCMD
        ORA     A
        JM      DUWAIT
        RET

; ANWAZL's body: eight blank digits. Keeps all registers and flags.
CLRDSP: PUSH    PSW
        PUSH    B
        CALL    DUWAIT
        MVI     A,KWRAI
        OUT     KDCMD
        XRA     A
        MVI     B,8
CLRD1:  OUT     KDDAT
        DCR     B
        JNZ     CLRD1
        POP     B
        POP     PSW
        RET

; ---- texts (segment codes, leftmost digit first) ----------------------------------------------
SIGNON: DB      40H,77H,38H,73H,00H,7FH,6DH,40H ; "-ALP 85-"
PRMTXT: DB      40H,00H,00H,00H,00H,00H,00H,00H ; "-"
ERRTXT: DB      79H,50H,50H,00H,00H,00H,00H,00H ; "Err"
RTXT:   DB      50H,00H,00H,00H,00H,00H,00H,00H ; "r"
GOTXT:  DB      00H,00H,3DH,5CH                 ; "  Go"
BPTXT:  DB      00H,00H,7CH,73H                 ; "  bP"
NBPTXT: DB      00H,00H,40H,40H                 ; "  --"

; ---- AUS at 05A8H ------------------------------------------------------------------------------
        IF      $ GT AUS
        ERROR   "monitor code overruns AUS (05A8H)"
        ELSE
        DS      AUS-$,0FFH
        ENDIF
; AUS: A = segment code; B = one-hot digit mask, 80H = digit 0 (leftmost) ... 01H = digit 7.
; Writes A to that digit and rotates B right one place (the next digit; 01H -> 80H). B = 0
; writes nothing. Keeps A, C, D, E, H, L and the flags.
        PUSH    H
        PUSH    PSW
        MOV     A,B
        MVI     L,KWRDSP        ; digit 0
        ORA     A
        JZ      AUS3
AUS1:   RLC                     ; find the leftmost 1: its digit number counts in L
        JC      AUS2
        INR     L
        JMP     AUS1
AUS2:   CALL    DUWAIT
        MOV     A,L
        OUT     KDCMD
        POP     PSW
        PUSH    PSW
        OUT     KDDAT
        MOV     A,B
        RRC
        MOV     B,A
AUS3:   POP     PSW
        POP     H
        RET

; ---- UMW at 05C9H ------------------------------------------------------------------------------
        IF      $ GT UMW
        ERROR   "AUS overruns UMW (05C9H)"
        ELSE
        DS      UMW-$,0FFH
        ENDIF
; UMW: A = hex digit (bits 3-0; bits 7-4 are ignored) -> A = its segment code.
; Keeps B, C, D, E, H, L; flags changed.
        PUSH    H
        ANI     0FH
        ADI     LOW SEGTAB
        MOV     L,A
        MVI     H,HIGH SEGTAB
        MOV     A,M
        POP     H
        RET
SEGTAB: DB      3FH,06H,5BH,4FH,66H,6DH,7DH,07H ; 0-7
        DB      7FH,6FH,77H,7CH,39H,5EH,79H,71H ; 8-9, A b C d E F
        IF      (HIGH SEGTAB) NE (HIGH (SEGTAB+15))
        ERROR   "SEGTAB must not cross a page"
        ENDIF

; ---- ANWEIN at 0701H ---------------------------------------------------------------------------
        IF      $ GT ANWEIN
        ERROR   "monitor code overruns ANWEIN (0701H)"
        ELSE
        DS      ANWEIN-$,0FFH
        ENDIF
; ANWEIN: returns at once. No key in the 8279 FIFO: Z set, A = 0. Else NZ (and CY), A = the
; key's code: 00H-0FH hex keys, 10H EXEC, 11H NEXT, 12H GO, 13H MEM, 14H REG, 15H STEP,
; 16H PREV, 17H R. Keeps B, C, D, E, H, L.
        IN      KDCMD
        ANI     KSTCNT          ; characters in the FIFO
        RZ
        MVI     A,KRDFIFO
        OUT     KDCMD
        IN      KDDAT
        ANI     3FH             ; scan row, return line (SHIFT and CNTL are grounded anyway)
        CPI     0FFH            ; NZ and CY, A unchanged: key 0 must not look like "no key"
        RET

; ---- ANWAZL at 07BCH ---------------------------------------------------------------------------
        IF      $ GT ANWAZL
        ERROR   "monitor code overruns ANWAZL (07BCH)"
        ELSE
        DS      ANWAZL-$,0FFH
        ENDIF
; ANWAZL: blanks all eight digits. Keeps every register and the flags.
        JMP     CLRDSP

; ---- ANWAUS at 07C7H ---------------------------------------------------------------------------
        IF      $ GT ANWAUS
        ERROR   "ANWAZL overruns ANWAUS (07C7H)"
        ELSE
        DS      ANWAUS-$,0FFH
        ENDIF
; ANWAUS: A = hex digit (bits 3-0): its segment code to the digit chosen by B, B rotated right
; (as AUS). Keeps A, C, D, E, H, L and the flags.
        PUSH    PSW
        CALL    UMW
        CALL    AUS
        POP     PSW
        RET

        IF      $ GT 0800H
        ERROR   "the monitor is larger than its 2 KB EPROM"
        ELSE
        DS      0800H-$,0FFH
        ENDIF
        END
