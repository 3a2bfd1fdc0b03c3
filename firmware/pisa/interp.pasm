; INTERP: two-axis linear and circular interpolation with speed control for the Pisa
; multi-purpose interpolator (CNR-IEI, 1969). The paper's own program (its ref. [7]) is not
; in the sources; this one is written for the machine as reconstructed in docs/pisa.md.
;
; Method (docs/pisa.md "The program"):
;   - every 6 ms (indicator CLK) the point computed in the previous period goes to the X and Y
;     converters (OUT 1 and OUT 2), then the next point is computed;
;   - the path is followed in 1 um unit steps, one axis at a time, by the sign of an estimating
;     function: lines D = 2(px B - py A) + B - A, arcs FC = x^2 + y^2 - R^2 (centre-relative,
;     R from the start point, so FC starts at 0); every point stays within 1 um of the element;
;   - speed: in each period the steps go on until the chord from the last output point reaches
;     F - 5 tenths of a um (Q >= QT = ceil((F-5)^2/100) um^2): 6 ms at F mm/min is F tenths of
;     a um; the chord is then within +-0.5 um of it;
;   - an element ends on its exact end point, which is that period's output; arcs end by a
;     short line once within 4 um (|dX|+|dY|) of the end point;
;   - the tape is read word by word (one word a period at most) into the next block's words
;     while the current element runs; at the end of a block its QT and near window are worked
;     out (MUL), and the reader waits until the element ahead has started.
; Only add, subtract, shifts, ABS, sign and zero tests: no multiply in the interpolation.

; ---- RWM words (64): constants, the element, the next block, scratch
SGN     EQU 0           ; ADS's fixed sign location (unused here)
ZERO    EQU 1
ONE     EQU 2
FOUR    EQU 3
FIVE    EQU 54
MEG     EQU 4           ; 1 000 000
K99     EQU 5
RAPID   EQU 6           ; G00 feedrate, 1500 mm/min
X       EQU 7           ; position (um from program zero) on lines
Y       EQU 8
XT      EQU 9           ; the element's end point
YT      EQU 10
RX      EQU 11          ; arcs: position relative to the centre
RY      EQU 12
XC      EQU 13          ; arcs: centre
YC      EQU 14
XE      EQU 15          ; arcs: end point relative to the centre
YE      EQU 16
FC      EQU 17          ; arcs: x^2 + y^2 - R^2
D       EQU 18          ; lines: decision variable
A2      EQU 19          ; lines: 2|dX|
B2      EQU 20          ; lines: 2|dY|
SX      EQU 21          ; lines: sign of dX (0 or -1)
SY      EQU 22
N       EQU 23          ; lines: unit steps left
QT      EQU 24          ; chord threshold (um^2)
NL      EQU 25          ; arcs: near-end window (um, |dX|+|dY|)
Q       EQU 26          ; chord^2 from the last output point
U       EQU 27          ; x - x(last output)
V       EQU 28
M       EQU 29          ; |dX| + |dY| to the end point
OX      EQU 30          ; the next output
OY      EQU 31
G       EQU 32          ; the element's G
NG      EQU 33          ; the next block: G X Y I J F (modal but I J)
NX      EQU 34
NY      EQU 35
NI      EQU 36
NJ      EQU 37
NF      EQU 38
NQT     EQU 39          ; the next block's QT and NL
NNL     EQU 40
T       EQU 41
T1      EQU 42
T2      EQU 43
LC      EQU 44          ; tape word: letter code
W       EQU 45          ; tape word as read
VAL     EQU 46          ; its value
MA      EQU 47          ; MUL: P = MA x MB
MB      EQU 48
P       EQU 49
MT      EQU 50
MD      EQU 51
RET     EQU 52          ; MUL's return address
LRET    EQU 53          ; LSET's return address

; ---- indicators
CLK     EQU 0           ; 6 ms time base
RDR     EQU 1           ; reader buffer full
RUN     EQU 2           ; reader start
EOT     EQU 3           ; end of tape
ENDL    EQU 5           ; end lamp: the run stops
ACT     EQU 8           ; an element is running
NXT     EQU 9           ; the next block is complete
CIRC    EQU 10          ; the element is an arc
CW      EQU 11          ; clockwise
ARM     EQU 12          ; the arc has left its start (its end may be sought)
NEAR    EQU 13          ; the end is within NL
MOVED   EQU 14          ; motion has started
LATE    EQU 15          ; a period's work overran 6 ms
STALL   EQU 16          ; an element ended before the next block was read

        ORG 0
INIT:   STO 1,ONE
        STO 4,FOUR
        STO 5,FIVE
        STO 1,MEG
        SHL MEG,6,MEG
        STO 99,K99
        STO 150,RAPID
        SHL RAPID,1,RAPID
        SET CLK                 ; start the time base
        SET RUN                 ; read the first word
WAIT:   TRS TICK,CLK
        JMP WAIT

