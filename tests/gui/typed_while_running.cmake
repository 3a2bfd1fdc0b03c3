# Command lines typed while the machine runs (--debug, the command pane): break, watch, display and
# info breakpoints run at once; a step is answered "pause first" and the run goes on; after Pause
# the step runs. The run is Continue with the thesis firmware waiting in its keyboard loop, so that
# no breakpoint set here is reached.
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=debug_enter.alp -P typed_while_running.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
set(hooks
  click:debug.continue frames:5 status
  step "break OUT" "watch word[YAC]" "display word[XAC]" "info breakpoints" frames:2 status
  click:debug.continue frames:3 status step)
debug_commands(commands ${hooks})
set(args --debug --speed max --script ${SCRIPT} ${commands})
window_run(1400x900x24 ${args} --screenshot ${WORK}/shot.png)
string(REGEX MATCHALL "status: [a-z]+" statuses "${out}")
if(NOT statuses STREQUAL "status: running;status: running;status: stopped")
  message(FATAL_ERROR "running, still running after the lines typed, stopped after Pause: got ${statuses}")
endif()
foreach(want "\\(alp85\\) step\nThe machine is running: pause first"
             "\\(alp85\\) break OUT\nBreakpoint 1 at "
             "\\(alp85\\) watch word\\[YAC\\]\n[^\n]*atchpoint 2"
             "\\(alp85\\) display word\\[XAC\\]\n1: word\\[XAC\\] = "
             "\\(alp85\\) info breakpoints\nNum[^\n]*\n1 +breakpoint[^\n]*OUT")
  if(NOT out MATCHES "${want}")
    message(FATAL_ERROR "missing: ${want}")
  endif()
endforeach()
# The last step, typed after Pause, ran: no second "pause first".
string(REGEX MATCHALL "pause first" refusals "${out}")
list(LENGTH refusals n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "${n} refusals, expected the one while running")
endif()
