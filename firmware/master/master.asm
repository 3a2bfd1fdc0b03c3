; ; MASTER PROGRAM (thesis 5.3's recommendation): walks a path table of rapid moves, lines and
; ; arcs and hands each linear segment to the line routine of thesis-fixed (0800H), as MAIN
; ; does: X1 Y1 X2 Y2 at 1B00H..1B09H, DLYK at 1B38H, then PARAM and the YID/OKEY/OUT/INPUT loop.
; ; Arcs: Watanabe and Iwai, IECI '81, eq. 11: the centre angle of a segment is 2^-C_R rad, so each
; ; next end point comes from shifts; the first point is pushed out by eps_A = 2^(-2C_R-4) R.
; ; A path that opens with a sampling header (type 5) runs by the paper's sampling interpolation
; ; instead (SMP, section 2: both axes every 2 ms, a feed ramp), not by the thesis's line routine.
; ; Runs from the expansion EPROM (3000H, board option `expansion`); tables at 3DD0H
; ; (alp85 gcode). docs/contours.md.
; ;
; ; thesis-fixed's routines (checked against build/firmware/thesis/thesis-fixed.json by CTest
; ; master:thesis-addresses)
TPARAM  EQU     0B32H                   ; thesis-fixed PARAM
TYID    EQU     0BE9H                   ; thesis-fixed YID
TOKEY   EQU     0C58H                   ; thesis-fixed OKEY
TOUT    EQU     0C73H                   ; thesis-fixed OUT
TINPUT  EQU     0D51H                   ; thesis-fixed INPUT
TZMOVE  EQU     0AABH                   ; thesis-fixed ZMOVE
TBITTI  EQU     0C39H                   ; thesis-fixed BITTI
TDIVI   EQU     093AH                   ; thesis-fixed DIVI
TSIFIR  EQU     0A10H                   ; thesis-fixed SIFIR
; ; the monitor
AUS     EQU     05A8H
ANWEIN  EQU     0701H
ANWAUS  EQU     07C7H
; ; the line routine's RAM (docs/thesis.md)
X1      EQU     1B00H
Y1      EQU     1B03H
X2      EQU     1B06H
Y2      EQU     1B09H
YIDV    EQU     1B30H
YAC     EQU     1B32H
XAC     EQU     1B34H
TPREV   EQU     1B36H
DLYK    EQU     1B38H
SGNY    EQU     1B39H
SGNX    EQU     1B3AH
ZKOR    EQU     1B3CH
ZAC     EQU     1B3EH
; ; the master's RAM, above the line routine's
AX      EQU     1C00H                   ; X* - CX, 16.16 two's complement (4 bytes)
AY      EQU     1C04H                   ; Y* - CY
NX      EQU     1C08H                   ; the next X*, Y*
NY      EQU     1C0CH
TV      EQU     1C10H                   ; the shift-and-add accumulator
CR      EQU     1C14H                   ; C_R
SIG     EQU     1C15H                   ; 0: add the shifted term, 1: subtract it
DIR     EQU     1C16H                   ; 0: CCW (G03), 1: CW (G02)
NCNT    EQU     1C17H                   ; whole segments still to go (word)
CXV     EQU     1C19H                   ; centre (word each)
CYV     EQU     1C1BH
EPTR    EQU     1C1DH                   ; the entry being run
SEG     EQU     1C1FH                   ; segments handed over (word), shown on the display
PBASE   EQU     1C21H                   ; P
TABLE   EQU     3DD0H                   ; the path tables (16-byte entries, type 0 ends a path)
;
        ORG     3000H
MSTR:   LXI     SP,20B0H
        CALL    TSIFIR                  ; clear, B = digit 0
        MVI     A,73H                   ; "P="
        CALL    AUS
        MVI     A,48H
        CALL    AUS
        MVI     A,40H                   ; "-": the path number to come
        CALL    AUS
PKEY:   CALL    ANWEIN                  ; a digit 1-9: the path
        JZ      PKEY
        CPI     01H
        JC      PKEY
        CPI     0AH
        JNC     PKEY
        STA     PBASE
        MVI     B,20H                   ; show it on digit 2
        CALL    ANWAUS
SKEY:   CALL    ANWEIN                  ; any key starts
        JZ      SKEY
        LXI     H,TABLE                 ; skip P-1 paths
        LDA     PBASE
        MOV     C,A
PSKIP:  DCR     C
        JZ      PFND
PSK1:   MOV     A,M
        LXI     D,0010H
        DAD     D
        ANA     A
        JNZ     PSK1
        JMP     PSKIP
PFND:   SHLD    EPTR
        LXI     H,0000H                 ; the table stands at the origin of the path (0, 0)
        SHLD    XAC
        SHLD    YAC
        SHLD    SEG
        CALL    SHOW
        LHLD    EPTR                    ; a path that opens with a sampling header (type 5)
        MOV     A,M                     ; runs by sampling (SMP), every other by the thesis's
        CPI     05H                     ; line routine
        JZ      SMP
; ; one entry: +0 type, +1 C_R, +2 F, +4 X, +6 Y, +8 Z, +10 CX, +12 CY, +14 N
ENTRY:  LHLD    EPTR
        MOV     A,M
        ANA     A
        JZ      DONE
        INX     H
        INX     H
        MOV     E,M                     ; F (mm/min): DLYK = 1500 / F, as SPEED does
        INX     H
        MOV     D,M
        XCHG
        SHLD    1B1CH
        LXI     H,05DCH
        SHLD    1B18H
        CALL    TDIVI
        LDA     1B2AH
        STA     DLYK
        LHLD    EPTR                    ; Z first, on its own (as COORD moves Z before X, Y)
        LXI     D,0008H
        DAD     D
        MOV     E,M
        INX     H
        MOV     D,M
        LHLD    ZAC
        MOV     A,L
        CMP     E
        JNZ     ZGO
        MOV     A,H
        CMP     D
        JZ      ZDONE
ZGO:    XCHG
        SHLD    ZKOR
        CALL    NEXTS
ZHAND:  CALL    TZMOVE                  ; the Z hand-over: ZKOR set
        CALL    SHOW
ZDONE:  LHLD    EPTR
        MOV     A,M
        CPI     03H
        JNC     ARC
        CALL    ENDXY                   ; rapid or line: one segment to the end point
        CALL    SEGMT
NEXTE:  LHLD    EPTR
        LXI     D,0010H
        DAD     D
        SHLD    EPTR
        JMP     ENTRY
DONE:   CALL    TBITTI
        HLT
;
; ; ENDXY: X2, Y2 = the entry's end point
ENDXY:  LHLD    EPTR
        CALL    EXY
        SHLD    Y2
        XCHG
        SHLD    X2
        RET
; ; EXY: DE = x, HL = y, the end point of the entry at HL
EXY:    LXI     D,0004H
        DAD     D
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        MOV     A,M
        INX     H
        MOV     H,M
        MOV     L,A
        RET
;
; ; SEGMT: one line from (XAC, YAC) to (X2, Y2) by the thesis line routine; none if no move
SEGMT:  LHLD    XAC
        SHLD    X1
        XCHG
        LHLD    X2
        MOV     A,L
        SUB     E
        MOV     C,A
        MOV     A,H
        SBB     D
        ORA     C
        MOV     B,A                     ; B = 0: X1 = X2
        LHLD    YAC
        SHLD    Y1
        XCHG
        LHLD    Y2
        MOV     A,L
        CMP     E
        JNZ     SEG1
        MOV     A,H
        CMP     D
        JNZ     SEG1
        MOV     A,B
        ANA     A
        RZ                              ; no move: no segment
SEG1:   CALL    NEXTS
HAND:   IN      0FAH                    ; the hand-over: X1 Y1 X2 Y2 DLYK set (CMAIN L21-L23)
        ANI     0FH
        STA     TPREV
        MOV     A,B
        ANA     A
        JZ      VERT
        CALL    TPARAM
SLOOP:  CALL    TYID                    ; MAIN's loop, L28-L33
        CALL    TOKEY
        RZ
        CALL    TOUT
        CALL    TINPUT
        JMP     SLOOP
