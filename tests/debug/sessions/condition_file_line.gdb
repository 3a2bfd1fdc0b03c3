# alp85 debug thesis-fixed --script condition_file_line.gdb --batch
# A conditional breakpoint and a breakpoint by FILE:LINE. The line (0000, 0000) -> (0020, 0010)
# at 1500 mm/min (D = 1): |M| = 0.5, YID(x) = floor(x/2); steps X, X, Y, X, Y, ... so YAC = 4
# when X reaches 10 (YID(9) = 4), then YID(10) = 5 asks for a Y step with X still 10. At D = 1
# the physical motor is not always settled when INPUT reads the transducer (docs/thesis.md), so
# the ideal motor: each step complete at its pulse.
motor ideal
type R 7 0 8 0 0 EXEC
wait display "?.=----" timeout 200ms
type 0 0 0 0
wait display "H1=----" timeout 1s
type 0 0 0 0 EXEC
wait display "y1=----" timeout 200ms
type 0 0 0 0 EXEC
wait display "H2=----" timeout 200ms
type 0 0 2 0 EXEC
wait display "y2=----" timeout 200ms
type 0 0 1 0 EXEC
wait display "H=----" timeout 200ms
type 1 5 0 0
# line 833 of thesis.asm is the comment "; ; INPUT SUBROUTINE": it binds to INPUT (835)
break thesis.asm:833
press EXEC hold 20ms gap 0ms
continue
expect reg PC INPUT
# the first step was X: INPUT is called from O42 (quadrant 0) and from LOOP
expect word XAC 0
delete
break YID if word[1B34H] == 10
continue
expect reg PC YID
expect word XAC 10
expect word YAC 4
finish
expect word 1B30H 5
continue
expect reg PC YID
expect word XAC 10
expect word YAC 5
info breakpoints
delete
wait display "  8itti" timeout 2s
run 10ms
expect word XAC 20
expect word YAC 10
expect halted
