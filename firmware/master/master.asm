; ; MASTER PROGRAM (thesis 5.3's recommendation): walks a path table of rapid moves, lines and
; ; arcs and hands each linear segment to the line routine of thesis-fixed (0800H), as MAIN
; ; does: X1 Y1 X2 Y2 at 1B00H..1B09H, DLYK at 1B38H, then PARAM and the YID/OKEY/OUT/INPUT loop.
; ; Arcs: Watanabe and Iwai, IECI '81, eq. 11: the centre angle of a segment is 2^-C_R rad, so each
; ; next end point comes from shifts; the first point is pushed out by eps_A = 2^(-2C_R-4) R.
; ; Runs from the expansion EPROM (3000H, board option `expansion`); tables at 3800H
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
TABLE   EQU     3800H                   ; the path tables (16-byte entries, type 0 ends a path)
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
        LXI     D,0004H
        DAD     D
        MOV     E,M
        INX     H
        MOV     D,M
        INX     H
        XCHG
        SHLD    X2
        XCHG
        MOV     E,M
        INX     H
        MOV     D,M
        XCHG
        SHLD    Y2
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
ARC:    SUI     03H                     ; 0: CW (G02), 1: CCW (G03)
        XRI     01H
        STA     DIR                     ; 0 CCW, 1 CW
        INX     H
        MOV     A,M
        STA     CR
        LXI     D,0009H                 ; +10: CX, CY, N
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
        LHLD    CXV                     ; AX = (XAC - CX) . 0
        XCHG
        LHLD    XAC
        LXI     B,AX
        CALL    START
        LHLD    CYV
        XCHG
        LHLD    YAC
        LXI     B,AY
        CALL    START
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
        IF      $ GT 3800H
        ERROR   "the master program does not fit 3000H-37FFH"
        ENDIF
        END
