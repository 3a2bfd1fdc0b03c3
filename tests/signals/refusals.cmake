# What record signals and --vcd refuse (docs/signals.md): -DALP85= -DDIR= (a scratch folder)
# Each refusal exits 2 with the place, and leaves its target and the folder as they were.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
function(expect_refusal what status pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY ${DIR})
  if(NOT rc EQUAL ${status} OR NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: expected exit ${status} and '${pattern}', got ${rc}:\n${out}${err}")
  endif()
endfunction()

# a recording onto the script itself: refused before anything runs; the script is intact
set(script "record signals self.alp PA0\nrun 1ms\nrecord stop\n")
file(WRITE ${DIR}/self.alp "${script}")
expect_refusal("onto the script" 2 "self.alp:1:[0-9]+: error: record '[./]*self.alp' is the script" ${ALP85} script self.alp)
file(READ ${DIR}/self.alp now)
if(NOT now STREQUAL script)
  message(FATAL_ERROR "the script was changed:\n${now}")
endif()

# a pin the board does not have: file:line:col at the pin
file(WRITE ${DIR}/pin.alp "record signals pin.vcd PA0 PA9\n")
expect_refusal("unknown pin" 2 "pin.alp:1:28: error: no pin 'PA9' on the board" ${ALP85} script pin.alp)

# --vcd onto the program alp85 run loads: refused, the program intact
file(WRITE ${DIR}/prog.asm "        ORG 0800H\nL:      JMP L\n")
expect_refusal("--vcd onto the program" 2 "would destroy the input" ${ALP85} run prog.asm --vcd prog.asm)
file(READ ${DIR}/prog.asm now)
if(NOT now STREQUAL "        ORG 0800H\nL:      JMP L\n")
  message(FATAL_ERROR "the program was changed:\n${now}")
endif()

# --vcd '' (an unset shell variable) is no request for no file
expect_refusal("--vcd ''" 2 "--vcd" ${ALP85} run --vcd "")

# a script that fails while recording: the recording up to the failure is written whole, as a
# CSV recording is (docs/scripting.md), with its end
file(WRITE ${DIR}/fails.alp "record signals fails.vcd 8155\nrun 1ms\nexpect reg A 99H\nrecord stop\n")
expect_refusal("a failing script" 1 "fails.alp:3" ${ALP85} script fails.alp)
file(READ ${DIR}/fails.vcd vcd)
if(NOT vcd MATCHES "\\$comment recording ended at T-state [0-9]+ \\(3072 T-states recorded\\) \\$end\n$")
  message(FATAL_ERROR "fails.vcd does not end with its end:\n${vcd}")
endif()

# a run ended by SIGTERM while recording (1 h of machine time: minutes of host time) leaves neither
# the VCD nor its temporary
file(WRITE ${DIR}/long.alp "record signals long.vcd\nrun 3600s\nrecord stop\n")
execute_process(COMMAND timeout -s TERM 2 ${ALP85} script long.alp WORKING_DIRECTORY ${DIR} RESULT_VARIABLE rc)
if(NOT rc EQUAL 124)
  message(FATAL_ERROR "the long script ended with ${rc} before SIGTERM")
endif()

file(GLOB left RELATIVE ${DIR} ${DIR}/* ${DIR}/.*)
list(SORT left)
if(NOT left STREQUAL "fails.alp;fails.vcd;long.alp;pin.alp;prog.asm;self.alp")
  message(FATAL_ERROR "the folder holds more than the inputs: ${left}")
endif()
