# --scale 2 on a 1366x768 screen: the window opens at the largest size that fits (1133x708, as
# without --scale: tests/gui gui:screen-1366x768) and says so, instead of hanging off the edges.
#   cmake -DXVFB_RUN=... -DALP85=... -DPIXELS=... -DWORK=dir -P scale_fit.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
window_run(1366x768x24 --scale 2 --frames 20 --screenshot ${WORK}/shot.png)
if(NOT err MATCHES "--scale 2 \\(2560x1600\\) does not fit the screen \\(1366x768 usable\\): the window opens at 1133x708")
  message(FATAL_ERROR "no warning that --scale 2 does not fit: ${err}")
endif()
execute_process(COMMAND ${PIXELS} ${WORK}/shot.png --size 1133,708 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the window is not 1133x708")
endif()
