# alp85 gui --script runs the script at real time by default (the table seen moving, not only the
# end state): the window's wall time is at least the script's simulated time (less 10 % for the
# clocks' rounding), and frames were drawn all along it, at least 30 a second (half of the 60
# the frame clock aims at, for a loaded host).
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=thesis_line.alp -P real_time.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
window_run(1400x900x24 --stats --script ${SCRIPT} --screenshot ${WORK}/shot.png)
if(NOT out MATCHES "PASS [^\n]*\\(([0-9]+) T-states\\) simulated")
  message(FATAL_ERROR "the script did not pass")
endif()
set(tstates ${CMAKE_MATCH_1})
if(NOT out MATCHES "stats: ([0-9]+) frames in ([0-9]+)\\.([0-9]+) s")
  message(FATAL_ERROR "no --stats line")
endif()
set(frames ${CMAKE_MATCH_1})
# Wall time in ms (the stats give two decimals); simulated ms = T-states / 3072.
math(EXPR wall_ms "${CMAKE_MATCH_2} * 1000 + ${CMAKE_MATCH_3} * 10")
math(EXPR script_ms "${tstates} / 3072")
math(EXPR least_ms "${script_ms} * 9 / 10")
if(wall_ms LESS least_ms)
  message(FATAL_ERROR "the script's ${script_ms} ms simulated took ${wall_ms} ms of wall time: not real time")
endif()
math(EXPR least_frames "${script_ms} * 30 / 1000")
if(frames LESS least_frames)
  message(FATAL_ERROR "${frames} frames drawn over a ${script_ms} ms script, fewer than ${least_frames}")
endif()
