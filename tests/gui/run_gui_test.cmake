# Runs `alp85 gui` under xvfb-run and then gui_pixels on its screenshot.
#   cmake -DXVFB_RUN=... -DALP85=... -DPIXELS=... -DSHOT=out.png -DGUI_ARGS="a;b" -DPIXEL_ARGS="c;d" -P run_gui_test.cmake
# Prints "SKIP: xvfb-run is missing" (the test's SKIP_REGULAR_EXPRESSION) when there is no xvfb-run.
if(NOT XVFB_RUN)
  message("SKIP: xvfb-run is missing: install xvfb (scripts/setup.sh --tests does) to run the GUI tests")
  return()
endif()
file(REMOVE "${SHOT}")
if(NOT SCREEN)
  set(SCREEN 1400x900x24)
endif()
execute_process(COMMAND ${XVFB_RUN} -a -s "-screen 0 ${SCREEN}" ${ALP85} gui ${GUI_ARGS} --screenshot ${SHOT}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 gui exited with ${rc}")
endif()
execute_process(COMMAND ${PIXELS} ${SHOT} ${PIXEL_ARGS} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the screenshot's pixels are not as expected")
endif()
# A screenshot of the documentation (docs/img): replaced only by one whose pixels were checked.
if(DOC_COPY)
  configure_file(${SHOT} ${DOC_COPY} COPYONLY)
endif()
