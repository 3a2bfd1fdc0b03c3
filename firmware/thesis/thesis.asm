; ==============================================================================================
; thesis.asm -- the ALP 85 machine-tool firmware of Appendix B (I. Guler, METU 1985),
; reconstructed from the OCR of the printed listing (source lines 1-888).
;
; Every statement carries its listing line: "; L123" = printed line 123 (OCR misreadings
; corrected, see RECONSTRUCTION.md); "; L123 NEW" = a line whose text is lost but whose place is
; known; "; NEW" = written for the lost pages 301-500; "; FIX En" = the repair of erratum En,
; assembled only with FIXED=1 (build thesis-fixed). FIXED=0 (build thesis) is the listing as
; printed. RECONSTRUCTION.md gives the evidence for every line, docs/thesis.md the use.
; ==============================================================================================

        IFNDEF  FIXED
FIXED   EQU     0                       ; NEW  0: as printed, 1: errata repaired
        ENDIF

; ---- names for the listing's RAM (the code uses the addresses, as the listing does) ---------
X1      EQU     1B00H                   ; NEW  start X, steps (3-byte slot, 16 bits used)
Y1      EQU     1B03H                   ; NEW  start Y
X2      EQU     1B06H                   ; NEW  end X
Y2      EQU     1B09H                   ; NEW  end Y
FEED    EQU     1B16H                   ; NEW  feedrate as entered, mm/min (reconstruction)
YIDV    EQU     1B30H                   ; NEW  YID, the ideal Y (the label YID is the routine)
YAC     EQU     1B32H                   ; NEW  actual Y, transducer count
XAC     EQU     1B34H                   ; NEW  actual X, transducer count
TPREV   EQU     1B36H                   ; NEW  port B bits 3-0 at the last INPUT1
DLYK    EQU     1B38H                   ; NEW  delay constant: ms (DL passes) per pulse half
OOKEY   EQU     1B3BH                   ; NEW  thesis 4.4.7's flag; the listing's OKEY returns
                                        ;      the Z flag instead and nothing writes this byte
ZKOR    EQU     1B3CH                   ; NEW  Z as entered, steps (reconstruction)
ZAC     EQU     1B3EH                   ; NEW  actual Z, counted by the firmware (open loop)
QUAD    EQU     1B54H                   ; NEW  OUT's quadrant code

; ---- port bits (8155 port A = F9H out, port B = FAH in) -------------------------------------
XPLS    EQU     01H                     ; NEW  port A bit 0: X pulse (rising edge = one step)
XDIR    EQU     02H                     ; NEW  port A bit 1: X direction, 1 = +X
YPLS    EQU     04H                     ; NEW  port A bit 2: Y pulse
YDIR    EQU     08H                     ; NEW  port A bit 3: Y direction, 1 = +Y
ZPLS    EQU     10H                     ; NEW  port A bit 4: Z pulse (reconstruction)
ZDIR    EQU     20H                     ; NEW  port A bit 5: Z direction, 1 = +Z (reconstruction)
TYTOG   EQU     01H                     ; NEW  port B bit 0: Y transducer, toggles each increment
TXTOG   EQU     02H                     ; NEW  port B bit 1: X transducer, toggles each increment
TXDIR   EQU     04H                     ; NEW  port B bit 2: X direction, 1 = X moving +
TYDIR   EQU     08H                     ; NEW  port B bit 3: Y direction, 1 = Y moving +
TZTOG   EQU     10H                     ; NEW  port B bit 4: Z toggle (reserved; Z is open loop)
TZDIR   EQU     20H                     ; NEW  port B bit 5: Z direction (reserved)
ZDL     EQU     02H                     ; NEW  Z move: DL passes per pulse half (4 ms a step)

; ; MAIN MACHINE TOOL CONTROL                                                ; L1
; ; IN THREE DIMENSIONS                                                      ; L2
; ;                                                                          ; L3
        ORG     0800H                   ; L4
AUS     EQU     05A8H                   ; L5
ANWEIN  EQU     0701H                   ; L6
ANWAZL  EQU     07BCH                   ; L7
UMW     EQU     05C9H                   ; L8
ANWAUS  EQU     07C7H                   ; L9
MAIN:   LXI     SP,20B0H                ; L10
        MVI     A,0F1H                  ; L11
        OUT     0E1H                    ; L12
        CALL    COORD                   ; L13
        CALL    SPEED                   ; L14
        CALL    BASLA                   ; L15
        MOV     A,E                     ; L16
        CPI     0FH                     ; L17
        JZ      SPEED1                  ; L18
        JMP     ANA                     ; L19
CMAIN:  CALL    PARAM                   ; L20
        IN      0FAH                    ; L21
        ANI     0FH                     ; L22
        STA     1B36H                   ; L23
        LHLD    1B00H                   ; L24
        SHLD    1B34H                   ; L25
        LHLD    1B03H                   ; L26
        SHLD    1B32H                   ; L27
        IF      FIXED
LOOP:   CALL    YID                     ; L28  FIX E4 (the loop label moved up one line)
        ELSE
        CALL    YID                     ; L28
LOOP:                                   ; L29  (label)
        ENDIF
        CALL    OKEY                    ; L29
        JZ      SOBE                    ; L30
        CALL    OUT                     ; L31
        CALL    INPUT                   ; L32
        JMP     LOOP                    ; L33
SOBE:   CALL    BITTI                   ; L34
        HLT                             ; L35
