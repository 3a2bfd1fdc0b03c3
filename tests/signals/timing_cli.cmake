# alp85 timing and the debugger's timing, as a user runs them (docs/signals.md):
#   -DALP85= -DDIR= (scratch) -DSIGROK= -DSRC= (this folder)
# The machine cycles and T-states are the data sheet's (instruction set table); each picture and
# VCD is written, and sigrok-cli reads the VCD without a complaint.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
function(expect_output what status)  # ARGN: the command, then PATTERNS and the patterns
  list(FIND ARGN PATTERNS p)
  list(SUBLIST ARGN 0 ${p} cmd)
  math(EXPR p "${p} + 1")
  list(SUBLIST ARGN ${p} -1 patterns)
  execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${DIR})
  if(NOT rc EQUAL ${status})
    message(FATAL_ERROR "${what}: exit ${rc}, expected ${status}\n${out}${err}")
  endif()
  foreach(pat ${patterns})
    if(NOT "${out}${err}" MATCHES "${pat}")
      message(FATAL_ERROR "${what}: no '${pat}' in\n${out}${err}")
    endif()
  endforeach()
endfunction()

set(F "M1  opcode fetch +T1-T4  IO/M=0 S1,S0=1,1  RD")
set(S "M1  opcode fetch +T1-T6  IO/M=0 S1,S0=1,1  RD")
set(R "memory read +T1-T3  IO/M=0 S1,S0=1,0  RD")
set(W "memory write +T1-T3  IO/M=0 S1,S0=0,1  WR")
# MVI r: F R, 7 T
expect_output(MVI 0 ${ALP85} timing "MVI A,32H" PATTERNS "${F}" "M2  ${R} +A15-A8=08H AD7-AD0=01H,32H" "2 machine cycles, 7 T-states")
# STA: F R R W, 13 T
expect_output(STA 0 ${ALP85} timing "STA 2050H" --svg sta.svg --png sta.png --vcd sta.vcd
              PATTERNS "${F}" "M2  ${R}" "M3  ${R}" "M4  ${W} +A15-A8=20H AD7-AD0=50H" "4 machine cycles, 13 T-states")
# CALL: S R R W W, 18 T
expect_output(CALL 0 ${ALP85} timing "CALL 0900H" PATTERNS "${S}" "M4  ${W}" "M5  ${W}" "5 machine cycles, 18 T-states")
# IN: F R I, OUT: F R O, 10 T
expect_output(IN 0 ${ALP85} timing "IN 0FAH" PATTERNS "M3  I/O read +T1-T3  IO/M=1 S1,S0=1,0  RD +A15-A8=FAH AD7-AD0=FAH" "10 T-states")
expect_output(OUT 0 ${ALP85} timing "OUT 0F9H" PATTERNS "M3  I/O write +T1-T3  IO/M=1 S1,S0=0,1  WR +A15-A8=F9H AD7-AD0=F9H" "10 T-states")
# DAD: F B B, 10 T
expect_output(DAD 0 ${ALP85} timing "DAD B" PATTERNS "M2  bus idle +T1-T3  IO/M=0 S1,S0=1,0 " "M3  bus idle" "3 machine cycles, 10 T-states")
# RST 7.5 acknowledge: a 6 T idle cycle with status 1 1 1 and no INTA, two writes: 12 T
expect_output(RST75 0 ${ALP85} timing --interrupt rst7.5 --vcd ack.vcd
              PATTERNS "M1  bus idle \\(RST/TRAP acknowledge\\)  T1-T6  IO/M=1 S1,S0=1,1  +\\(no INTA" "M2  ${W}" "3 machine cycles, 12 T-states")
# refusals: an instruction that does not assemble (its column), no instruction, --svg onto --vcd
expect_output(bad 2 ${ALP85} timing "MVI Q,3" PATTERNS "alp85 timing:1:15: error: undefined symbol 'Q'")
expect_output(none 2 ${ALP85} timing PATTERNS "give one instruction")
expect_output(clash 2 ${ALP85} timing "NOP" --svg x.vcd --vcd x.vcd PATTERNS "nothing written")
# A drawing that cannot be written: exit 1, the command and the file named (--help's exit status).
expect_output(unwritable 1 ${ALP85} timing "NOP" --svg no-such-dir/x.svg PATTERNS "^NOP at 0800H" "alp85 timing: .*no-such-dir/x.svg")
# the debugger's timing: the next instruction with the machine's registers (A = 0 after RESET)
expect_output(debugger 0 ${ALP85} debug --script ${SRC}/timing.gdb --batch
              PATTERNS "0800H\tSTA 2050H" "M4  ${W} +A15-A8=20H AD7-AD0=50H" "13 T-states")

foreach(f sta.svg sta.png sta.vcd ack.vcd)
  if(NOT EXISTS ${DIR}/${f})
    message(FATAL_ERROR "alp85 timing wrote no ${f}")
  endif()
endforeach()
file(READ ${DIR}/sta.svg svg)
if(NOT svg MATCHES "<title>STA 2050H at 0800H</title>")
  message(FATAL_ERROR "sta.svg has no title")
endif()
include(${SRC}/sigrok.cmake)
foreach(vcd sta.vcd ack.vcd)
  sigrok_read(${vcd} "" -I vcd -i ${DIR}/${vcd} -O vcd)  # the rewrite on standard output, searched too
endforeach()

# The diagrams of docs/signals.md, written by the command once its output was checked above
# (-DDOC_IMG=docs/img when ALP85_DOC_IMAGES is on).
if(DOC_IMG)
  foreach(pair "MVI A,32H|mvi" "STA 2050H|sta" "CALL 0900H|call" "OUT 0F9H|out")
    string(REPLACE "|" ";" p "${pair}")
    list(GET p 0 instruction)
    list(GET p 1 name)
    expect_output(doc 0 ${ALP85} timing "${instruction}" --svg ${DOC_IMG}/timing-${name}.svg PATTERNS "T-states")
  endforeach()
  expect_output(doc 0 ${ALP85} timing --interrupt rst7.5 --svg ${DOC_IMG}/timing-rst75.svg PATTERNS "12 T-states")
endif()
