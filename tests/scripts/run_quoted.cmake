# alp85 run with a program whose path holds a double quote: the arguments become commands
# directly, so no script text is made that the quote could break (issue #11, item 3).
#   cmake -DALP85=<alp85> -DSOURCE=<a .asm> -DDIR=<scratch folder> -P run_quoted.cmake
file(MAKE_DIRECTORY ${DIR})
set(program "${DIR}/say \"hi\".asm")
configure_file(${SOURCE} ${program} COPYONLY)
execute_process(COMMAND ${ALP85} run ${program} --no-monitor --text --boot 1ms
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit status ${rc}\n${out}${err}")
endif()
if(NOT out MATCHES "1\\.000 ms \\(3072 T-states\\) simulated, PC=")
  message(FATAL_ERROR "unexpected output:\n${out}${err}")
endif()