; ;                                                                          ; L36
; ; END OF MAIN PROGRAM                                                      ; L37
; ;                                                                          ; L38
; ; ADDSUB SUBROUTINE                                                        ; L39
; ;                                                                          ; L40
ADDSUB: CALL    CHECK                   ; L41
        LXI     H,1B0EH                 ; L42
        MOV     A,M                     ; L43
        ANI     80H                     ; L44
        CNZ     COMP                    ; L45
        LXI     H,1B11H                 ; L46
        MOV     A,M                     ; L47
        ANI     80H                     ; L48
        CNZ     COMP                    ; L49
        PUSH    B                       ; L50
        PUSH    D                       ; L51
        PUSH    H                       ; L52
        IF      FIXED
        LHLD    1B0CH                   ; FIX E1 operand 1 into DE
        XCHG                            ; FIX E1
        ENDIF
        LHLD    1B0FH                   ; L53
        LDA     1B0EH                   ; L54
        MOV     B,A                     ; L55
        LDA     1B11H                   ; L56
        DAD     D                       ; L57
        SHLD    1B12H                   ; L58
        ADC     B                       ; L59
        STA     1B14H                   ; L60
        ANI     80H                     ; L61
        JZ      LEAVE                   ; L62
        LXI     H,1B14H                 ; L63
        CALL    COMP                    ; L64
LEAVE:                                  ; L65  (label)
        IF      FIXED
        LXI     H,1B0EH                 ; FIX E3 operand 1 back to sign-magnitude
        MOV     A,M                     ; FIX E3
        ANA     A                       ; FIX E3
        CM      COMP                    ; FIX E3
        ENDIF
        POP     H                       ; L65
        POP     D                       ; L66
        POP     B                       ; L67  (no RET: runs on into COMP, see RECONSTRUCTION.md)
COMP:   DCX     H                       ; L68
        DCX     H                       ; L69
        MOV     A,M                     ; L70
        CMA                             ; L71
        ADI     01H                     ; L72
        MOV     M,A                     ; L73
        INX     H                       ; L74
        MOV     A,M                     ; L75
        CMA                             ; L76
        ACI     00H                     ; L77
        MOV     M,A                     ; L78
        INX     H                       ; L79
        MOV     A,M                     ; L80
        CMA                             ; L81
        ACI     00H                     ; L82
        ORI     80H                     ; L83
        MOV     M,A                     ; L84
        RET                             ; L85
CHECK:  LXI     H,1B0CH                 ; L86
        CALL    SS                      ; L87
        LXI     H,1B0FH                 ; L88
        CALL    SS                      ; L89
        RET                             ; L90
SS:     MOV     A,M                     ; L91
        ANA     A                       ; L92
        RNZ                             ; L93
        INX     H                       ; L94
        IF      FIXED
        MOV     A,M                     ; FIX E2 (L95 read the high byte)
        ELSE
        MOV     M,A                     ; L95
        ENDIF
        ANA     A                       ; L96
        RNZ                             ; L97
        INX     H                       ; L98
        SUB     A                       ; L99
        MOV     M,A                     ; L100
        RET                             ; L101
; ;                                                                          ; L102
; ; END OF ADDSUB                                                            ; L103
; ;                                                                          ; L104
; ; MULT SUBROUTINE                                                          ; L105
; ;                                                                          ; L106
MULT:   LDA     1B43H                   ; L107
        ANI     80H                     ; L108
        MOV     C,A                     ; L109
        LDA     1B47H                   ; L110
        ANI     80H                     ; L111
        XRA     C                       ; L112
        MOV     C,A                     ; L113
        LDA     1B43H                   ; L114
        ANI     7FH                     ; L115
        STA     1B43H                   ; L116
        LDA     1B47H                   ; L117
        ANI     7FH                     ; L118
        STA     1B47H                   ; L119
        LXI     H,1B48H                 ; L120
        SUB     A                       ; L121
        MOV     M,A                     ; L122
        INX     H                       ; L123
        MOV     M,A                     ; L124
        INX     H                       ; L125
        MOV     M,A                     ; L126
        INX     H                       ; L127
        MOV     M,A                     ; L128
        MVI     B,20H                   ; L129
STAR:   LXI     H,1B48H                 ; L130
        CALL    SHIFT                   ; L131
        LXI     H,1B44H                 ; L132
        CALL    SHIFT                   ; L133
        JNC     CONT                    ; L134
        CALL    SUM                     ; L135
CONT:   DCR     B                       ; L136
        JNZ     STAR                    ; L137
        LDA     1B4BH                   ; L138
        ORA     C                       ; L139
        STA     1B4BH                   ; L140
        RET                             ; L141
SHIFT:  MOV     A,M                     ; L142
        ANA     A                       ; L143 NEW
        RAL                             ; L144 NEW
        MOV     M,A                     ; L145 NEW
        INX     H                       ; L146 NEW
SHIFT1: MOV     A,M                     ; L147
        RAL                             ; L148 NEW
        MOV     M,A                     ; L149 NEW
        INX     H                       ; L150 NEW
SHIFT2: MOV     A,M                     ; L151
        RAL                             ; L152
        NOP                             ; L153
        MOV     M,A                     ; L154
        INX     H                       ; L155
        MOV     A,M                     ; L156
        RAL                             ; L157
        MOV     M,A                     ; L158
        RET                             ; L159
SUM:    PUSH    B                       ; L160
        LHLD    1B40H                   ; L161
        XCHG                            ; L162
        LHLD    1B48H                   ; L163
        DAD     D                       ; L164
        SHLD    1B48H                   ; L165
        JC      CAR                     ; L166
        CALL    REPEAT                  ; L167
        SHLD    1B4AH                   ; L168
        POP     B                       ; L169
        RET                             ; L170
