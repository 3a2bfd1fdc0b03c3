# The Terminal pane (alp85 gui --serial 9600): echo85 runs at 9600 baud; "Hello, 85" is typed into
# the pane's input line as a keyboard types (text input events to the focused line), each character
# goes to SID, echo85 sends it back on SOD, and the pane shows it: the "terminal" hook prints the
# pane's text, and the screenshot has text in the pane's first row (the pane opens at the table
# view's lower left: x 536, y 280, 440 x 160; its first row of text at y 316-328, x from 552).
#   cmake -DXVFB_RUN=... -DALP85=... -DPIXELS=gui_pixels -DWORK=dir -DSCRIPT=echo85.alp -P terminal_pane.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
debug_commands(commands "serial:Hello, 85" frames:30 terminal)
window_run(1400x900x24 --serial 9600 --speed max --script ${SCRIPT} ${commands} --screenshot ${WORK}/shot.png)
if(NOT out MATCHES "\\[gui\\] terminal: Hello, 85\n")
  message(FATAL_ERROR "the Terminal pane does not show the echo of what was typed:\n${out}")
endif()
execute_process(COMMAND ${PIXELS} ${WORK}/shot.png --text-in 545,312,120,16 RESULT_VARIABLE rc OUTPUT_VARIABLE pout ERROR_VARIABLE perr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "no text in the Terminal pane's first row: ${pout}${perr}")
endif()
