# The Signals pane (emu/gui/signals_pane.h) at the thesis line with D = 1 (signals_d1.alp): port A's
# X step pulse on a logic analyzer, measured by its cursors and by the screenshot's pixels.
#   cmake -DXVFB_RUN=... -DALP85=... -DPIXELS=... -DWORK=dir -DSCRIPT=signals_d1.alp -P signals_pane.cmake
#
# The run stops at a breakpoint on DELAY's MOV A,C (DELAY+13: LDA 3 bytes, ANA 1, MOV 1, CALL 3,
# MOV 1, ANI 2, OUT 2), right after the OUT that ends the first X pulse. OUT is 10 T-states (opcode
# fetch 4, memory read 3, I/O write 3: 8085AH data sheet), and port A changes at the first T-state
# of its I/O write cycle, so the falling edge is 3 T-states before the stop. The pulse is high
# 3070*D + 85 = 3155 T-states (docs/thesis.md, "Timing"): the rising edge is 3158 before the stop.
#
# The pane shows the last 2 ms = 6144 T-states (3.072 MHz) over kSignalsTraceW = 640 pixels from
# x = 624 (layout.h), the stop at the right end (624 + 640 = 1264): an edge k T-states before the
# stop is at x = 1264 - 640 k / 6144. Rising: 1264 - 328.96 = 935.04; falling: 1264 - 0.31 = 1263.69.
# A click within kSnapPixels = 6 pixels of an edge takes the edge: cursor A is clicked at 933,
# cursor B at 1262, on PA0's row (row 0: y 96 to 122). Row 1 is the X sequencer's PULSE input,
# which follows PA0 through the board's wiring.
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
debug_commands(commands "break DELAY+13" "press EXEC" "expect PC == DELAY+13"
               "clickat:933,109" frames:2 "clickat:1262,109" frames:2 signals)
window_run(1400x900x24 --speed max --debug --signals PA0 X.PULSE X.A X.nA X.B X.nB --signals-ms 2
           --script ${SCRIPT} ${commands} --screenshot ${WORK}/signals-pane.png)
# 3155 T-states at 3.072 MHz: 3155 / 3.072 = 1027.018 us.
if(NOT out MATCHES "signals: A at T ([0-9]+), B at T ([0-9]+): B - A = 3155 T = 1027\\.018 ")
  string(REGEX MATCH "signals: [^\n]*" got "${out}")
  message(FATAL_ERROR "the cursors do not read the pulse's 3155 T-states (1027.018 us): ${got}")
endif()
# The pixels: PA0 and PULSE low before the rising edge (x 935.04), high after it up to the falling
# edge (1263.69), two pixels clear of each edge; the cursors' lines on the edges (each line is
# 2 pixels wide about x + 0.5: pixel 935 for A, 1264 for B).
execute_process(COMMAND ${PIXELS} ${WORK}/signals-pane.png
                        --signal 0,626,932,L --signal 0,938,1261,H --signal 1,626,932,L --signal 1,938,1261,H
                        --cursor A,935 --cursor B,1264
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the Signals pane's pixels are not as expected")
endif()