CAR:    CALL    REPEAT                  ; L171
        INX     H                       ; L172
        SHLD    1B4AH                   ; L173
        POP     B                       ; L174
        RET                             ; L175
REPEAT: LHLD    1B42H                   ; L176
        XCHG                            ; L177
        LHLD    1B4AH                   ; L178
        DAD     D                       ; L179
        RET                             ; L180
; ;                                                                          ; L181
; ; END OF MULT                                                              ; L182
; ;                                                                          ; L183
; ; DIVI SUBROUTINE                                                          ; L184
; ;                                                                          ; L185
DIVI:   LHLD    1B18H                   ; L186
        XCHG                            ; L187
        LHLD    1B1CH                   ; L188
        MOV     C,L                     ; L189 NEW
        MOV     B,H                     ; L190
        LXI     H,0000H                 ; L191
        CALL    DIV                     ; L192
        XCHG                            ; L193
        SHLD    1B2AH                   ; L194
        LHLD    1B1CH                   ; L195
        MOV     C,L                     ; L196 NEW
        MOV     B,H                     ; L197
        LXI     H,0000H                 ; L198 NEW
        XCHG                            ; L199
        CALL    DIV                     ; L200
        XCHG                            ; L201
        SHLD    1B28H                   ; L202
        RET                             ; L203
DIV:    MOV     A,B                     ; L204
        CMA                             ; L205
        MOV     B,A                     ; L206 NEW
        MOV     A,C                     ; L207 NEW
        CMA                             ; L208 NEW
        MOV     C,A                     ; L209 NEW
        INX     B                       ; L210
        CALL    LOOP1                   ; L211
LOOP1:  MOV     A,D                     ; L212
        MOV     D,E                     ; L213
        MVI     E,08H                   ; L214  (printed 09H, read 08H)
LOOP11: DAD     H                       ; L215
        JC      OVER                    ; L216
        ADD     A                       ; L217
        JNC     SUB1                    ; L218
        INX     H                       ; L219
SUB1:   PUSH    H                       ; L220
        DAD     B                       ; L221
        JC      OK                      ; L222
        POP     H                       ; L223
        DCR     E                       ; L224
        JNZ     LOOP11                  ; L225
        MOV     E,A                     ; L226
        ANA     A                       ; L227 NEW
        RET                             ; L228 NEW
OK:     INX     SP                      ; L229
        INX     SP                      ; L230 NEW
        INR     A                       ; L231 NEW
        DCR     E                       ; L232 NEW
        JNZ     LOOP11                  ; L233 NEW
        MOV     E,A                     ; L234 NEW
        STC                             ; L235
        RET                             ; L236
OVER:   ADC     A                       ; L237
        JNC     OVER1                   ; L238 NEW
        INX     H                       ; L239 NEW
OVER1:  DAD     B                       ; L240 NEW
        DCR     E                       ; L241 NEW
        JNZ     LOOP11                  ; L242 NEW
        MOV     E,A                     ; L243 NEW
        STC                             ; L244 NEW
        RET                             ; L245
; ;                                                                          ; L246
; ; END OF DIV                                                               ; L247
; ;                                                                          ; L248
; ; COORD SUBROUTINE                                                         ; L249
; ;                                                                          ; L250
COORD:  CALL    SIFIR                   ; L251
        CALL    Z                       ; L252
        CALL    X                       ; L253
        CALL    ONEE                    ; L254
        CALL    XX12                    ; L255  (printed XX122)
        LXI     H,0000H                 ; L256
        CALL    CEVIR                   ; L257
        SHLD    1B00H                   ; L258
        CALL    BASLA                   ; L259
        MOV     A,E                     ; L260
        CPI     0FH                     ; L261
        JZ      COORD                   ; L262
SHOWY1: CALL    Y                       ; L263
        CALL    ONLE1                   ; L264
        CALL    YY12                    ; L265
        CALL    CEVIR1                  ; L266
        SHLD    1B03H                   ; L267
        CALL    BASLA                   ; L268
        MOV     A,E                     ; L269
        CPI     0FH                     ; L270
        JZ      SHOWY1                  ; L271
SHOWX1: CALL    X                       ; L272
        CALL    TWOE                    ; L273
        CALL    XX12                    ; L274
        LXI     H,0000H                 ; L275
        CALL    CEVIR2                  ; L276
        SHLD    1B06H                   ; L277
        CALL    BASLA                   ; L278
        MOV     A,E                     ; L279 NEW
        CPI     0FH                     ; L280
        JZ      SHOWX1                  ; L281
SHOWY2: CALL    Y                       ; L282
        CALL    ONLE2                   ; L283
        CALL    YY12                    ; L284
        CALL    CEVIR                   ; L285
        SHLD    1B09H                   ; L286
        IF      FIXED
        CALL    BASLA                   ; FIX E15 F re-enters Y2 too
        MOV     A,E                     ; FIX E15
        CPI     0FH                     ; FIX E15
        JZ      SHOWY2                  ; FIX E15
        RET                             ; FIX E15
        ENDIF
BASLA:  CALL    ANWEIN                  ; L287
        JZ      BASLA                   ; L288
        NOP                             ; L289 NEW
        ANI     0FH                     ; L290
        MOV     E,A                     ; L291
SIFIR:  CALL    ANWAZL                  ; L292
        MVI     B,80H                   ; L293
        RET                             ; L294
Z:      MVI     A,8FH                   ; L295
        JMP     ZGIR                    ; L296 NEW
