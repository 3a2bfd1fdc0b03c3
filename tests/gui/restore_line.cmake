# Restore keeps the picture true (issue 33, item 13): the thesis line run to Bitti (X1,Y1 = 100,50
# to X2,Y2 = 300,200 steps: 10 mm in X, 7.5 mm in Y from where the table stood, 0,0), saved with
# the Controls' Save snapshot and restored with Restore, both clicked. Before: the ideal line of the
# move, 0,0 to 10,7.5 mm. After: the move is not known, and the line from where the table stands,
# 10,7.5 to 20,15 mm, was never commanded: no ideal line until the next move begins.
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=thesis_line.alp -P restore_line.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
debug_commands(commands toolpath click:controls.save frames:3 click:controls.restore frames:5 toolpath)
window_run(1400x900x24 --speed max --script ${SCRIPT} ${commands} --screenshot ${WORK}/shot.png)
string(REGEX MATCHALL "toolpath: [0-9]+ points, [^\n]*" lines "${out}")
list(LENGTH lines n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "expected two toolpath reports, got ${n}")
endif()
list(GET lines 0 before)
list(GET lines 1 after)
if(NOT before MATCHES "ideal line from 0,0 to 10,7.5 mm")
  message(FATAL_ERROR "before the restore: ${before}")
endif()
if(NOT EXISTS ${WORK}/alp85.snap)
  message(FATAL_ERROR "Save snapshot wrote no alp85.snap")
endif()
if(NOT after MATCHES "no ideal line")
  message(FATAL_ERROR "after restoring the snapshot at Bitti: ${after}")
endif()
