; ALP85's small CP/M 2.2 BDOS for `alp85 cpm`: just enough of CP/M for the period CPU diagnostics.
; The emulated CPU executes it; the host only watches three output ports and the HALT state.
;
;   function 0  system reset   -> JMP 0000H (warm boot)
;   function 2  console output -> the character in E to port CONOUT
;   function 9  print string   -> (DE) up to '$' to port CONOUT
;   anything else              -> the function number to port BADFN, then HLT
;
; A warm boot (any jump to 0000H) executes the HLT at 0000H: `alp85 cpm` ends with status 0.
; (0006H) holds the BDOS entry, the top of the transient program area, as in CP/M.

CONOUT  EQU     01H             ; console output port (the host prints the byte)
BADFN   EQU     02H             ; undefined BDOS function number (the host reports it)
BDOSORG EQU     0FF00H

        ORG     0000H
WBOOT:  HLT                     ; warm boot: end of the program
        NOP
        NOP
        NOP
        NOP
        JMP     BDOS            ; 0005H: the BDOS entry point

        ORG     BDOSORG
BDOS:   MOV     A,C
        CPI     2
        JZ      CONCHR
        CPI     9
        JZ      PRSTR
        ORA     A
        JZ      WBOOT
        OUT     BADFN
        HLT

CONCHR: MOV     A,E
        OUT     CONOUT
        RET

PRSTR:  LDAX    D
        CPI     '$'
        RZ
        OUT     CONOUT
        INX     D
        JMP     PRSTR

        END