X:      MVI     A,76H                   ; L297
        CALL    AUS                     ; L298 NEW
        RET                             ; L299
Y:      MVI     A,6EH                   ; L300
        CALL    AUS                     ; L301 NEW
        RET                             ; L302 NEW

; ==== lines 303-498: the lost pages, reconstructed (every statement here is NEW) ==============
;      The prompt helpers, the 4-digit decimal entry, the Z axis, SPEED, and the start of PARAM.
;      Style of the surviving code: literal addresses, AUS with B advancing, BASLA-type polls.

ONEE:   MVI     A,06H                   ; NEW  "1" after H (X1 prompt)
        CALL    AUS                     ; NEW
        RET                             ; NEW
ONLE1:  MVI     A,06H                   ; NEW  "1" after y (Y1 prompt)
        CALL    AUS                     ; NEW
        RET                             ; NEW
TWOE:   MVI     A,5BH                   ; NEW  "2" after H (X2 prompt)
        CALL    AUS                     ; NEW
        RET                             ; NEW
ONLE2:  MVI     A,5BH                   ; NEW  "2" after y (Y2 prompt)
        CALL    AUS                     ; NEW
        RET                             ; NEW
YY12:   MVI     A,48H                   ; NEW  "=" then four dashes; B, C = the first dash
        CALL    AUS                     ; NEW
        MOV     C,B                     ; NEW
        JMP     TIRE                    ; NEW
XX12:   MVI     A,48H                   ; NEW  the same for the X prompts
        CALL    AUS                     ; NEW
        MOV     C,B                     ; NEW
TIRE:   MOV     B,C                     ; NEW  four dashes from digit C, B back to C
        MVI     A,40H                   ; NEW
        CALL    AUS                     ; NEW
        MVI     A,40H                   ; NEW
        CALL    AUS                     ; NEW
        MVI     A,40H                   ; NEW
        CALL    AUS                     ; NEW
        MVI     A,40H                   ; NEW
        CALL    AUS                     ; NEW
        MOV     B,C                     ; NEW
        RET                             ; NEW
; CEVIR: four decimal digits -> HL (binary); more than 4000 steps (200 mm) is refused: the
; dashes come back and the four digits are typed again. Three names, one routine (see
; RECONSTRUCTION.md: the printed callers clear HL before CEVIR and CEVIR2 only).
CEVIR1:                                 ; NEW
CEVIR2:                                 ; NEW
CEVIR:  CALL    DGIR                    ; NEW
CEV1:   MOV     A,L                     ; NEW  HL - 4001
        SUI     0A1H                    ; NEW
        MOV     A,H                     ; NEW
        SBI     0FH                     ; NEW
        RC                              ; NEW  HL <= 4000: accepted
        CALL    TIRE                    ; NEW  refused: dashes again
        CALL    DGIR0                   ; NEW
        JMP     CEV1                    ; NEW
; DGIR: read four decimal digits (keys 0-9; A-F and the command keys are ignored), show each
; at digit B (ANWAUS moves B on), return HL = their value. C = the first digit's mask.
DGIR:   MOV     C,B                     ; NEW
DGIR0:  LXI     H,0000H                 ; NEW
        MVI     D,04H                   ; NEW  four digits
DGIR1:  CALL    ANWEIN                  ; NEW
        JZ      DGIR1                   ; NEW
        CPI     0AH                     ; NEW
        JNC     DGIR1                   ; NEW  not a decimal digit
        CALL    ANWAUS                  ; NEW  echo it
        PUSH    D                       ; NEW
        MOV     E,A                     ; NEW
        MVI     D,00H                   ; NEW
        PUSH    D                       ; NEW  the digit
        DAD     H                       ; NEW  HL*2
        MOV     D,H                     ; NEW
        MOV     E,L                     ; NEW
        DAD     H                       ; NEW  HL*4
        DAD     H                       ; NEW  HL*8
        DAD     D                       ; NEW  HL*10
        POP     D                       ; NEW
        DAD     D                       ; NEW  + digit
        POP     D                       ; NEW
        DCR     D                       ; NEW
        JNZ     DGIR1                   ; NEW
        RET                             ; NEW
; ZGIR: the Z axis. Prompt 8FH "=----" (Z, entered first), four digits = Z in steps, then the
; table moves to Z at once (open loop, counted in ZAC, as ONYN/ONYP count YAC), 4 ms a step.
ZGIR:   CALL    AUS                     ; NEW  the Z symbol (A = 8FH from Z) at digit 0
        CALL    XX12                    ; NEW
        CALL    DGIR                    ; NEW
        SHLD    1B3CH                   ; NEW  ZKOR
ZMOVE:  LHLD    1B3EH                   ; NEW  ZAC
        XCHG                            ; NEW
        LHLD    1B3CH                   ; NEW
        MOV     A,L                     ; NEW  ZKOR - ZAC
        SUB     E                       ; NEW
        MOV     C,A                     ; NEW
        MOV     A,H                     ; NEW
        SBB     D                       ; NEW
        JC      ZNEG                    ; NEW
        ORA     C                       ; NEW
        JZ      SIFIR                   ; NEW  reached: clear, B = 80H, return
        MVI     C,20H                   ; NEW  + : Z direction high
        INX     D                       ; NEW
        JMP     ZSTEP                   ; NEW
ZNEG:   MVI     C,00H                   ; NEW  - : Z direction low
        DCX     D                       ; NEW
