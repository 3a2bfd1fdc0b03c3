# alp85 debug scripts/machine/endstop.asm --motor ideal --script endstop.gdb --batch
# Watchpoints on the machine tool's end stop and lost steps. endstop.asm steps the Y table 120
# steps in -, its low end stop 100 steps below the power-on position (scripts/machine/endstop.alp).
# Ideal motors step at the pulse's rising edge: the 100th edge is the OUT whose I/O cycle starts at
# T-state 65 + 99 x 12409 = 1228556 (tests/scripts/CMakeLists.txt counts it); that OUT ends 3
# T-states later, and the watchpoint stops after it.
watch axis Y endstop
continue
expect $T == 65 + 99 * 12409 + 3
expect axis Y steps -100
expect lost Y 0
delete
# the 101st edge: commanded -101, the table stays at -100: one step lost
watch axis Y lost
continue
expect $T == 65 + 100 * 12409 + 3
expect lost Y -1
expect axis Y steps -100
info axis Y
