# sigrok-cli run for a test, its complaints refused. sigrok 0.5 says what it could not read only in
# its debug log (it stops at the first line it cannot parse and still exits 0): it runs at log level
# 5 and any such message fails the test.
#   sigrok_read(FILE RESULT ARGS...)  reads FILE (vcd) with sigrok-cli ARGS...; RESULT: the name of
#                                     a variable for its standard output, or "" when it writes to a
#                                     file (then its standard output is searched for complaints too)
function(sigrok_read file result)
  execute_process(COMMAND ${SIGROK} -l 5 ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sigrok-cli could not read ${file}: exit ${rc}\n${log}")
  endif()
  set(searched "${log}")
  if(result STREQUAL "")
    set(searched "${out}${log}")
  endif()
  string(REGEX MATCHALL "[^\n]*(Unexpected|[Ee]rror|[Ff]ailed|[Ii]nvalid)[^\n]*" bad "${searched}")
  if(bad)
    message(FATAL_ERROR "sigrok-cli reading ${file}:\n${bad}")
  endif()
  if(NOT result STREQUAL "")
    set(${result} "${out}" PARENT_SCOPE)
  endif()
endfunction()