ZSTEP:  MOV     A,C                     ; NEW
        OUT     0F9H                    ; NEW  direction, pulse low
        ORI     10H                     ; NEW
        OUT     0F9H                    ; NEW  pulse high: the step
        XCHG                            ; NEW
        SHLD    1B3EH                   ; NEW  ZAC
        MVI     A,02H                   ; NEW  ZDL
        CALL    DL                      ; NEW
        MOV     A,C                     ; NEW
        OUT     0F9H                    ; NEW  pulse low
        MVI     A,02H                   ; NEW  ZDL
        CALL    DL                      ; NEW
        JMP     ZMOVE                   ; NEW
; ; END OF COORD                                                           ; NEW
; ;                                                                        ; NEW
; ; SPEED SUBROUTINE                                                       ; NEW
; ;                                                                        ; NEW
; SPEED: prompt "H=----" (Hiz, speed), four digits = feedrate in mm/min. Refused (dashes
; again): 0, more than 1500, and less than 6 (the delay would not fit a byte). The delay
; constant is 1500 / F (DIVI, integer part): DL milliseconds per half pulse.
SPEED:  CALL    SIFIR                   ; NEW
        CALL    X                       ; NEW  "H"
        CALL    XX12                    ; NEW  "=----"
        CALL    DGIR                    ; NEW
SPD1:   MOV     A,H                     ; NEW
        ORA     L                       ; NEW
        JZ      SPD2                    ; NEW  0: refused
        MOV     A,L                     ; NEW  HL - 1501
        SUI     0DDH                    ; NEW
        MOV     A,H                     ; NEW
        SBI     05H                     ; NEW
        JNC     SPD2                    ; NEW  over 1500: refused
        SHLD    1B16H                   ; NEW  FEED
        SHLD    1B1CH                   ; NEW  divisor
        LXI     H,05DCH                 ; NEW  1500
        SHLD    1B18H                   ; NEW  dividend
        PUSH    B                       ; NEW  (C: the first dash, for a refusal)
        CALL    DIVI                    ; NEW
        POP     B                       ; NEW
        LHLD    1B2AH                   ; NEW  integer part
        MOV     A,H                     ; NEW
        ANA     A                       ; NEW
        JNZ     SPD2                    ; NEW  under 6 mm/min: refused
        MOV     A,L                     ; NEW
        STA     1B38H                   ; NEW  the delay constant
        RET                             ; NEW
SPD2:   CALL    TIRE                    ; NEW
        CALL    DGIR0                   ; NEW
        JMP     SPD1                    ; NEW
; SPEED1: F pressed after the feedrate (MAIN L18 jumps here with an empty stack): enter the
; feedrate again, wait for the start key, go on as MAIN L15-L19 do.
SPEED1: CALL    SPEED                   ; NEW
        CALL    BASLA                   ; NEW
        MOV     A,E                     ; NEW
        CPI     0FH                     ; NEW
        JZ      SPEED1                  ; NEW
        JMP     ANA                     ; NEW
; ; END OF SPEED                                                           ; NEW
; ;                                                                        ; NEW
; ; PARAM SUBROUTINE                                                       ; NEW
; ;                                                                        ; NEW
; ==== end of the lost pages ==================================================================
PARAM:  LHLD    1B03H                   ; L499 NEW
        SHLD    1B0CH                   ; L500 NEW
        MVI     A,80H                   ; L501
        STA     1B0EH                   ; L502 NEW
        LHLD    1B09H                   ; L503
        SHLD    1B0FH                   ; L504
        SUB     A                       ; L505
        STA     1B11H                   ; L506
        CALL    ADDSUB                  ; L507 NEW
        LDA     1B14H                   ; L508
        STA     1B39H                   ; L509
        LHLD    1B12H                   ; L510
        SHLD    1B18H                   ; L511
        LHLD    1B00H                   ; L512
        SHLD    1B0CH                   ; L513
        MVI     A,80H                   ; L514
        STA     1B0EH                   ; L515
        LHLD    1B06H                   ; L516
        SHLD    1B0FH                   ; L517
        SUB     A                       ; L518 NEW
        STA     1B11H                   ; L519
        CALL    ADDSUB                  ; L520
        LDA     1B14H                   ; L521 NEW
        LXI     H,1B3AH                 ; L522
        XCHG                            ; L523 NEW
        LHLD    1B12H                   ; L524 NEW
        XCHG                            ; L525 NEW
        MOV     M,A                     ; L526
        LHLD    1B12H                   ; L527
        SHLD    1B1CH                   ; L528 NEW
        LHLD    1B18H                   ; L529
        DAD     D                       ; L530
        SHLD    1B2EH                   ; L531
        LHLD    1B18H                   ; L532
        SHLD    1B50H                   ; L533
        LHLD    1B1CH                   ; L534
        SHLD    1B52H                   ; L535
        CALL    DIVI                    ; L536
        LHLD    1B28H                   ; L537
        SHLD    1B40H                   ; L538
        LHLD    1B2AH                   ; L539
        SHLD    1B42H                   ; L540
        LXI     H,0000H                 ; L541
        SHLD    1B46H                   ; L542
        LHLD    1B00H                   ; L543
        SHLD    1B44H                   ; L544
        CALL    MULT                    ; L545
        LHLD    1B4AH                   ; L546
        SHLD    1B0CH                   ; L547
        LDA     1B39H                   ; L548
        IF      FIXED
        LXI     H,1B3AH                 ; FIX E5 the slope's sign is sign(dY) xor sign(dX)
        XRA     M                       ; FIX E5
        ENDIF
        XRI     80H                     ; L549
        STA     1B0EH                   ; L550
        LHLD    1B03H                   ; L551
        SHLD    1B0FH                   ; L552 NEW
        SUB     A                       ; L553
        STA     1B11H                   ; L554 NEW
        CALL    ADDSUB                  ; L555
        LHLD    1B12H                   ; L556
        SHLD    1B0CH                   ; L557
        LDA     1B14H                   ; L558
        STA     1B0EH                   ; L559
        LHLD    1B40H                   ; L560
        SHLD    1B4CH                   ; L561
        LHLD    1B42H                   ; L562
        SHLD    1B4EH                   ; L563
        RET                             ; L564
