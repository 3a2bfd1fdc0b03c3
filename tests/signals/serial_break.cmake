# A framing error on the serial line: tests/signals/sod.asm raises SOD for 11 T-states and then holds
# it at space. The terminal (alp85 run --serial 9600) takes the fall as a start bit and finds the
# stop bit at space too: a break, reported on standard error with its T-state; nothing is written
# to standard output and the run ends with status 0. Standard input is empty (/dev/null).
#   cmake -DALP85= -DSOD=sod.asm -P serial_break.cmake
execute_process(COMMAND ${ALP85} run ${SOD} --keys "R 7 0800 EXEC" --serial 9600 --for 10ms
                INPUT_FILE /dev/null RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 run --serial 9600: exit ${rc}\n${out}${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "a break wrote '${out}' to standard output")
endif()
string(REGEX MATCHALL "alp85 run: serial: [^\n]*" reports "${err}")
if(NOT reports MATCHES "^alp85 run: serial: break \\(SOD held at space through the stop bit\\) at [0-9.]+ ms \\(([0-9]+) T-states\\), character 00H as sampled$")
  message(FATAL_ERROR "expected one break reported, got:\n${reports}\n${err}")
endif()
