# What the window's scripted tests share (cmake -P scripts that run alp85 gui under Xvfb):
#   window_test_begin()           without xvfb-run: say SKIP and end the test; else a fresh ${WORK}
#   window_run(SCREEN ARGS...)    alp85 gui ARGS... on an Xvfb screen SCREEN (e.g. 1400x900x24) in
#                                 ${WORK}; fails on a non-zero exit; leaves its output in `out`, `err`
#   debug_commands(VAR HOOK...)   VAR: each HOOK after --debug-command (a command line or a hook:
#                                 click:BUTTON, frames:N, status, toolpath, ...)
# Macros, so that window_test_begin's return() ends the calling script.
macro(window_test_begin)
  if(NOT XVFB_RUN)
    message("SKIP: xvfb-run is missing: install xvfb (scripts/setup.sh --tests does) to run the GUI tests")
    return()
  endif()
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
endmacro()

macro(window_run screen)
  execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 ${screen}" ${ALP85} gui ${ARGN}
                  WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "alp85 gui exited with ${rc}: ${err}")
  endif()
endmacro()

function(debug_commands var)
  set(args "")
  foreach(h IN LISTS ARGN)
    list(APPEND args --debug-command "${h}")
  endforeach()
  set(${var} "${args}" PARENT_SCOPE)
endfunction()
