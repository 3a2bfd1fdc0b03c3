# alp85 debug thesis-fixed --script break_step_finish.gdb --batch
# Break at OUT, step into DELAY, finish back; registers checked. The line of the worked Appendix C
# session (docs/thesis.md): (0100, 0050) -> (0300, 0200), Z = 12, 750 mm/min (D = 1500/750 = 2).
# Every expected value below is read off firmware/thesis/thesis.asm by hand.
type R 7 0 8 0 0 EXEC
wait display "?.=----" timeout 200ms
type 0 0 1 2
wait display "H1=----" timeout 1s
type 0 1 0 0 EXEC
wait display "y1=----" timeout 200ms
type 0 0 5 0 EXEC
wait display "H2=----" timeout 200ms
type 0 3 0 0 EXEC
wait display "y2=----" timeout 200ms
type 0 2 0 0 EXEC
wait display "H=----" timeout 200ms
type 0 7 5 0
expect display "H=0750"
break OUT
# the key that starts the motion: CMAIN, PARAM, then LOOP calls YID, OKEY, and OUT
press EXEC
expect reg PC OUT
# LOOP: CALL YID (3) CALL OKEY (3) JZ SOBE (3) CALL OUT (3): the return address is LOOP+12,
# pushed below MAIN's stack top 20B0H
expect reg SP 20AEH
expect word 20AEH LOOP+12
expect word XAC 100
expect word YAC 50
# YID at X1: Y1 + |M|*100 - |M|*100 = 50
expect word 1B30H 50
expect mem DLYK 2
bt
# OUT: LXI, MOV, RLC, MOV, INX, MOV, RLC, RLC, ORA, STA, ANA, JZ: both signs + (00H): quadrant 0
step 12
expect reg PC O00
expect mem QUAD 0
# COMPAR run whole: YIDV - YAC = 50 - 50 = 0, so Z
next
expect reg PC O00+3
expect flag Z 1
# JNZ O41 not taken: the X case O42
step
expect reg PC O42
# MVI A,02H; OUT 0F9H; MVI A,03H; MOV E,A; OUT 0F9H: direction +X then the pulse high
step 5
expect reg PC O42+9
expect reg A 03H
expect reg E 03H
expect port A 03H
# into DELAY: CALL pushes O42+12
step
expect reg PC DELAY
expect reg SP 20ACH
expect word 20ACH O42+12
bt
set $t0 = $T
finish
# back in O42 after the CALL; DELAY: A = D = 2, C = A; DL; A = E & 0AH = 02H out (pulse low);
# A = C; DL counts A down to 0 (Z = 1, B = 0); RET
expect reg PC O42+12
expect reg SP 20AEH
expect reg A 00H
expect reg B 00H
expect reg C 02H
expect reg E 03H
expect flag Z 1
expect port A 02H
# docs/thesis.md: DELAY with its CALL takes 6140*D + 124 T-states; finish started after the CALL (18 T)
expect $T - $t0 == 6140 * 2 + 124 - 18
info registers
