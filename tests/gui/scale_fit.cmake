# --scale 2 on a 1366x768 screen: the window opens at the largest size that fits (1133x708, as
# without --scale: tests/gui gui:screen-1366x768) and says so, instead of hanging off the edges.
#   cmake -DXVFB_RUN=... -DALP85=... -DPIXELS=... -DWORK=dir -P scale_fit.cmake
if(NOT XVFB_RUN)
  message("SKIP: xvfb-run is missing: install xvfb (scripts/setup.sh does) to run the GUI tests")
  return()
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 1366x768x24" ${ALP85} gui --scale 2 --frames 20 --screenshot ${WORK}/shot.png
                OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 gui exited with ${rc}: ${err}")
endif()
if(NOT err MATCHES "--scale 2 \\(2560x1600\\) does not fit the screen \\(1366x768 usable\\): the window opens at 1133x708")
  message(FATAL_ERROR "no warning that --scale 2 does not fit: ${err}")
endif()
execute_process(COMMAND ${PIXELS} ${WORK}/shot.png --size 1133,708 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the window is not 1133x708")
endif()
