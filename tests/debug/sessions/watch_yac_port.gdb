# alp85 debug thesis-fixed --script watch_yac_port.gdb --batch
# Watchpoints on YAC, on the Y transducer and on port F9H. The worked line (0100, 0050) ->
# (0300, 0200) at 750 mm/min: |M| = floor(65536*150/200)/65536 = 0.75 exactly, and
# YID(x) = 50 + floor(0.75*x) - floor(0.75*100) = floor(0.75*x) - 25 (docs/thesis.md, "How the
# line is drawn"): YID(100) = 50, YID(101) = 50, YID(102) = 51, YID(103) = 52, YID(104) = 53.
# Steps: X (100->101), X (->102), Y (50->51), X (->103), Y (->52), X (->104), Y (->53), ...
type R 7 0 8 0 0 EXEC
wait display "?.=----" timeout 200ms
type 0 0 0 0
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
# YAC is set to Y1 by CMAIN (LHLD 1B03H; SHLD 1B32H, just before LOOP), then written by INPUT
# when the Y transducer's increment is counted (YINC: LHLD, INX, SHLD)
watch word YAC
press EXEC
expect reg PC LOOP
expect word YAC 50
expect word XAC 100
continue
expect reg PC YINC+7
expect word YAC 51
expect reg HL 51
expect word XAC 102
expect count Y 1
expect count X 2
expect axis Y steps 1
delete
# the transducer itself: its count changes while the table moves, before the firmware reads it
watch axis Y count
continue
expect count Y 2
expect word YAC 51
expect word XAC 103
delete
# every rising X pulse: OUT 0F9H with A = 03H (O42); the Y pulses (0CH) do not stop it
watch port F9H out == 03H
continue
expect reg PC O42+9
expect reg A 03H
expect word XAC 103
expect word YAC 52
continue
expect reg PC O42+9
expect word XAC 104
expect word YAC 53
info breakpoints
# without a value: every write; next is DELAY's pulse low (A = E AND 0AH = 02H, after the OUT at
# DELAY+11), then, with YID(105) = 53 = YAC, the next X step's direction write in O42
delete
watch port F9H out
continue
expect reg A 02H
expect reg PC DELAY+13
continue
expect reg A 02H
expect reg PC O42+4
