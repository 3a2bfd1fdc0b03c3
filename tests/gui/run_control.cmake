# Run control in the window (issue 22): the debugger's Continue stops at each hit of a breakpoint,
# Pause ends a free run promptly, the Controls' Run keeps running, Plot draws what Record
# recorded, and a refused Restore leaves the drawn toolpath. Every button is clicked with
# synthesized mouse events where it was drawn.
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=debug_enter.alp -P run_control.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
set(hooks
  "break OUT" "keydown EXEC"
  click:debug.continue frames:90 click:debug.continue frames:60 "info breakpoints"
  delete click:debug.continue frames:20 click:debug.continue frames:3 status
  click:controls.run frames:5 click:controls.record frames:40 toolpath
  click:controls.restore frames:2 toolpath click:controls.plot frames:3 status)
debug_commands(commands ${hooks})
set(args --debug --script ${SCRIPT} ${commands})
window_run(1400x900x24 ${args} --screenshot ${WORK}/shot.png)
# Continue, Continue: two stops at OUT, the second on its next hit.
string(REGEX MATCHALL "Breakpoint 1, OUT" hits "${out}")
list(LENGTH hits n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "Continue stopped ${n} times at OUT, not 2")
endif()
if(NOT out MATCHES "breakpoint already hit 2 times")
  message(FATAL_ERROR "OUT's breakpoint was not hit exactly twice")
endif()
# Pause: within 100 ms of wall time of the click (the press, two frames for ImGui's click, the run's slice).
if(NOT out MATCHES "paused ([0-9.]+) ms after the request")
  message(FATAL_ERROR "Pause did not stop the run")
endif()
if(NOT CMAKE_MATCH_1 LESS 100)
  message(FATAL_ERROR "Pause took ${CMAKE_MATCH_1} ms")
endif()
string(REGEX MATCHALL "status: [a-z]+ t=[0-9]+" statuses "${out}")
list(GET statuses 0 after_pause)
list(GET statuses 1 after_run)
if(NOT after_pause MATCHES "stopped" OR NOT after_run MATCHES "running")
  message(FATAL_ERROR "after Pause: ${after_pause}; after Controls > Run and ~50 frames: ${after_run}")
endif()
string(REGEX MATCH "t=([0-9]+)" _ "${after_pause}")
set(t0 ${CMAKE_MATCH_1})
string(REGEX MATCH "t=([0-9]+)" _ "${after_run}")
math(EXPR ran "${CMAKE_MATCH_1} - ${t0}")
# About 50 frames at real time is ~0.8 s: well over one frame's 51 200 T-states.
if(ran LESS 500000)
  message(FATAL_ERROR "Controls > Run ran only ${ran} T-states over ~50 frames")
endif()
# A refused Restore (no alp85.snap here) leaves the toolpath; Plot writes what was recorded.
string(REGEX MATCHALL "toolpath: ([0-9]+) points" paths "${out}")
list(GET paths 0 p0)
list(GET paths 1 p1)
string(REGEX MATCH "[0-9]+" n0 "${p0}")
string(REGEX MATCH "[0-9]+" n1 "${p1}")
if(n0 EQUAL 0 OR n1 LESS n0)
  message(FATAL_ERROR "the toolpath had ${n0} points, then ${n1} after a refused Restore")
endif()
if(NOT EXISTS ${WORK}/toolpath.png)
  message(FATAL_ERROR "Plot wrote no toolpath.png")
endif()