; ;                                                                          ; L565
; ; END OF PARAM                                                             ; L566
; ;                                                                          ; L567
; ; YID SUBROUTINE                                                           ; L568
; ;                                                                          ; L569
YID:    LHLD    1B34H                   ; L570 NEW
        SHLD    1B44H                   ; L571
        LXI     H,0000H                 ; L572
        SHLD    1B46H                   ; L573
        CALL    MULT                    ; L574
        IF      FIXED
        LDA     1B39H                   ; FIX E5 sign of the slope (L575 LDA 1B4BH)
        LXI     H,1B3AH                 ; FIX E5
        XRA     M                       ; FIX E5
        ELSE
        LDA     1B4BH                   ; L575
        ENDIF
        ANI     80H                     ; L576
        STA     1B11H                   ; L577
        LHLD    1B4AH                   ; L578
        SHLD    1B0FH                   ; L579
        CALL    ADDSUB                  ; L580
        LHLD    1B12H                   ; L581
        IF      FIXED
        LDA     1B14H                   ; FIX E6 a negative sum: its 16-bit two's complement
        ANA     A                       ; FIX E6
        JP      YID1                    ; FIX E6
        MOV     A,L                     ; FIX E6
        CMA                             ; FIX E6
        MOV     L,A                     ; FIX E6
        MOV     A,H                     ; FIX E6
        CMA                             ; FIX E6
        MOV     H,A                     ; FIX E6
        INX     H                       ; FIX E6
YID1:   XCHG                            ; FIX E7 at X2 the ideal Y is Y2
        LHLD    1B34H                   ; FIX E7
        LDA     1B06H                   ; FIX E7
        CMP     L                       ; FIX E7
        JNZ     YID2                    ; FIX E7
        LDA     1B07H                   ; FIX E7
        CMP     H                       ; FIX E7
        JNZ     YID2                    ; FIX E7
        LHLD    1B09H                   ; FIX E7
        XCHG                            ; FIX E7
YID2:   XCHG                            ; FIX E7
        ENDIF
        SHLD    1B30H                   ; L582
        RET                             ; L583
; ;                                                                          ; L584
; ; END OF YID                                                               ; L585
; ;                                                                          ; L586
; ; BITTI SUBROUTINE                                                         ; L587
; ;                                                                          ; L588
BITTI:  CALL    ANWAZL                  ; L589
        MVI     B,20H                   ; L590
        MVI     A,7FH                   ; L591
        CALL    AUS                     ; L592
        IF      FIXED
        MVI     A,04H                   ; FIX E11 "i" (L593 MVI A,78H)
        ELSE
        MVI     A,78H                   ; L593
        ENDIF
        CALL    AUS                     ; L594
        MVI     A,78H                   ; L595
        CALL    AUS                     ; L596
        MVI     A,78H                   ; L597
        CALL    AUS                     ; L598
        MVI     A,04H                   ; L599
        IF      FIXED
        CALL    AUS                     ; FIX E11 the fifth letter (L600 RET)
        ELSE
        RET                             ; L600
        ENDIF
        RET                             ; L601
; ;                                                                          ; L602
; ; END OF BITTI                                                             ; L603
; ;                                                                          ; L604
; ; OKEY SUBROUTINE                                                          ; L605
; ;                                                                          ; L606
OKEY:   LDA     1B06H                   ; L607
        LXI     H,1B34H                 ; L608
        XRA     M                       ; L609
        RNZ                             ; L610
        LDA     1B07H                   ; L611
        INX     H                       ; L612
        XRA     M                       ; L613
        RNZ                             ; L614
        DCX     H                       ; L615
        DCX     H                       ; L616
        LDA     1B31H                   ; L617
        XRA     M                       ; L618
        RNZ                             ; L619
        DCX     H                       ; L620
        LDA     1B30H                   ; L621
        XRA     M                       ; L622
        RET                             ; L623
; ;                                                                          ; L624
; ; END OF OKEY                                                              ; L625
; ;                                                                          ; L626
; ; OUT SUBROUTINE                                                           ; L627
; ;                                                                          ; L628
OUT:    LXI     H,1B39H                 ; L629
        MOV     A,M                     ; L630
        RLC                             ; L631
        MOV     B,A                     ; L632
        INX     H                       ; L633
        MOV     A,M                     ; L634
        RLC                             ; L635
        RLC                             ; L636
        ORA     B                       ; L637
        STA     1B54H                   ; L638
        ANA     A                       ; L639
        JZ      O00                     ; L640
        CPI     01H                     ; L641
        JZ      O01                     ; L642
        CPI     02H                     ; L643
        JZ      O02                     ; L644
O03:    CALL    COMPAR                  ; L645
        JNZ     O31                     ; L646
O32:    MVI     A,00H                   ; L647
        OUT     0F9H                    ; L648
        MVI     A,01H                   ; L649
        MOV     E,A                     ; L650
        IF      FIXED
        OUT     0F9H                    ; FIX E9 the X pulse was never raised
        ENDIF
        CALL    DELAY                   ; L651
        CALL    INPUT                   ; L652
        RET                             ; L653
        IF      FIXED
