; Ends that `alp85 cpm` must report as errors; assembled once per MODE (-D MODE=n).
;   MODE 1: an undefined BDOS function (99)      -> exit status 3
;   MODE 2: HLT outside the warm-boot vector      -> exit status 2
;   MODE 3: an endless loop, for --max-cycles     -> exit status 4
        ORG     100H
START:
        IF      MODE EQ 1
        MVI     C,99
        CALL    5
        JMP     0
        ENDIF
        IF      MODE EQ 2
        HLT
        ENDIF
        IF      MODE EQ 3
LOOP:   JMP     LOOP
        ENDIF
        END     START