; ---- every 6 ms
TICK:   RST CLK
        OUT 1,8,OX
        OUT 2,8,OY
        STO 0,Q
        STO 0,U
        STO 0,V
        TRS STEP,ACT
        TRS START,NXT
        TRS FINIS,EOT           ; nothing left: the last point has gone out
        TRS STALLD,MOVED
        JMP TAPE
STALLD: SET STALL
        JMP TAPE
FINIS:  SET ENDL
        JMP WAIT

; ---- the next block becomes the element
START:  MOV NG,G
        MOV NX,XT
        MOV NY,YT
        MOV NQT,QT
        MOV NNL,NL
        RST NXT
        SET RUN                 ; read the block after it meanwhile
        SUB ONE,G,T             ; G - 1
        TPL ST1,T
        JMP STLIN               ; G00
ST1:    TZE STLIN,T             ; G01
        SUB ONE,T,T
        TZE SCW,T               ; G02
        RST CW                  ; G03
        JMP SARC
SCW:    SET CW
SARC:   SET CIRC
        ADD X,NI,XC
        ADD Y,NJ,YC
        SUB NI,ZERO,RX          ; start relative to the centre: -I, -J
        SUB NJ,ZERO,RY
        STO 0,FC
        SUB XC,XT,XE
        SUB YC,YT,YE
        RST NEAR
        SUB RX,XE,T1            ; armed when the start lies outside the near window
        ABS T1,T1
        SUB RY,YE,T2
        ABS T2,T2
        ADD T1,T2,M
        SUB M,NL,T              ; NL - M
        SET ARM
        TPL SA1,T
        JMP SGO
SA1:    RST ARM                 ; a full circle: armed once it has left
        JMP SGO
STLIN:  STO #SGO,LRET
        JMP LSET
SGO:    STO 0,NI
        STO 0,NJ
        SET MOVED               ; (a block with no move has not started the motion)
        SET ACT
STEP:   TRS CSTART,CIRC
        JMP LSTEP

; ---- line set-up from X Y to XT YT (returns through LRET; a zero length ends the element)
LSET:   RST CIRC
        STO 0,SX
        SUB X,XT,T
        TPL LS1,T
        SUB ONE,ZERO,SX
LS1:    ABS T,T1                ; A = |dX|
        ADD T1,T1,A2
        STO 0,SY
        SUB Y,YT,T
        TPL LS2,T
        SUB ONE,ZERO,SY
LS2:    ABS T,T2                ; B = |dY|
        ADD T2,T2,B2
        SUB T1,T2,D             ; D = B - A
        ADD T1,T2,N             ; A + B unit steps
        TZE ELEND,N
        JMI LRET

; ---- line: one unit step
LSTEP:  TPL LY,D
        ADD B2,D,D              ; an X step
        TPL LXP,SX
        SUB ONE,X,X
        SUB U,Q,Q               ; Q += -2U + 1
        SUB ONE,U,U
        SUB U,Q,Q
        JMP LTAIL
LXP:    ADD ONE,X,X
        ADD U,Q,Q               ; Q += 2U + 1
        ADD ONE,U,U
        ADD U,Q,Q
        JMP LTAIL
LY:     SUB A2,D,D              ; a Y step
        TPL LYP,SY
        SUB ONE,Y,Y
        SUB V,Q,Q
        SUB ONE,V,V
        SUB V,Q,Q
        JMP LTAIL
LYP:    ADD ONE,Y,Y
        ADD V,Q,Q
        ADD ONE,V,V
        ADD V,Q,Q
LTAIL:  SUB ONE,N,N
        TZE ELEND,N
        SUB QT,Q,T              ; Q - QT
        TPL TDONE,T
        JMP LSTEP

; ---- arc: once a period, the end's distance
CSTART: SUB RX,XE,T1
        ABS T1,T1
        SUB RY,YE,T2
        ABS T2,T2
        ADD T1,T2,M
        SUB M,NL,T              ; NL - M
        TRS CSA,ARM
        TPL CSTEP,T
        SET ARM                 ; it has left the start
        JMP CSTEP
CSA:    TPL CSN,T
        JMP CSTEP
CSN:    SET NEAR

; ---- arc: one unit step, by quadrant, direction and the sign of FC
CSTEP:  TRS CWS,CW
        TPL CC1,RX
        TPL CC2,RY
        TPL XP,FC               ; CCW, x<0 y<0: FC>=0 x+1, else y-1
        JMP YM
CC2:    TPL YM,FC               ; CCW, x<0 y>=0: FC>=0 y-1, else x-1
        JMP XM
CC1:    TPL CCQ1,RY
        TPL YP,FC               ; CCW, x>=0 y<0: FC>=0 y+1, else x+1
        JMP XP
CCQ1:   TPL XM,FC               ; CCW, x>=0 y>=0: FC>=0 x-1, else y+1
        JMP YP
CWS:    TPL CW1,RX
        TPL CW2,RY
        TPL YP,FC               ; CW, x<0 y<0: FC>=0 y+1, else x-1
        JMP XM
