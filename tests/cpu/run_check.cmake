# Runs one command and checks its exit status and its output (stdout and stderr together).
#   cmake -DCMD="prog;arg;..." -DSTATUS=n|nonzero [-DMATCH=regex] [-DMATCH2=regex] [-DNOMATCH=regex] -P run_check.cmake
# With -DTWICE=1 the command runs twice and both outputs must be identical (determinism).
execute_process(COMMAND ${CMD} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(STATUS STREQUAL "nonzero")  # an argument error: CLI11 picks the code
  if(rc EQUAL 0)
    message(FATAL_ERROR "exit status 0, expected an error\n${all}")
  endif()
elseif(NOT rc STREQUAL "${STATUS}")
  message(FATAL_ERROR "exit status ${rc}, expected ${STATUS}\n${all}")
endif()
foreach(m MATCH MATCH2)
  if(DEFINED ${m} AND NOT all MATCHES "${${m}}")
    message(FATAL_ERROR "output does not match '${${m}}':\n${all}")
  endif()
endforeach()
if(DEFINED NOMATCH AND all MATCHES "${NOMATCH}")
  message(FATAL_ERROR "output matches '${NOMATCH}', which it must not:\n${all}")
endif()
if(TWICE)
  execute_process(COMMAND ${CMD} RESULT_VARIABLE rc2 OUTPUT_VARIABLE out2 ERROR_VARIABLE err2)
  # Only the counters must agree; wall time and rate differ between runs.
  string(REGEX MATCHALL "(instructions|T-states): +[0-9]+" c1 "${all}")
  string(REGEX MATCHALL "(instructions|T-states): +[0-9]+" c2 "${out2}${err2}")
  if(NOT c1 OR NOT c1 STREQUAL c2 OR NOT rc2 STREQUAL rc)
    message(FATAL_ERROR "two runs differ:\n${c1}\n${c2}")
  endif()
endif()
