# Plot without a recording plots the toolpath the window draws (the thesis line of thesis_line.alp,
# 200 x 150 steps), not "nothing recorded to plot". The file is a PNG of the chart's default size,
# 720 x 440 pixels (emu/plot/plot.h), read from its IHDR chunk (bytes 16-23, big-endian).
#   cmake -DXVFB_RUN=... -DALP85=... -DWORK=dir -DSCRIPT=thesis_line.alp -P plot_drawn.cmake
include(${CMAKE_CURRENT_LIST_DIR}/window.cmake)
window_test_begin()
window_run(1400x900x24 --debug --speed max --script ${SCRIPT}
           --debug-command toolpath --debug-command click:controls.plot --debug-command frames:3
           --screenshot ${WORK}/shot.png)
if(NOT out MATCHES "toolpath: [1-9][0-9]* points")
  message(FATAL_ERROR "no toolpath was drawn to plot")
endif()
if(NOT EXISTS ${WORK}/toolpath.png)
  message(FATAL_ERROR "Plot wrote no toolpath.png while the toolpath was drawn")
endif()
file(READ ${WORK}/toolpath.png header LIMIT 24 HEX)
string(SUBSTRING "${header}" 32 16 size)
if(NOT size STREQUAL "000002d0000001b8")
  message(FATAL_ERROR "toolpath.png is not a 720 x 440 PNG: IHDR size ${size}")
endif()