O31:    MVI     A,00H                   ; FIX E8 Y down (L654 MVI A,08H)
        ELSE
O31:    MVI     A,08H                   ; L654
        ENDIF
        OUT     0F9H                    ; L655
        IF      FIXED
        MVI     A,04H                   ; FIX E8 (L656 MVI A,0CH)
        ELSE
        MVI     A,0CH                   ; L656
        ENDIF
        MOV     E,A                     ; L657
        OUT     0F9H                    ; L658
        CALL    DELAY                   ; L659
        CALL    INPUT                   ; L660
        RET                             ; L661
O00:    CALL    COMPAR                  ; L662
        JNZ     O41                     ; L663
O42:    MVI     A,02H                   ; L664
        OUT     0F9H                    ; L665
        MVI     A,03H                   ; L666
        MOV     E,A                     ; L667
        OUT     0F9H                    ; L668
        CALL    DELAY                   ; L669
        CALL    INPUT                   ; L670
        RET                             ; L671
O41:    MVI     A,08H                   ; L672
        OUT     0F9H                    ; L673
        MVI     A,0CH                   ; L674
        MOV     E,A                     ; L675
        OUT     0F9H                    ; L676
        CALL    DELAY                   ; L677
        CALL    INPUT                   ; L678
        RET                             ; L679
O01:    CALL    COMPAR                  ; L680
        JNZ     O11                     ; L681
O12:    MVI     A,02H                   ; L682
        OUT     0F9H                    ; L683
        MVI     A,03H                   ; L684
        MOV     E,A                     ; L685
        OUT     0F9H                    ; L686
        CALL    DELAY                   ; L687
        CALL    INPUT                   ; L688
        RET                             ; L689
O11:    MVI     A,00H                   ; L690
        OUT     0F9H                    ; L691
        MVI     A,04H                   ; L692
        MOV     E,A                     ; L693
        OUT     0F9H                    ; L694
        CALL    DELAY                   ; L695
        CALL    INPUT                   ; L696
        RET                             ; L697
O02:    CALL    COMPAR                  ; L698
        JNZ     O21                     ; L699
O22:    MVI     A,00H                   ; L700
        OUT     0F9H                    ; L701
        MVI     A,01H                   ; L702
        MOV     E,A                     ; L703
        OUT     0F9H                    ; L704
        CALL    DELAY                   ; L705
        CALL    INPUT                   ; L706
        RET                             ; L707
O21:    MVI     A,08H                   ; L708
        OUT     0F9H                    ; L709
        MVI     A,0CH                   ; L710
        MOV     E,A                     ; L711
        OUT     0F9H                    ; L712
        CALL    DELAY                   ; L713
        CALL    INPUT                   ; L714
        RET                             ; L715
COMPAR: LHLD    1B30H                   ; L716
        XCHG                            ; L717
        LHLD    1B32H                   ; L718
        MOV     A,L                     ; L719
        SUB     E                       ; L720
        RNZ                             ; L721
        MOV     A,H                     ; L722
        SBB     D                       ; L723
        RET                             ; L724
DELAY:  LDA     1B38H                   ; L725
        ANA     A                       ; L726
        MOV     C,A                     ; L727
        CALL    DL                      ; L728
        MOV     A,E                     ; L729
        ANI     0AH                     ; L730
        OUT     0F9H                    ; L731
        MOV     A,C                     ; L732
        CALL    DL                      ; L733
        RET                             ; L734
DL:     MVI     B,0DAH                  ; L735
IDI:    DCR     B                       ; L736
        JNZ     IDI                     ; L737
        DCR     A                       ; L738
        JNZ     DL                      ; L739
        RET                             ; L740
; ;                                                                          ; L741
; ; END OF OUT                                                               ; L742
; ;                                                                          ; L743
; ; INPUT SUBROUTINE                                                         ; L744
; ;                                                                          ; L745
INPUT:  CALL    INPUT1                  ; L746 NEW
        IF      FIXED
        MOV     C,A                     ; FIX E10 keep the direction bits
        ANI     03H                     ; FIX E10 which toggle bit changed?
        RZ                              ; FIX E10 none: no increment
        CPI     02H                     ; L747  the X bit (bit 1) alone?
        MOV     A,C                     ; FIX E10
        JZ      STEST                   ; L748
        ANI     08H                     ; FIX E10 Y direction (L749 CPI 08H)
        JZ      YDEC                    ; L750
        ELSE
        CPI     02H                     ; L747
        JZ      STEST                   ; L748
        CPI     08H                     ; L749
        JZ      YDEC                    ; L750
        ENDIF
YINC:   LHLD    1B32H                   ; L751
        INX     H                       ; L752
        SHLD    1B32H                   ; L753
        RET                             ; L754
YDEC:   LHLD    1B32H                   ; L755
        DCX     H                       ; L756
        SHLD    1B32H                   ; L757
        RET                             ; L758
STEST:  CPI     01H                     ; L759
        RZ                              ; L760
        ANI     04H                     ; L761
        JZ      XDEC                    ; L762
XINC:   LHLD    1B34H                   ; L763
        INX     H                       ; L764
        SHLD    1B34H                   ; L765
        RET                             ; L766
XDEC:   LHLD    1B34H                   ; L767
        DCX     H                       ; L768
        SHLD    1B34H                   ; L769
        RET                             ; L770
