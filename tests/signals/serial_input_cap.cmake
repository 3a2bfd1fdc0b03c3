# alp85 run --serial reads standard input to its end before the run, at most 1 MiB: /dev/zero (no
# end) is refused with status 2 and a sentence before anything runs, not read for ever.
#   cmake -DALP85= -P serial_input_cap.cmake
execute_process(COMMAND ${ALP85} run --serial 9600 INPUT_FILE /dev/zero RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "alp85 run: standard input is larger than 1048576 bytes, the most --serial sends\n")
  message(FATAL_ERROR "/dev/zero as standard input: exit ${rc}, expected 2 and the cap named\n${err}")
endif()
