# alp85 script's exit statuses: 1 when an expectation fails, 2 when a script has errors (and then
# nothing runs: no JUnit file appears).
execute_process(COMMAND ${ALP85} script ${CASES}/fails.alp RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "failing expectation: exit status ${rc}, expected 1")
endif()
set(junit ${CMAKE_CURRENT_BINARY_DIR}/errors-junit.xml)
file(REMOVE ${junit})
execute_process(COMMAND ${ALP85} script ${CASES}/errors.alp --junit ${junit} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "script errors: exit status ${rc}, expected 2")
endif()
if(EXISTS ${junit})
  message(FATAL_ERROR "a script with errors still wrote ${junit}")
endif()
foreach(want "errors.alp:2:1: error: unknown command 'frobnicate'"
             "errors.alp:3:12: error: address 10000H is out of range"
             "errors.alp:4:11: error: unknown symbol 'NOSUCHSYMBOL'"
             "errors.alp:5:7: error: unknown key 'Q'")
  string(FIND "${err}" "${want}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "missing report: ${want}\n--- got:\n${err}")
  endif()
endforeach()