INPUT1: IN      0FAH                    ; L771
        ANI     0FH                     ; L772
        MOV     D,A                     ; L773
        ANI     0CH                     ; L774
        MOV     B,A                     ; L775
        LXI     H,1B36H                 ; L776
        MOV     A,D                     ; L777
        XRA     M                       ; L778
        ANI     03H                     ; L779
        ORA     B                       ; L780
        MOV     M,D                     ; L781
        RET                             ; L782
; ;                                                                          ; L783
; ; END OF INPUT                                                             ; L784
; ;                                                                          ; L785
ANA:                                    ; L786  (label)
        IF      FIXED
        LHLD    1B00H                   ; FIX E12 X1 = X2 (16 bits): the Y-only routine
        XCHG                            ; FIX E12
        LHLD    1B06H                   ; FIX E12
        MOV     A,L                     ; FIX E12
        SUB     E                       ; FIX E12
        JNZ     CMAIN                   ; FIX E12
        MOV     A,H                     ; FIX E12
        SBB     D                       ; FIX E12
        JNZ     CMAIN                   ; FIX E12
        SHLD    1B34H                   ; FIX E12 XAC = X2, so that OKEY can end it
        LHLD    1B09H                   ; FIX E12
        SHLD    1B30H                   ; FIX E12 YID = Y2
        LHLD    1B03H                   ; FIX E12
        SHLD    1B32H                   ; FIX E12 YAC = Y1
        ELSE
        LDA     1B03H                   ; L786
        MOV     B,A                     ; L787
        LDA     1B09H                   ; L788
        ORA     B                       ; L789
        JNZ     CMAIN                   ; L790
        LDA     1B00H                   ; L791
        MOV     B,A                     ; L792
        LDA     1B06H                   ; L793
        ORA     B                       ; L794
        JZ      CMAIN                   ; L795
        ENDIF
        LHLD    1B03H                   ; L796
        XCHG                            ; L797
        LHLD    1B09H                   ; L798
        MOV     A,L                     ; L799
        SUB     E                       ; L800
        MOV     A,H                     ; L801
        SBB     D                       ; L802
        JNC     ONYP                    ; L803
ONYN:   CALL    OKEY                    ; L804
        JZ      SOBE                    ; L805
        MVI     A,00H                   ; L806
        OUT     0F9H                    ; L807
        MVI     A,04H                   ; L808
        OUT     0F9H                    ; L809
        CALL    DELAY                   ; L810
        MVI     A,00H                   ; L811
        OUT     0F9H                    ; L812
        CALL    DELAY                   ; L813
        LHLD    1B32H                   ; L814
        DCX     H                       ; L815
        SHLD    1B32H                   ; L816
        JMP     ONYN                    ; L817
ONYP:   CALL    OKEY                    ; L818
        JZ      SOBE                    ; L819
        MVI     A,08H                   ; L820
        OUT     0F9H                    ; L821
        IF      FIXED
        MVI     A,0CH                   ; FIX E13 the Y pulse
        OUT     0F9H                    ; FIX E13
        ENDIF
        CALL    DELAY                   ; L822
        MVI     A,08H                   ; L823
        OUT     0F9H                    ; L824
        LHLD    1B32H                   ; L825
        INX     H                       ; L826
        SHLD    1B32H                   ; L827
        JMP     ONYP                    ; L828
SPED:   LHLD    1B50H                   ; L829
        XCHG                            ; L830
        LHLD    1B52H                   ; L831
        MOV     A,L                     ; L832
        SUB     E                       ; L833
        MOV     A,H                     ; L834
        SBB     D                       ; L835
        JNC     BOL1                    ; L836
        SHLD    1B18H                   ; L837
        XCHG                            ; L838
        SHLD    1B1CH                   ; L839
        CALL    DIVI                    ; L840
        JMP     CBOL1                   ; L841
BOL1:   SHLD    1B1CH                   ; L842
        XCHG                            ; L843
        SHLD    1B18H                   ; L844
        CALL    DIVI                    ; L845
CBOL1:  LDA     1B29H                   ; L846
        CPI     80H                     ; L847
        RC                              ; L848
        CPI     0C8H                    ; L849
        JNC     BBOL2                   ; L850
        IF      FIXED
        LDA     1B38H                   ; FIX E14 the delay constant (L851 LDA 1B39H)
        ELSE
        LDA     1B39H                   ; L851
        ENDIF
        MOV     B,A                     ; L852
        ANA     A                       ; L853
        RAR                             ; L854
        ANA     A                       ; L855
        RAR                             ; L856
        ANA     A                       ; L857
        RAR                             ; L858
        MOV     C,A                     ; L859
        ANA     A                       ; L860
        RAR                             ; L861
        ADD     C                       ; L862
        ADD     B                       ; L863
        STA     1B38H                   ; L864
        RET                             ; L865
BBOL2:  CPI     0E8H                    ; L866
        JNC     BBOL3                   ; L867
        LDA     1B38H                   ; L868
        MOV     B,A                     ; L869
        ANA     A                       ; L870
        RAR                             ; L871
        ANA     A                       ; L872
        RAR                             ; L873
        ADD     B                       ; L874
        STA     1B38H                   ; L875
        RET                             ; L876
BBOL3:  LDA     1B38H                   ; L877
        MOV     B,A                     ; L878
        ANA     A                       ; L879
        RAR                             ; L880
        MOV     C,A                     ; L881
        ANA     A                       ; L882
        RAR                             ; L883
        ADD     C                       ; L884
        ADD     B                       ; L885
        STA     1B38H                   ; L886
        RET                             ; L887

        IF      $ GT 1000H
        ERROR   "the program does not fit the 2 KB user EPROM (0800H-0FFFH)"  ; NEW
        ENDIF
        END                             ; L888
