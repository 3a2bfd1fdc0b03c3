# The source pane follows what the user asks for, also while the machine runs (the PC in the
# monitor's keyboard loop, the thesis firmware at its feed prompt): `list OUT` shows OUT's line
# (thesis.asm 707, OUT: LXI H,1B39H) centred, from 707 - 23/2 = 696; a click on row 13 (line 709,
# OUT's RLC) sets a breakpoint there; the file chooser shows monitor.asm from line 1; and after
# Pause and EXEC (the run stops at 709, inside OUT), a click on frame 1 of the call stack shows
# the caller at its CALL, as gdb and the console's `frame 1` do: thesis.asm 83's CALL OUT (the
# return address is the CALL INPUT on 84), shown from 83 - 11 = 72.
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=debug_enter.alp -P source_follows.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
set(hooks
  click:debug.continue frames:5 status
  "list OUT" frames:3 source clickrow:13 frames:3 "info breakpoints"
  click:debug.source-files frames:3 click:debug.source:monitor.asm frames:3 source
  click:debug.continue frames:3 status "press EXEC" frames:3
  "click:debug.tab:call stack" frames:3 click:debug.frame:1 frames:3 source)
debug_commands(commands ${hooks})
set(args --debug --speed max --script ${SCRIPT} ${commands})
window_run(1400x900x24 ${args} --screenshot ${WORK}/shot.png)
string(REGEX MATCHALL "status: [a-z]+" statuses "${out}")
if(NOT statuses STREQUAL "status: running;status: stopped")
  message(FATAL_ERROR "expected running, then stopped after Pause: ${statuses}")
endif()
string(REGEX MATCHALL "source: [^\n]*" shown "${out}")
if(NOT shown STREQUAL "source: thesis.asm from line 696;source: monitor.asm from line 1;source: thesis.asm from line 72")
  message(FATAL_ERROR "the source pane showed: ${shown}")
endif()
if(NOT out MATCHES "\\(alp85\\) info breakpoints\n[^(]*thesis\\.asm:709")
  message(FATAL_ERROR "the click on row 13 did not set a breakpoint at thesis.asm:709")
endif()
