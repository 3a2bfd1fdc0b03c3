load timing.asm
set $pc = 0800H
timing