; ; X1 = X2: PARAM would divide by zero; the general loop steps Y alone when YAC <> YIDV, so
; ; give it the signs and the ideal Y = Y2 (ANA's open-loop routine ends in HLT)
VERT:   LHLD    Y1
        XCHG
        LHLD    Y2
        SHLD    YIDV
        MOV     A,L                     ; Y2 - Y1: 80H in SGNY when negative
        SUB     E
        MOV     A,H
        SBB     D
        MVI     A,00H
        JNC     VERT1
        MVI     A,80H
VERT1:  STA     SGNY
        XRA     A
        STA     SGNX
VLOOP:  CALL    TOKEY
        RZ
        CALL    TOUT
        CALL    TINPUT
        JMP     VLOOP
;
; ; NEXTS: one more segment, on the display (keeps B)
NEXTS:  LHLD    SEG
        INX     H
        SHLD    SEG
SHOW:   PUSH    B
        MVI     B,80H                   ; "P=n" again (ZMOVE clears the display)
        MVI     A,73H
        CALL    AUS
        MVI     A,48H
        CALL    AUS
        LDA     PBASE
        CALL    ANWAUS
        MVI     B,08H                   ; digits 4-7: the segment number, hex
        LDA     SEG+1
        RRC
        RRC
        RRC
        RRC
        CALL    ANWAUS
        LDA     SEG+1
        CALL    ANWAUS
        LDA     SEG
        RRC
        RRC
        RRC
        RRC
        CALL    ANWAUS
        LDA     SEG
        CALL    ANWAUS
        POP     B
        RET
;
; ; ARC: C_R, centre, N from the entry; X*, Y* from the start with the first-point correction
ARC:    CALL    APAR                    ; DIR, C_R, centre, N (HL at the entry, A its type)
        CALL    ASTX                    ; AX, AY = (XAC, YAC) - the centre, pushed out by eps_A
        CALL    ASTY
ALOOP:  LHLD    NCNT
        MOV     A,H
        ORA     L
        JZ      ALAST
        DCX     H
        SHLD    NCNT
        LDA     DIR                     ; X' with sigma = -s: subtract for CCW
        XRI     01H
        STA     SIG
        LXI     H,AX
        LXI     D,AY
        LXI     B,NX
        CALL    STEP3
        LDA     DIR                     ; Y' with sigma = +s
        STA     SIG
        LXI     H,AY
        LXI     D,AX
        LXI     B,NY
        CALL    STEP3
        LXI     H,NX
        LXI     D,AX
        MVI     C,08H
        CALL    COPYN
        LDA     AY+3                    ; X2 = CX + X* to a step against the X motion: the
        RLC                             ; line routine's corners stand on the side the X step
        LXI     H,DIR                   ; goes to, so the floor where X goes +, the ceiling
        XRA     M                       ; where it goes - (CCW below the centre, CW above it)
        ANI     01H                     ; sign(Y*) xor DIR: 1 = floor
        XRI     01H
        MOV     B,A                     ; B = 1: the ceiling
        LXI     H,AX
        LXI     D,CXV
        CALL    XRND
        SHLD    X2
        LXI     H,AY                    ; Y2 = CY + round(Y*)
        LXI     D,CYV
        CALL    ROUND
        SHLD    Y2
AHAND:  CALL    SEGMT                   ; ALOOP to here: one segment's arithmetic (docs/contours.md)
        JMP     ALOOP
ALAST:  CALL    ENDXY                   ; the last, shorter segment ends on the end point
        CALL    SEGMT
        JMP     NEXTE
;
; ; START: (BC) = (HL - DE) . 0, pushed out by eps_A: + rsh((BC), 2 C_R + 4)
START:  MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     H,A
        PUSH    B
        SHLD    TV+2
        LXI     H,0000H
        SHLD    TV
        LXI     H,TV
        POP     D
        PUSH    D
        MVI     C,04H
        CALL    COPYN                   ; (BC) = the start, exact
        LDA     CR
        ADD     A
        ADI     04H
        CALL    RSH                     ; TV = rsh(start, 2 C_R + 4)
        POP     H
        PUSH    H
        CALL    ADDT                    ; TV = start + TV
        LXI     H,TV
        POP     D
        MVI     C,04H
        JMP     COPYN
;
; ; STEP3: eq. 11 for one coordinate, P at HL, Q at DE, the result to BC, SIG = sigma:
; ;   T = rsh(Q, C_R+2); T = P + sigma T; T = rsh(T, C_R+1); T = Q - sigma T;
; ;   T = rsh(T, C_R); result = P + sigma T
STEP3:  PUSH    B
        PUSH    H
        PUSH    D
        XCHG
        LXI     D,TV
        MVI     C,04H
        CALL    COPYN                   ; T = Q
        LDA     CR
        ADI     02H
        CALL    RSH
        POP     D
        POP     H
        PUSH    H
        PUSH    D
        CALL    PSIG                    ; T = P + sigma T
        LDA     CR
        INR     A
        CALL    RSH
        POP     H
        PUSH    H
        CALL    MSIG                    ; T = Q - sigma T
        LDA     CR
        CALL    RSH
        POP     D
        POP     H
        CALL    PSIG                    ; T = P + sigma T
        LXI     H,TV
        POP     D
        MVI     C,04H
        JMP     COPYN
PSIG:   LDA     SIG
        ANA     A
        JZ      ADDT
        JMP     SUBT
MSIG:   LDA     SIG
        ANA     A
        JZ      SUBT
        JMP     ADDT
;
; ; ADDT: TV = (HL) + TV; SUBT: TV = (HL) - TV (32 bits)
ADDT:   LXI     D,TV
        MVI     B,04H
        ANA     A
ADD1:   LDAX    D
        ADC     M
        STAX    D
        INX     H
        INX     D
        DCR     B                       ; keeps CY
        JNZ     ADD1
        RET
SUBT:   LXI     D,TV
        MVI     B,04H
        ANA     A
SUB1:   LDAX    D
        MOV     C,A
        MOV     A,M
        SBB     C
        STAX    D
        INX     H
        INX     D
        DCR     B
        JNZ     SUB1
        RET
;
; ; RSH: TV = (TV + 2^(A-1)) >> A, arithmetic, A >= 1: A-1 shifts, +1, one shift
RSH:    MOV     C,A
RSH1:   DCR     C
        JZ      RSH2
        CALL    SHR1
        JMP     RSH1
RSH2:   LXI     H,TV
        MVI     B,04H
RSH3:   INR     M
        JNZ     SHR1
        INX     H
        DCR     B
        JNZ     RSH3
SHR1:   LXI     H,TV+3
        MOV     A,M
        RAL                             ; CY = the sign
        MOV     A,M
        RAR
        MOV     M,A
        DCX     H
        MOV     A,M
        RAR
        MOV     M,A
        DCX     H
        MOV     A,M
        RAR
        MOV     M,A
        DCX     H
        MOV     A,M
        RAR
        MOV     M,A
        RET
;
; ; COPYN: C bytes from (HL) to (DE)
COPYN:  MOV     A,M
        STAX    D
        INX     H
        INX     D
        DCR     C
        JNZ     COPYN
        RET
;
; ; ROUND: HL = (DE) + the integer part of (HL) + 1/2 (16.16 rounded to the nearest step)
ROUND:  PUSH    D
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        MOV     A,D
        ADI     80H                     ; CY: the half carries into the integer part
        MOV     E,M
        INX     H
        MOV     D,M
        JNC     RND1
        INX     D
RND1:   POP     H
        MOV     A,M
        INX     H
        MOV     H,M
        MOV     L,A
        DAD     D
        RET
;
; ; XRND: HL = (DE) + floor (HL) when B = 0, else its ceiling (16.16 to a step)
XRND:   PUSH    D
        MOV     A,M
        INX     H
        ORA     M                       ; Z: X* is a whole step, floor = ceiling
        INX     H
        MOV     E,M
        INX     H
        MOV     D,M
        JZ      RND1
        DCR     B
        JNZ     RND1
        INX     D
        JMP     RND1
;
;
; ; ---------------------------------------------------------------------------------------------
; ; SAMPLING: the second segment method, Watanabe and Iwai section 2 (eqs. 2-7), chosen per path:
; ; a path whose first entry is a sampling header (type 5) runs here. Each 2 ms sample advances
; ; the major axis by dS_x (eq. 4), puts y = T_y x_r + y0* (eq. 5) and sends both axes' pulses in
; ; one OUT (eq. 6). B = 16 (T_y 0.16), double precision 16.16, C_L = 8: X_d = 128 steps. Lines are
; ; one chord, arcs the chords between the 2^-C_R vertices of eq. 11 (exact 16.16, STEP3).
; ; Header: +1 bit 0 ramp, +2 F_s (steps a sample, 0.16), +4 L (16.16): the path length to the next
; ; stop, less a margin. docs/contours.md "Sampling"; tests/master/sampling_ref.py is the model.
; ;
; ; The period: the 8155 timer, polled. TIMER OUT is wired to TRAP, whose vector (0024H) is the
; ; monitor's single step in ROM: a terminal count would end the run in the monitor. So the timer
; ; (single-pulse mode, TIMER OUT high all along) is never let reach it: a sample begins when the
; ; counter falls below 2800H (polled, its high byte), and STICK stops it, rewinds it by one
; ; period less the T-states the rewinding takes, and starts it again. The period is exact and
; ; does not drift; a sample that runs long (a chord's set-up) delays the next one only, by up to
; ; 2800H T-states before the terminal count. A sample's pulses go where x* crossed the major
; ; axis's step, PDN T-states after its tick (STICK, WOUT): a motor's pulses 1 / rate apart.
SPER    EQU     6144                    ; T-states a sample (2 ms at 3.072 MHz)
SKH     EQU     28H                     ; a sample begins below 2800H
SDT     EQU     97                      ; T-states from TREW's STOP write to its START write
KOUT    EQU     132                     ; T-states from WOUT's START write to its pulse write
FMIN    EQU     8000H                   ; 0.5 step a sample: 250 steps/s, start and stop
AFS     EQU     328                     ; ramp: 0.16 steps a sample per sample (1250 steps/s^2)
DWELL   EQU     20                      ; samples at rest at a stop point
SKJ     EQU     31H                     ; a job's stage runs while the counter is above 3100H
; ; RAM, above the master's
SFL     EQU     1C30H                   ; header flags (bit 0: ramp)
FSV     EQU     1C31H                   ; F_s, the group's feed (0.16 steps a sample)
LREM    EQU     1C33H                   ; path still to go before the stop, 16.16 (4)
DST     EQU     1C37H                   ; distance a deceleration from here takes, 16.16 (4)
FCU     EQU     1C3BH                   ; f, the feed now (0.16)
FLV     EQU     1C3DH                   ; F_MIN + j AFS (uncapped level)
JLV     EQU     1C3FH                   ; j, the ramp level
KST     EQU     1C40H                   ; k*, the progress along u, 16.16 (4)
OUTX    EQU     1C44H                   ; the position the pulses sent so far make
OUTY    EQU     1C46H
POUT    EQU     1C4CH                   ; port A for the next sample
POSX    EQU     1C4DH                   ; the entry's start point
POSY    EQU     1C4FH
CMU     EQU     1C61H                   ; 0: u = x, 1: u = y
CSU     EQU     1C62H                   ; u direction: 0 +, 1 -
CSG     EQU     1C63H                   ; sigma, the v direction: 0 +, 1 -
CNV     EQU     1C64H                   ; n, whole steps of u
CTY     EQU     1C66H                   ; T_y (0.16)
CYD     EQU     1C68H                   ; Y_d* (16.16, 4)
CYI     EQU     1C6CH                   ; Y_i* (16.16, 4)
CSEG    EQU     1C70H                   ; i, the segment of 128 steps
CCX     EQU     1C71H                   ; C_x (0.16)
PUV     EQU     1C73H                   ; P_u, P_v: the tool's target at the chord's start
PVV     EQU     1C75H
DSV     EQU     1C77H                   ; dS_x (0.16)
DSOK    EQU     1C79H                   ; 0: dS_x to compute
UUV     EQU     1C7AH                   ; |du| (4)
VVV     EQU     1C7EH                   ; |dv| (4)
DNF     EQU     1C84H                   ; 1: the chord ended in this sample
DUS     EQU     1C85H                   ; sign of du (0 +, 1 -)
DVS     EQU     1C86H                   ; sign of dv (0 +, 1 -, 2 zero)
SXV     EQU     1C87H                   ; this sample's target x, y
SYV     EQU     1C89H
JST     EQU     1C8BH                   ; the job's next stage (RUNJ), 0: none
OFV     EQU     1C8CH                   ; scratch (4)
OF2     EQU     1C90H                   ; scratch (4)
VRDY    EQU     1C94H                   ; 1: NX, NY hold the next vertex
PDN     EQU     1C95H                   ; POUT's pulses: T-states after their tick, 0 at once
PSND    EQU     1C97H                   ; port A this sample sends
PEND    EQU     1C98H                   ; 1: PSND waits for its time
CTG     EQU     1C99H                   ; minus the counter's value WOUT waits for
MCNT    EQU     1C9BH                   ; MUL32's count
QV      EQU     1C9CH                   ; F_LV C_x, 32 bits (mod 2^32), while QOK
DAV     EQU     1CA0H                   ; A_F C_x, 32 bits
OWED    EQU     1CA5H                   ; ticks owed (GRD): STICK takes them at once
QOK     EQU     1CA4H                   ; 1: QV holds for this chord, 2: DAV too
NOF     EQU     4FH                     ; the next chord's set-up (SDESC's results) at CMU + NOF
                                        ; ... PVV + NOF (1CB0H-1CC5H), copied at its join
JAV     EQU     1CD0H                   ; SDESC's A, E (16.16, 8 each) and P, the tool's target
JEV     EQU     1CD8H                   ; at the chord's start: the chord's, or the next one's
JPX     EQU     1CE0H                   ; when it is set up ahead (RUNJ)
JPY     EQU     1CE2H
SRDY    EQU     1CE4H                   ; 1: the next chord is set up (at CMU + NOF); 2, 3: the run's
                                        ; first chord to come (its predecessor's state is not)
JPT     EQU     1CE5H                   ; the entry whose end point ends the next chord
JPH     EQU     12H                     ; PDN from 1200H T-states: a late pulse
CAV     EQU     1CE8H                   ; the chord's start A: x, y 16.16 (8)
CEV     EQU     1CF0H                   ; its end E (8)
TPX     EQU     1CF8H                   ; the target where the last chord ended (as JAV-JPY)
TPY     EQU     1CFAH
JALT    EQU     1CE7H                   ; toggles: a stage a sample at most in the chord's end
JFW     EQU     16                      ; steps to go from which stages run whatever the time
GTC     EQU     17H                     ; SDESC's guard before SDC: 5888 T-states
SPLH    EQU     (0C000H+3075-KOUT)/256  ; CTG's high byte for a pulse within 3075 T-states
;
SMP:    LXI     H,0000H
        SHLD    OUTX
        SHLD    OUTY
        SHLD    TPX
        SHLD    TPY
        SHLD    POSX
        SHLD    POSY
        SHLD    X2                      ; (the look-ahead's start point)
        SHLD    Y2
        SHLD    PDN
        XRA     A
        STA     POUT
        STA     VRDY
        STA     PEND
        STA     OWED
        MVI     A,02H                   ; (no chord yet: the first is set up where it comes)
        STA     SRDY
        CALL    TSTART
SENT:   LHLD    EPTR
        MOV     A,M
        ANA     A
        JZ      SEND
        CPI     05H
        JZ      SHDR
        LXI     D,0008H                 ; Z first, on its own, the timer stopped (ZMOVE's own
        DAD     D                       ; 4 ms steps): the header before it stopped X and Y
        MOV     E,M
        INX     H
        MOV     D,M
        LHLD    ZAC
        MOV     A,L
        CMP     E
        JNZ     SZGO
        MOV     A,H
        CMP     D
        JZ      SZDN
SZGO:   XCHG
        SHLD    ZKOR
        CALL    TSTOP
        CALL    TZMOVE
        CALL    SHOW
        CALL    TSTART
SZDN:   LHLD    POSX                    ; the chord starts at the entry's start point
        SHLD    XAC
        SHLD    CAV+2
        LHLD    POSY
        SHLD    YAC
        SHLD    CAV+6
        LXI     H,0000H
        SHLD    CAV
        SHLD    CAV+4
        LHLD    EPTR
        MOV     A,M
        CPI     03H
        JNC     SARC
        CALL    SENDP                   ; a line: one chord to the end point, the next entry
        MVI     A,01H                   ; looked at during it
        STA     JST
        CALL    SCHRD
SNXT:   CALL    ENDXY                   ; the next entry starts where this one ended
        LHLD    X2
        SHLD    POSX
        LHLD    Y2
        SHLD    POSY
SNXT2:  LHLD    EPTR
        LXI     D,0010H
        DAD     D
        SHLD    EPTR
        JMP     SENT
SEND:   XRA     A                       ; the path's end: a stop, the timer stopped
        STA     JST
        CALL    SSTOP
        CALL    TSTOP
        LHLD    OUTX
        SHLD    XAC
        LHLD    OUTY
        SHLD    YAC
        JMP     DONE
; ; a header: a stop point (unless it is the first), then the group's feed, length and ramp
SHDR:   MVI     A,01H                   ; a stop point, the entry after the header looked at in
        STA     JST                     ; its dwell
        CALL    SSTOP
        XRA     A
        STA     JLV
        STA     DSOK
        STA     QOK
        LXI     H,0000H
        SHLD    KST
        SHLD    KST+2
        SHLD    DST
        SHLD    DST+2
        LHLD    EPTR
        INX     H
        MOV     A,M
        STA     SFL
        INX     H
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        XCHG
        SHLD    FSV
        SHLD    FCU
        XCHG
        LXI     D,LREM
        MVI     C,04H
        CALL    COPYN
        LXI     H,FMIN
        SHLD    FLV
        LDA     SFL
        RRC
        JNC     SNXT2
        ANA     A                       ; the ramp starts at F_MIN, or at F_s below it
        CALL    SLVL1
        JMP     SNXT2
; ; SENDP: CEV = the entry's end point . 0
SENDP:  CALL    ENDXY
        LXI     H,0000H
        SHLD    CEV
        SHLD    CEV+4
        LHLD    X2
        SHLD    CEV+2
        LHLD    Y2
        SHLD    CEV+6
        RET
; ; an arc: the vertices of eq. 11 from the start pushed out by eps_A (as ARC), a chord to each;
; ; its set-up and each next vertex computed during the chord before (RUNJ), else here
SARC:   LDA     JST
        CPI     01H
        JNZ     SAL
        XRA     A
        STA     JST
        STA     VRDY
        LHLD    EPTR
        MOV     A,M
        CALL    APAR
        CALL    GCHK
        CALL    ASTX
        CALL    GCHK
        CALL    ASTY
        LHLD    NCNT
        MOV     A,H
        ORA     L
        JZ      SAL
        MVI     A,03H
        STA     JST
SAL:    LDA     JST                     ; a job the last chord was too short for: finished here
        ANA     A
        JZ      SAL1
        CALL    GCHK
        CALL    RUNJ
        JMP     SAL
SAL1:   LHLD    NCNT
        MOV     A,H
        ORA     L
        JZ      SALST
        DCX     H
        SHLD    NCNT
        LDA     VRDY
        ANA     A
        JNZ     SAL2
        CALL    GCHK
        CALL    AVX
        CALL    GCHK
        CALL    AVY
SAL2:   XRA     A
        STA     VRDY
        LXI     H,NX
        LXI     D,AX
        MVI     C,08H
        CALL    COPYN
        CALL    NXE                     ; E = the centre . 0 + the vertex (JEV free: no job
        LXI     H,JEV                   ; runs here)
        LXI     D,CEV
        MVI     C,08H
        CALL    COPYN
        LHLD    NCNT                    ; the next vertex during this chord (3, 4), then the
        MOV     A,H                     ; next chord's set-up; the last chord next: its
        ORA     L                       ; set-up to the end point (9)
        MVI     A,03H
        JNZ     SAL4
        LHLD    EPTR
        SHLD    JPT
        MVI     A,09H
SAL4:   STA     JST
SAL3:   CALL    SCHRD
        LXI     H,CEV                   ; the next chord starts at this vertex
        LXI     D,CAV
        MVI     C,08H
        CALL    COPYN
        JMP     SAL
SALST:  CALL    SENDP                   ; the last chord ends on the end point; the next entry
        MVI     A,01H                   ; looked at during it
        STA     JST
        CALL    SCHRD
        JMP     SNXT
; ; APAR: an arc's DIR, C_R, centre and N from its entry (HL at it, A its type)
APAR:   SUI     03H
        XRI     01H
        STA     DIR
        INX     H
        MOV     A,M
        STA     CR
        LXI     D,0009H
        DAD     D
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        XCHG
        SHLD    CXV
        XCHG
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        XCHG
        SHLD    CYV
        XCHG
        MOV     E,M
        INX     H
        MOV     D,M
        XCHG
        SHLD    NCNT
        RET
; ; ASTX, ASTY: AX, AY = the start (XAC, YAC) less the centre, pushed out by eps_A
ASTX:   LHLD    CXV
        XCHG
        LHLD    XAC
        LXI     B,AX
        JMP     START
ASTY:   LHLD    CYV
        XCHG
        LHLD    YAC
        LXI     B,AY
        JMP     START
; ; AVX, AVY: the next vertex, eq. 11, to NX and NY
AVX:    LDA     DIR
        XRI     01H
        STA     SIG
        LXI     H,AX
        LXI     D,AY
        LXI     B,NX
        JMP     STEP3
AVY:    LDA     DIR
        STA     SIG
        LXI     H,AY
        LXI     D,AX
        LXI     B,NY
        JMP     STEP3
; ; RUNJ: one stage of the job that runs in the samples' spare time (each at most about 4000
; ; T-states): 1 the next entry, if an arc: its parameters and X start, 2 its Y start, 3 the next
; ; vertex's X, 4 its Y; then the next chord's set-up ahead of its join (SDESC into CMU + NOF, which
; ; SCHRD copies in): 5 (after the vertex) or 9 (to an entry's end point) its A, E and P, once this
; ; chord is in its last segment; 6, 7, 8 SDESC's three parts
RUNJ:   LDA     JST
        DCR     A
        JZ      JL1
        DCR     A
        JZ      JL2
        DCR     A
        JZ      JV1
        DCR     A
        JZ      JV2
        DCR     A
        JZ      JE5
        DCR     A
        JZ      JS6
        DCR     A
        JZ      JS7
        DCR     A
        JZ      JS8
        CALL    JSEG                    ; 9: the next chord ends on the end point of the entry
        RNZ                             ; at JPT
        LHLD    JPT
        CALL    EXY
        SHLD    JEV+6
        XCHG
        SHLD    JEV+2
        LXI     H,0000H
        SHLD    JEV
        SHLD    JEV+4
JAP:    LXI     H,CEV                   ; it starts at this chord's end, the tool at this
        LXI     D,JAV                   ; chord's last target (eq. 5 at k = n)
        MVI     C,08H
        CALL    COPYN
        LHLD    CNV                     ; (n = 128 m: TGT moves into segment m, the
        CALL    TGT                     ; next sample's TGT back to m - 1)
        SHLD    JPX
        XCHG
        SHLD    JPY
        MVI     A,06H
        STA     JST
        RET
JE5:    CALL    JSEG                    ; 5: the next chord ends on the next vertex
        RNZ
        CALL    NXE
        JMP     JAP
; ; NXE: JEV = the centre . 0 + the next vertex (NX, NY)
NXE:    LXI     H,NX
        LXI     D,JEV
        MVI     C,08H
        CALL    COPYN
        LHLD    JEV+2
        XCHG
        LHLD    CXV
        DAD     D
        SHLD    JEV+2
        LHLD    JEV+6
        XCHG
        LHLD    CYV
        DAD     D
        SHLD    JEV+6
        RET
JS6:    CALL    SDA                     ; 6-8: its set-up, in three stages
        JMP     JINC
JS7:    CALL    SDB
JINC:   LXI     H,JST
        INR     M
        RET
JS8:    CALL    SDC
        LXI     H,SRDY                  ; 0 to 1: ready (2, before a run's first chord: not)
        INR     M
        XRA     A
        STA     JST
        RET
; ; JSEG: Z when this chord is in its last segment (its target at k = n computable: TGT)
; ; (steps 0 .. n - 1 lie in the segments up to (n - 1) >> 7; k = n itself in n >> 7, one more
; ; when n is a multiple of 128: Z when CSEG >= (n - 1) >> 7; n = 0: Z)
JSEG:   LHLD    CNV
        DCX     H
        MOV     A,L
        RAL
        MOV     A,H
        RAL
        LXI     H,CSEG
        SUB     M
        RZ
        INR     A
        RET
JV2:    CALL    AVY
        MVI     A,01H
        STA     VRDY
        MVI     A,05H                   ; then the next chord's set-up
        STA     JST
        RET
JV1:    CALL    AVX
        MVI     A,04H
        STA     JST
        RET
JL1:    LHLD    EPTR
        LXI     D,0010H
        DAD     D
        SHLD    JPT
        MOV     A,M
        CPI     03H
        JC      JL0
        CPI     05H
        JNC     JL0
        CALL    APAR
        LHLD    X2                      ; it starts where this entry ends
        SHLD    XAC
        LHLD    Y2
        SHLD    YAC
        CALL    ASTX
        XRA     A
        STA     VRDY
        MVI     A,02H
        STA     JST
        RET
JL0:    DCR     A                       ; a line next (type 1, 2): stage 9, its set-up to its
                                        ; end point; else (the end, a header) none
        CPI     02H
        MVI     A,09H
        JC      JL3
        XRA     A
        JMP     JL3
JL2:    CALL    ASTY
        LHLD    NCNT
        MOV     A,H
        ORA     L
        MVI     A,03H
        JNZ     JL3
        MVI     A,09H                   ; an arc of its last chord only: to its end point
JL3:    STA     JST
        RET
;
; ; TSTART: the 8155 timer from 3FFFH, single-pulse mode (TIMER OUT stays high); TSTOP holds it
TSTART: LXI     H,3FFFH
        JMP     TRW2
TSTOP:  MVI     A,41H                   ; STOP
        OUT     0F8H
        RET
;
; ; STICK: waits for the sample's tick, rewinds the timer by one period, takes POUT to send: at
; ; once (PDN 0: the directions with the pulses low, then the pulses, both axes in the same OUT),
; ; or PDN T-states after the tick (WOUT), when x* crossed the major axis's step: a pulse at each
; ; crossing keeps a motor's pulses 1 / rate apart, not on the 2 ms grid (docs/results.md)
STICK:  LDA     OWED                    ; a tick a guard took (GCHK): now, the counter kept at
        ANA     A                       ; 2800H or more for this sample's work (up to ~5300
        JZ      STK0                    ; T-states) while the owed ticks are caught up, one
        DCR     A                       ; period a tick, each sample shorter than its period
        STA     OWED
        CALL    GCHK
        JMP     STK2
STK0:   IN      0FDH
        ANI     3FH
        CPI     SKH
        JNC     STK0
        CALL    TRWP
STK2:   LDA     POUT
        STA     PSND
        LHLD    PDN
        MOV     A,H
        ORA     L
        JZ      STOUT
        LXI     D,-(4000H+KOUT)         ; CTG = -(4000H + KOUT - PDN): the tick stands at
        DAD     D                       ; 4000H, the pulse at 4000H - PDN
        SHLD    CTG
        MVI     A,01H
        STA     PEND
        RET
STOUT:  LDA     PSND
        MOV     B,A
        ANI     0AH
        OUT     0F9H
        MOV     A,B
        OUT     0F9H
        XRA     A
        STA     PEND
        RET
; ; GCHK: the guard before work at a join that may run past the next tick (up to ~7400 T-states:
; ; SDESC's first two parts, a job's stage, a vertex, an owed tick's sample; then ~1500 to the
; ; next guard or tick): while the counter stands below 2800H, the tick due, the timer is rewound
; ; by one period and that tick owed (STICK's own grid), so the counter stands at 2800H or more
; ; and the work cannot run it to its terminal count (TRAP: the monitor's single step)
GCHK:   MVI     C,SKH
GCK0:   IN      0FDH                    ; (GCK0: C the high byte to stay above)
        ANI     3FH
        CMP     C
        RNC
        CALL    GRD
        JMP     GCK0
GRD:    LXI     H,OWED                  ; one more tick owed (STICK takes it without waiting
        INR     M                       ; or rewinding)
TRWP:   LXI     D,SPER-SDT              ; v + one period less the SDT T-states it stood still
; ; TREW: stops the counter at v, restarts it from HL = v + DE (the 8155 takes a new count at START)
TREW:   MVI     A,41H                   ; STOP: the counter holds its value v
        OUT     0F8H
        IN      0FCH
        MOV     L,A
        IN      0FDH
        ANI     3FH
        MOV     H,A
        DAD     D
TRW2:   MOV     A,H
        ORI     80H                     ; mode: single pulse
        OUT     0FDH
        MOV     A,L
        OUT     0FCH
        MVI     A,0C1H                  ; START; port A out, B and C in (the monitor's 01H)
        OUT     0F8H
        RET
; ; WOUT: PSND when the counter reaches CTG - KOUT (exact to 20 T-states: the counter read by TREW,
; ; the rest waited in 20-T-state rounds), at once if that is past
WOUT:   LXI     D,-SDT
        CALL    TREW
        XCHG
        LHLD    CTG
        DAD     D                       ; the T-states left (no carry: past)
        JNC     STOUT
        LXI     D,-20
WO1:    DAD     D
        JC      WO1
        JMP     STOUT
;
; ; SSTOP: a stop point: the output catches up with the target, then DWELL samples at rest
SSTOP:  CALL    STICK
        CALL    WPND                    ; (the last sample's pulse, if it waits)
        LXI     H,0000H                 ; the catching up and the dwell: pulses at the tick
        SHLD    PDN
        LHLD    TPX
        SHLD    SXV
        LHLD    TPY
        SHLD    SYV
        CALL    CHASE
        LDA     POUT
        ANA     A
        JNZ     SSTOP
        MVI     C,DWELL
SST1:   PUSH    B
        CALL    STICK
        LDA     JST                     ; the dwell's spare time: the look-ahead
        ANA     A
        CNZ     RUNJ
        POP     B
        DCR     C
        JNZ     SST1
        RET
;
; ; SCHRD: one chord from CAV to CEV: its set-up (SDESC, or the one made ahead), then samples
; ; until it ends
SCHRD:  CALL    GCHK
        LDA     SRDY                    ; its set-up: made ahead in the chord before (RUNJ
        DCR     A                       ; 5-9: SRDY 1), else here, from A, E, P as the flows
        JZ      SCH0                    ; left them
        LXI     H,CAV
        LXI     D,JAV
        MVI     C,14H
        CALL    COPYN
        CALL    SDESC
SCH0:   XRA     A                       ; then copied in: a join costs a copy, not a set-up
        STA     SRDY
        LXI     H,CMU+NOF
        LXI     D,CMU
        MVI     C,16H
        CALL    COPYN
        XRA     A
        STA     CSEG
        STA     DSOK
        STA     DNF
        STA     QOK                     ; C_x changed: its products to make again
SCH1:   CALL    SSAMP
        LDA     DNF
        ANA     A
        RNZ
        LDA     JST                     ; a job's stage in the sample's spare time (a stage takes
        ANA     A                       ; at most about 4000 T-states): while the counter stands
        JZ      SCH1                    ; above 3100H (it then ends within 1.7 ms of the next
        IN      0FDH                    ; tick); in every other sample when the next pulse goes
        ANI     3FH                     ; late in its sample or the chord has fewer than JFW steps
        CPI     SKJ
        JNC     SCH2
        CPI     20H                     ; (never nearer the terminal count than 2000H)
        JC      SCH1
        LDA     PDN+1                   ; (a late pulse: the next sample's work comes before it,
        CPI     JPH                     ; so the stage delays it little)
        JNC     SCH3
        LHLD    KST+2
        XCHG
        LHLD    CNV
        MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        JNZ     SCH1
        MOV     A,L
        CPI     JFW
        JNC     SCH1
SCH3:   LXI     H,JALT                  ; (every other sample: the one after a stage catches up)
        MOV     A,M
        XRI     01H
        MOV     M,A
        JZ      SCH1
SCH2:   CALL    RUNJ
        JMP     SCH1
;
; ; SSAMP: one sample (the tick, the ramp, eqs. 4-6, POUT for the next tick)
SSAMP:  CALL    STICK
        LHLD    KST+2                   ; a pulse early in the sample goes first, a late one
        XCHG                            ; after the sample's work (up to 3300 T-states,
        LHLD    CNV                     ; docs/results.md); in the chord's last sample right
        DCX     H                       ; after its work (the next chord's set-up follows:
        DCX     H
        MOV     A,L                     ; up to 11000 T-states before the next tick, the
        SUB     E                       ; timer's terminal count 16384 after the last)
        MOV     A,H
        SBB     D
        JC      SSL
        LDA     CTG+1
        CPI     SPLH
        CC      WPND
SSL:    CALL    SSMP
        LDA     DNF
        ANA     A
        JZ      WPND
        DCR     A
        STA     CTG+1
WPND:   LDA     PEND
        ANA     A
        RZ
        JMP     WOUT
SSMP:   LDA     SFL
        RRC
        JNC     SS3
        LXI     D,DST                   ; decelerate when LREM <= DST
        LXI     H,LREM
        MVI     B,04H
        ANA     A
SS1:    LDAX    D
        SBB     M
        INX     D
        INX     H
        DCR     B
        JNZ     SS1
        ANA     A
        JM      SACC
        LDA     JLV                     ; decelerate: DST -= f, one level down
        ANA     A
        JZ      SS3
        DCR     A
        STA     JLV
        CALL    DSTSUB
        LXI     H,SUB4                  ; F_LV C_x -= A_F C_x
        CALL    QLV
        LHLD    FLV
        LXI     D,-AFS
        DAD     D
        SHLD    FLV
        ANA     A
        CALL    SLVL1
        JMP     SS3
SACC:   LHLD    FCU                     ; accelerate while f < F_s: one level up, DST += f
        XCHG
        LHLD    FSV
        MOV     A,E
        SUB     L
        MOV     A,D
        SBB     H
        JNC     SS3
        LDA     JLV
        INR     A
        STA     JLV
        LXI     H,ADD4                  ; F_LV C_x += A_F C_x
        CALL    QLV
        LHLD    FLV
        LXI     D,AFS
        DAD     D
        SHLD    FLV
        CALL    SLVL1
        LHLD    FCU
        XCHG
        LXI     H,DST
        CALL    ADD16
        JMP     SS3
; ; f = min(F_s, FLV), HL = FLV (beyond FFFFH only at the top level: CY from its DAD)
SLVL1:  JC      SLV2
        XCHG
        LHLD    FSV
        MOV     A,E
        SUB     L
        MOV     A,D
        SBB     H
        JNC     SLV2
        XCHG
        SHLD    FCU
        JMP     SLV3
SLV2:   LHLD    FSV
        SHLD    FCU
SLV3:   XRA     A
        STA     DSOK
        RET
; ; QLV: QV +- DAV (HL: ADD4 or SUB4), while QOK
QLV:    LDA     QOK
        ANA     A
        RZ
        DCR     A                       ; A_F C_x at the first level change (not in the sample
        JNZ     QLV1                    ; that makes F_LV C_x: one product a sample at most)
        PUSH    H
        LXI     B,AFS
        CALL    MULCX
        SHLD    DAV+2
        XCHG
        SHLD    DAV
        MVI     A,02H
        STA     QOK
        POP     H
QLV1:   PUSH    H                       ; RET goes to it, and it returns to QLV's caller
        LXI     H,DAV
        LXI     D,QV
        RET
DSTSUB: LHLD    FCU
        XCHG
        LXI     H,DST
        MOV     A,M
        SUB     E
        MOV     M,A
        INX     H
        MOV     A,M
        SBB     D
        MOV     M,A
        INX     H
        MOV     A,M
        SBI     00H
        MOV     M,A
        INX     H
        MOV     A,M
        SBI     00H
        MOV     M,A
        RET
; ; ADD16: the 32 bits at HL += DE (unsigned)
ADD16:  MOV     A,M
        ADD     E
        MOV     M,A
        INX     H
        MOV     A,M
        ADC     D
        MOV     M,A
        INX     H
        MOV     A,M
        ACI     00H
        MOV     M,A
        INX     H
        MOV     A,M
        ACI     00H
        MOV     M,A
        RET
SS3:    LHLD    FCU                     ; L_rem -= f
        XCHG
        LXI     H,LREM
        MOV     A,M
        SUB     E
        MOV     M,A
        INX     H
        MOV     A,M
        SBB     D
        MOV     M,A
        INX     H
        MOV     A,M
        SBI     00H
        MOV     M,A
        INX     H
        MOV     A,M
        SBI     00H
        MOV     M,A
        LDA     DSOK                    ; dS_x = (f C_x) >> 16, when f or the chord changed:
        ANA     A                       ; at F_s its product, once a chord; below, the level's
        JNZ     SS4                     ; F_LV C_x, one product a chord, then A_F C_x added or
        INR     A                       ; taken away at each level (one multiplication a sample
        STA     DSOK                    ; would leave no time to place the pulse)
        LHLD    FCU
        XCHG
        LHLD    FSV
        MOV     A,L
        CMP     E
        JNZ     SQ1
        MOV     A,H
        CMP     D
        JNZ     SQ1
        MOV     B,H
        MOV     C,L
        CALL    MULCX
        JMP     SQ3
SQ1:    LDA     QOK
        ANA     A
        JNZ     SQ2
        INR     A
        STA     QOK
        LHLD    FLV
        MOV     B,H
        MOV     C,L
        CALL    MULCX
        SHLD    QV+2
        XCHG
        SHLD    QV
SQ2:    LHLD    QV+2
SQ3:    SHLD    DSV
SS4:    LHLD    DSV                     ; eq. 4: k* += dS_x
        XCHG
        LXI     H,KST
        CALL    ADD16                   ; (DE: dS_x still)
        LHLD    KST                     ; x* crossed a step (the fraction r < dS_x): PDN =
        MOV     A,L                     ; 24 (255 - floor(256 r / dS_x)), where it did in the
        SUB     E                       ; sample (eight bits of r / dS_x, restoring); else 0
        MOV     A,H
        SBB     D
        LXI     B,0800H
        MVI     A,0FFH
        JNC     PD4
PD1:    DAD     H
        JC      PD2
        MOV     A,L
        SUB     E
        MOV     A,H
        SBB     D
        JC      PD3
PD2:    MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     H,A
        ORA     A
PD3:    CMC
        MOV     A,C
        RAL
        MOV     C,A
        DCR     B
        JNZ     PD1
PD4:    CMA
        MOV     L,A
        MVI     H,00H
        MOV     D,H
        MOV     E,L
        DAD     H
        DAD     D
        DAD     H
        DAD     H
        DAD     H
        SHLD    PDN
        XRA     A
        STA     DNF
        LHLD    CNV                     ; k = min(n, floor k*)
        XCHG
        LHLD    KST+2
        MOV     A,L
        SUB     E
        MOV     C,A
        MOV     A,H
        SBB     D
        JC      SS5
        MOV     H,A                     ; reached: k* -= n (the rest carries on), k = n
        MOV     L,C
        SHLD    KST+2
        XCHG
        MVI     A,01H
        STA     DNF
SS5:    CALL    TGT
        SHLD    SXV
        XCHG
        SHLD    SYV
        CALL    CHASE
        LDA     DNF
        ANA     A
        RZ
        LHLD    SXV                     ; the chord's end: the next one starts from this target
        SHLD    TPX
        LHLD    SYV
        SHLD    TPY
        RET
;
; ; TGT: HL = x, DE = y, the chord's target at step k = HL (eq. 5; k in the segment CSEG)
TGT:    PUSH    H                       ; k
        MOV     A,L                     ; i = k >> 7: a new segment adds Y_d* (eq. 3's Y_i*)
        RAL
        MOV     A,H
        RAL
        LXI     H,CSEG
        CMP     M
        JZ      SS6
        MOV     M,A
        LXI     H,CYD
        LXI     D,CYI
        JC      TGB                     ; back one: JAP's TGT at k = n went ahead into n >> 7
        CALL    ADD4
SS6:    POP     H
        PUSH    H
        MOV     A,L                     ; x_r = k & 127; C:HL = T_y x_r (eq. 5)
        ANI     7FH
        ADD     A
        ORI     01H
        MOV     B,A
        LHLD    CTY
        XCHG
        LXI     H,0000H
        MVI     C,00H
SM1:    MOV     A,B
        CPI     80H
        JZ      SM3
        DAD     H
        MOV     A,C
        RAL
        MOV     C,A
        MOV     A,B
        ADD     A
        MOV     B,A
        JNC     SM1
        DAD     D
        MOV     A,C
        ACI     00H
        MOV     C,A
        JMP     SM1
SM3:    XCHG                            ; + frac(Y_i*) + 1/2 = + y0* (eq. 3)
        LHLD    CYI
        DAD     D
        MOV     A,C
        ACI     00H
        MOV     C,A
        MOV     A,H
        ADI     80H
        MOV     A,C
        ACI     00H
        MOV     E,A                     ; w = floor(Y_i*) + the integer part
        MVI     D,00H
        LHLD    CYI+2
        DAD     D
        XCHG                            ; DE = w
        LDA     CSG                     ; target v = P_v +- w
        ANA     A
        JZ      SS7
        XRA     A
        SUB     E
        MOV     E,A
        MVI     A,00H
        SBB     D
        MOV     D,A
SS7:    LHLD    PVV
        DAD     D
        POP     D                       ; k
        PUSH    H                       ; target v
        LDA     CSU                     ; target u = P_u +- k
        ANA     A
        JZ      SS8
        XRA     A
        SUB     E
        MOV     E,A
        MVI     A,00H
        SBB     D
        MOV     D,A
SS8:    LHLD    PUV
        DAD     D
        POP     D                       ; HL = u, DE = v
        LDA     CMU
        ANA     A
        RZ
        XCHG
        RET
TGB:    CALL    SUB4
        JMP     SS6
; ; CHASE: POUT = one pulse per axis toward SXV, SYV where the output is not there (eq. 6)
CHASE:  MVI     B,00H
        LHLD    OUTX
        XCHG
        LHLD    SXV
        MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     C,A
        ORA     L
        JZ      CH2
        MOV     A,C
        XCHG
        RAL                             ; CY: the target is below
        JC      CH1
        INX     H
        MVI     B,03H                   ; X pulse, X +
        JMP     CH1A
CH1:    DCX     H
        MVI     B,01H                   ; X pulse, X -
CH1A:   SHLD    OUTX
CH2:    LHLD    OUTY
        XCHG
        LHLD    SYV
        MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     C,A
        ORA     L
        JZ      CH4
        MOV     A,C
        XCHG
        RAL
        JC      CH3
        INX     H
        MOV     A,B
        ORI     0CH                     ; Y pulse, Y +
        MOV     B,A
        JMP     CH3A
CH3:    DCX     H
        MOV     A,B
        ORI     04H                     ; Y pulse, Y -
        MOV     B,A
CH3A:   SHLD    OUTY
CH4:    MOV     A,B
        STA     POUT
        RET
;
; ; SDESC: a chord's set-up at its first point (section 2.1-2.2): u, n, T_y, Y_d*, sigma, Y0*, from
; ; JAV, JEV, JPX, JPY into CMU + NOF ... PVV + NOF; in three parts, SDA, SDB, SDC (RUNJ 6-8)
SDESC:  CALL    SDA                     ; (at the join; ahead of it, stages 6-8 of RUNJ)
        CALL    SDB
        MVI     C,GTC                   ; SDC, C_x, the copy and STICK: up to ~5500
        CALL    GCK0
SDC:    LXI     H,0000H                 ; off = su (P_u . 0 - A_u)
        SHLD    OF2
        LHLD    PUV+NOF
        SHLD    OF2+2
        CALL    PTRU
        LXI     D,JAV
        DAD     D
        LXI     D,OF2
        CALL    SUB4
        LDA     CSU+NOF
        ANA     A
        JZ      SO1
        LXI     H,OF2
        CALL    NEG4
SO1:    LXI     H,OF2                   ; T_y |off| >> 16 = T_y . int + (T_y . frac) >> 16
        CALL    ABS4
        STA     DVS                     ; (the sign of off, for a moment)
        LHLD    CTY+NOF
        MOV     B,H
        MOV     C,L
        LHLD    OF2
        XCHG
        CALL    MUL32
        SHLD    OFV
        LXI     H,0000H
        SHLD    OFV+2
        LDA     OF2+2
        ANA     A
        JZ      SO3
SO2:    PUSH    PSW
        LHLD    CTY+NOF
        XCHG
        LXI     H,OFV
        CALL    ADD16
        POP     PSW
        DCR     A
        JNZ     SO2
SO3:    CALL    PTRU                    ; Y0* = sigma (A_v - P_v . 0) +- T_y |off| (eq. 13)
        MOV     A,L
        XRI     04H
        MOV     L,A
        LXI     D,JAV
        DAD     D
        LXI     D,CYI+NOF
        MVI     C,04H
        CALL    COPYN
        LXI     H,0000H
        SHLD    OF2
        LHLD    PVV+NOF
        SHLD    OF2+2
        LXI     H,OF2
        LXI     D,CYI+NOF
        CALL    SUB4
        LDA     CSG+NOF
        ANA     A
        JZ      SY1
        LXI     H,CYI+NOF
        CALL    NEG4
SY1:    LXI     H,OFV
        LXI     D,CYI+NOF
        LDA     DVS
        ANA     A
        JNZ     SY2
        CALL    ADD4
        JMP     SY3
SY2:    CALL    SUB4
SY3:    IN      0FDH                    ; a set-up at a join that ran almost to the timer's
        ANI     3FH                     ; terminal count (the counter below 0200H, 2.6
        CPI     02H                     ; periods after the last tick): the timer rewound by
        CC      GRD                     ; one before the count would trap, the tick owed
        LDA     CTY+NOF+1                   ; C_x from the table, by T_y's top 4 bits
        RRC
        RRC
        RRC
        ANI     1EH
        MOV     E,A
        MVI     D,00H
        LXI     H,CXTAB
        DAD     D
        MOV     E,M
        INX     H
        MOV     D,M
        XCHG
        SHLD    CCX+NOF
        RET
; ; SDA: dx, dy, u, P, n and their signs (the set-up's first stage)
SDA:    LXI     H,JEV                   ; UUV = dx, VVV = dy, 16.16 (UUV, VVV as JEV's x, y)
        LXI     D,UUV
        MVI     C,08H
        CALL    COPYN
        LXI     H,JAV
        LXI     D,UUV
        CALL    SUB4
        CALL    SUB4                    ; (HL = JAV + 4, DE = VVV)
        LXI     H,UUV
        CALL    ABS4
        STA     DUS
        LXI     H,VVV
        CALL    ABS4
        STA     DVS
        LXI     D,UUV                   ; |dx| >= |dy|: u = x
        LXI     H,VVV
        MVI     B,04H
        ANA     A
SD1:    LDAX    D
        SBB     M
        INX     D
        INX     H
        DCR     B
        JNZ     SD1
        MVI     A,00H
        JNC     SD2
        LXI     H,UUV                   ; else u = y: swap
        LXI     D,VVV
        MVI     C,04H
SW1:    MOV     B,M
        LDAX    D
        MOV     M,A
        MOV     A,B
        STAX    D
        INX     H
        INX     D
        DCR     C
        JNZ     SW1
        LDA     DUS
        MOV     B,A
        LDA     DVS
        STA     DUS
        MOV     A,B
        STA     DVS
        MVI     A,01H
SD2:    STA     CMU+NOF
        ANA     A                       ; P_u, P_v
        LHLD    JPX
        XCHG
        LHLD    JPY
        JZ      SD3
        XCHG
SD3:    SHLD    PVV+NOF
        XCHG
        SHLD    PUV+NOF
        CALL    PTRU                    ; round(E_u): the high word of E_u + 8000H
        LXI     D,JEV
        DAD     D
        MOV     A,M
        INX     H
        MOV     A,M
        ADI     80H
        INX     H
        MOV     C,M
        INX     H
        MOV     B,M
        JNC     SD3A
        INX     B
SD3A:   LHLD    PUV+NOF                     ; n = |round(E_u) - P_u|, su its sign
        XCHG
        MOV     A,C
        SUB     E
        MOV     L,A
        MOV     A,B
        SBB     D
        MOV     H,A
        ANA     A
        MVI     A,00H
        JP      SD4
        CALL    NEGHL
        MVI     A,01H
SD4:    STA     CSU+NOF
        SHLD    CNV+NOF
        LXI     H,VVV                   ; sigma: + if dv = 0, else sgn(dv) sgn(du) su
        MOV     A,M
        INX     H
        ORA     M
        INX     H
        ORA     M
        INX     H
        ORA     M
        JZ      SD5
        LDA     DUS
        MOV     B,A
        LDA     DVS
        XRA     B
        MOV     B,A
        LDA     CSU+NOF
        XRA     B
SD5:    STA     CSG+NOF
        LHLD    UUV                     ; U, V below 2^15: whole steps from the high words
        MOV     A,H
        ORA     L
        RNZ
        LHLD    VVV
        MOV     A,H
        ORA     L
        RNZ
        LHLD    UUV+2
        SHLD    UUV
        LHLD    VVV+2
        SHLD    VVV
        LXI     H,0000H
        SHLD    UUV+2
        SHLD    VVV+2
        RET
; ; SDB: T_y, Y_d* (the set-up's second stage)
SDB:
SN2:    LDA     UUV+3                   ; else both shifted right: in registers while U < 2^24
        ANA     A
        JZ      SN5
        LXI     H,UUV+3
        CALL    SHR4
        LXI     H,VVV+3
        CALL    SHR4
        JMP     SN2
SN5:    LHLD    VVV+1                   ; V = C:D:E, U = B:H:L
        MOV     C,H
        MOV     D,L
        LDA     VVV
        MOV     E,A
        LHLD    UUV+1
        MOV     B,H
        MOV     H,L
        LDA     UUV
        MOV     L,A
SN6:    MOV     A,B
        ORA     A
        JNZ     SN7
        MOV     A,H
        ORA     A
        JP      SN4
SN7:    ORA     A
        MOV     A,B
        RAR
        MOV     B,A
        MOV     A,H
        RAR
        MOV     H,A
        MOV     A,L
        RAR
        MOV     L,A
        ORA     A
        MOV     A,C
        RAR
        MOV     C,A
        MOV     A,D
        RAR
        MOV     D,A
        MOV     A,E
        RAR
        MOV     E,A
        JMP     SN6
SN4:    MOV     A,H                     ; U = HL, V = DE, below 2^15
        ORA     L
        JZ      SQZ
        MOV     A,L
        CMP     E
        JNZ     SDV
        MOV     A,H
        CMP     D
        JZ      SQE
SDV:    CALL    NEGHL                   ; Q = floor(2^24 V / U): DE = -U, HL = V, the
        XCHG                            ; remainder; 16 quotient bits, then 8 (SDVL)
        LXI     B,0001H
        CALL    SDVL
        PUSH    B
        LXI     B,0100H
        CALL    SDVL
        POP     H
        MOV     A,C
        STA     OFV
        SHLD    OFV+1
        XRA     A
        STA     OFV+3
        JMP     SQD
; ; SDVL: restoring division steps until the 1 put below BC's quotient bits leaves B's top: HL =
; ; 2 HL - U (DAD D, DE = -U: CY when 2 HL >= U, the quotient bit; 2 HL < 2^16 as HL < U < 2^15),
; ; else HL = 2 HL (the -U taken back, CY 0)
SDVL:   DAD     H
        DAD     D
        JC      SDV2
        MOV     A,L
        SUB     E
        MOV     L,A
        MOV     A,H
        SBB     D
        MOV     H,A
SDV2:   MOV     A,C
        RAL
        MOV     C,A
        MOV     A,B
        RAL
        MOV     B,A
        JNC     SDVL
        RET
SQZ:    LXI     H,0000H                 ; U = 0 (A = E): Q = 0
        SHLD    OFV
        SHLD    OFV+2
        JMP     SQD
SQE:    LXI     H,0000H                 ; V = U: Q = 2^24
        SHLD    OFV
        LXI     H,0100H
        SHLD    OFV+2
SQD:    LHLD    OFV                     ; T_y = min(FFFFH, (Q + 80H) >> 8)
        LXI     D,0080H
        DAD     D
        MOV     E,H
        LDA     OFV+2
        ACI     00H
        MOV     D,A
        LDA     OFV+3
        ACI     00H
        XCHG
        JZ      SQT
        LXI     H,0FFFFH
SQT:    SHLD    CTY+NOF
        LXI     H,OFV                   ; Y_d* = (Q + 1) >> 1
        LXI     D,CYD+NOF
        MVI     C,04H
        CALL    COPYN
        LXI     H,CYD+NOF
        MVI     B,04H
YI1:    INR     M
        JNZ     YI2
        INX     H
        DCR     B
        JNZ     YI1
YI2:    LXI     H,CYD+NOF+3
        JMP     SHR4
; ; PTRU: HL = 4 CMU+NOF (the u coordinate's offset in JAV, JEV)
PTRU:   LDA     CMU+NOF
        ADD     A
        ADD     A
        MOV     L,A
        MVI     H,00H
        RET
; ; NEGHL: HL = -HL
NEGHL:  XRA     A
        SUB     L
        MOV     L,A
        MVI     A,00H
        SBB     H
        MOV     H,A
        RET
; ; ADD4, SUB4: the 32 bits at DE += / -= those at HL
ADD4:   MVI     B,04H
        ANA     A
AD41:   LDAX    D
        ADC     M
        STAX    D
        INX     D
        INX     H
        DCR     B
        JNZ     AD41
        RET
SUB4:   MVI     B,04H
        ANA     A
SB41:   LDAX    D
        SBB     M
        STAX    D
        INX     D
        INX     H
        DCR     B
        JNZ     SB41
        RET
; ; NEG4: the 32 bits at HL negated; ABS4: made positive, A = 1 if they were negative
NEG4:   MVI     B,04H
        ANA     A
NG41:   MVI     A,00H
        SBB     M
        MOV     M,A
        INX     H
        DCR     B
        JNZ     NG41
        RET
ABS4:   PUSH    H
        INX     H
        INX     H
        INX     H
        MOV     A,M
        POP     H
        ANA     A
        MVI     A,00H
        RP
        CALL    NEG4
        MVI     A,01H
        RET
; ; SHR4: the 32 bits ending at HL (the top byte) shifted right, unsigned
SHR4:   MVI     B,04H
        ANA     A
SR41:   MOV     A,M
        RAR
        MOV     M,A
        DCX     H
        DCR     B
        JNZ     SR41
        RET
; ; MUL32: HL:DE = BC x DE, unsigned: 16 steps shifting right, the product's low bits into DE as
; ; the multiplier's leave it
MULCX:  LHLD    CCX                     ; HL:DE = BC x C_x
        XCHG
MUL32:  LXI     H,0000H
        MVI     A,11H                   ; a first round shifts DE only: CY = its bit 0
        STA     MCNT
        ORA     A
        JMP     MU3
MU1:    JNC     MU2
        DAD     B
MU2:    MOV     A,H
        RAR
        MOV     H,A
        MOV     A,L
        RAR
        MOV     L,A
MU3:    MOV     A,D
        RAR
        MOV     D,A
        MOV     A,E
        RAR
        MOV     E,A
        LDA     MCNT                    ; (LDA, DCR, STA leave CY)
        DCR     A
        STA     MCNT
        JNZ     MU1
        RET
; ; C_x = 1 / sqrt(1 + T^2) at the middle of each 1/16 of T_y (0.16): eq. 4's dS_x = C_x f
CXTAB:  DW      0FFE0H,0FEE2H,0FCEEH,0FA16H,0F670H,0F219H,0ED2DH,0E7CCH
        DW      0E214H,0DC1FH,0D607H,0CFE0H,0C9BCH,0C3A9H,0BDB1H,0B7DFH
;
MEND    EQU     $
        IF      $ GT 3DD0H
        ERROR   "the master program does not fit 3000H-3DCFH"
        ENDIF
        END