CW2:    TPL XP,FC               ; CW, x<0 y>=0: FC>=0 x+1, else y+1
        JMP YP
CW1:    TPL CWQ1,RY
        TPL XM,FC               ; CW, x>=0 y<0: FC>=0 x-1, else y-1
        JMP YM
CWQ1:   TPL YM,FC               ; CW, x>=0 y>=0: FC>=0 y-1, else x+1
        JMP XP

XP:     ADD RX,FC,FC            ; FC += 2x + 1
        ADD ONE,RX,RX
        ADD RX,FC,FC
        ADD U,Q,Q
        ADD ONE,U,U
        ADD U,Q,Q
        JMP CTAIL
XM:     SUB RX,FC,FC            ; FC += -2x + 1
        SUB ONE,RX,RX
        SUB RX,FC,FC
        SUB U,Q,Q
        SUB ONE,U,U
        SUB U,Q,Q
        JMP CTAIL
YP:     ADD RY,FC,FC
        ADD ONE,RY,RY
        ADD RY,FC,FC
        ADD V,Q,Q
        ADD ONE,V,V
        ADD V,Q,Q
        JMP CTAIL
YM:     SUB RY,FC,FC
        SUB ONE,RY,RY
        SUB RY,FC,FC
        SUB V,Q,Q
        SUB ONE,V,V
        SUB V,Q,Q
CTAIL:  TRS CNEAR,NEAR
CT2:    SUB QT,Q,T
        TPL TDONE,T
        JMP CSTEP
CNEAR:  SUB RX,XE,T1
        ABS T1,T1
        SUB RY,YE,T2
        ABS T2,T2
        ADD T1,T2,M
        SUB FIVE,M,T            ; M - 5
        TPL CT2,T
        ADD XC,RX,X             ; within 4 um: a line to the end point
        ADD YC,RY,Y
        STO #LSTEP,LRET
        JMP LSET

; ---- the end of an element, the period's output point
ELEND:  RST ACT
        RST CIRC
        MOV XT,X
        MOV YT,Y
TDONE:  TRS TDC,CIRC
        MOV X,OX
        MOV Y,OY
        JMP TAPE
TDC:    ADD XC,RX,OX
        ADD YC,RY,OY

; ---- one tape word, if the reader has one
TAPE:   TRS RDW,RDR
        JMP TEND
RDW:    IN 0,1,LC               ; the letter's code
        IN 0,8,W
        RST RDR
        SHR W,1,VAL             ; sign digit and six digits
        TPL RD1,VAL
        ADD MEG,VAL,VAL         ; 99vvvvvv + 1 000 000 = vvvvvv
        SUB VAL,ZERO,VAL        ; negated
RD1:    SUB ONE,LC,T
        TZE RNEXT,T             ; N: not used
        SUB ONE,T,T
        TZE RG,T
        SUB ONE,T,T
        TZE RXW,T
        SUB ONE,T,T
        TZE RYW,T
        SUB ONE,T,T
        TZE RIW,T
        SUB ONE,T,T
        TZE RJW,T
        SUB ONE,T,T
        TZE RFW,T
        JMP REOB                ; 8: end of block
RG:     MOV VAL,NG
        JMP RNEXT
RXW:    MOV VAL,NX
        JMP RNEXT
RYW:    MOV VAL,NY
        JMP RNEXT
RIW:    MOV VAL,NI
        JMP RNEXT
RJW:    MOV VAL,NJ
        JMP RNEXT
RFW:    MOV VAL,NF
RNEXT:  SET RUN
        JMP TEND
REOB:   MOV NF,MA               ; the block's feedrate (G00: RAPID)
        TZE REOB1,NG
        JMP REOB2
REOB1:  MOV RAPID,MA
REOB2:  SHR MA,1,T              ; NL = 2 (F/10 + 1) + 4
        ADD ONE,T,T
        ADD T,T,T
        ADD FOUR,T,NNL
        SUB FIVE,MA,MA          ; QT = ceil((F - 5)^2 / 100)
        MOV MA,MB
        STO #REOB3,RET
        JMP MUL
REOB3:  ADD K99,P,P
        SHR P,2,NQT
        SET NXT                 ; the reader waits until this block has started
TEND:   TRS LATEP,CLK
        JMP WAIT
LATEP:  SET LATE
        JMP TICK

; ---- MUL: P = MA x MB (MB >= 0) by repeated addition, digit by digit; returns through RET
MUL:    STO 0,P
MUL1:   TZE MULX,MB
        SHR MB,1,MT             ; MB / 10
        SHL MT,1,MD
        SUB MD,MB,MD            ; the low digit
MUL2:   TZE MUL3,MD
        ADD MA,P,P
        SUB ONE,MD,MD
        JMP MUL2
MUL3:   MOV MT,MB
        SHL MA,1,MA
        JMP MUL1
MULX:   JMI RET
        END
