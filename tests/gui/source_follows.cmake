# The source pane follows what the user asks for, also while the machine runs (the PC in the
# monitor's keyboard loop, the thesis firmware at its feed prompt): `list OUT` shows OUT's line
# (thesis.asm 707, OUT: LXI H,1B39H) centred, from 707 - 23/2 = 696; a click on row 13 (line 709,
# OUT's RLC) sets a breakpoint there; the file chooser shows monitor.asm from line 1; and after
# Pause and EXEC (the run stops at 709, inside OUT), a click on frame 1 of the call stack shows
# the caller's line: OUT's return address is the CALL INPUT after thesis.asm 83's CALL OUT, line
# 84, shown from 84 - 11 = 73.
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=debug_enter.alp -P source_follows.cmake
if(NOT XVFB_RUN)
  message("SKIP: xvfb-run is missing: install xvfb (scripts/setup.sh does) to run the GUI tests")
  return()
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(hooks
  click:debug.continue frames:5 status
  "list OUT" frames:3 source clickrow:13 frames:3 "info breakpoints"
  click:debug.source-files frames:3 click:debug.source:monitor.asm frames:3 source
  click:debug.continue frames:3 status "press EXEC" frames:3
  "click:debug.tab:call stack" frames:3 click:debug.frame:1 frames:3 source)
set(args --debug --speed max --script ${SCRIPT})
foreach(h IN LISTS hooks)
  list(APPEND args --debug-command "${h}")
endforeach()
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1400x900x24" ${ALP85} gui ${args} --screenshot ${WORK}/shot.png
                WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 gui exited with ${rc}: ${err}")
endif()
string(REGEX MATCHALL "status: [a-z]+" statuses "${out}")
if(NOT statuses STREQUAL "status: running;status: stopped")
  message(FATAL_ERROR "expected running, then stopped after Pause: ${statuses}")
endif()
string(REGEX MATCHALL "source: [^\n]*" shown "${out}")
if(NOT shown STREQUAL "source: thesis.asm from line 696;source: monitor.asm from line 1;source: thesis.asm from line 73")
  message(FATAL_ERROR "the source pane showed: ${shown}")
endif()
if(NOT out MATCHES "\\(alp85\\) info breakpoints\n[^(]*thesis\\.asm:709")
  message(FATAL_ERROR "the click on row 13 did not set a breakpoint at thesis.asm:709")
endif()
