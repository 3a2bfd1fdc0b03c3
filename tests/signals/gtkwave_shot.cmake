# GTKWave on the thesis's step pulses, as docs/signals.md shows them: docs/signals/thesis.alp records
# the thesis line at D = 2 (750 mm/min, physical motors) to thesis.vcd, GTKWave opens it with
# docs/signals/thesis.gtkw under Xvfb and gtkwave_shot.tcl grabs its window (File > Grab To File) into
# ${OUT}/gtkwave-thesis.png, in the build tree (scripts/doc-images.sh copies it to docs/img).
#   cmake -DALP85= -DGTKWAVE= -DXVFB_RUN= -DSRC=(source root) -DOUT=(scratch) -P gtkwave_shot.cmake
# GTKWave's own reading of the file is checked: port A's first pulse, between the edges it finds,
# is 3070*D + 85 = 6225 T-states (docs/thesis.md, "Timing"): round(ns * 3072000 / 1e9).
if(NOT GTKWAVE OR NOT XVFB_RUN)
  message("SKIP: gtkwave or xvfb-run is missing (scripts/setup.sh --tests installs both)")
  return()
endif()
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${ALP85} script ${SRC}/docs/signals/thesis.alp --out-dir ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/thesis.vcd)
  message(FATAL_ERROR "docs/signals/thesis.alp: exit ${rc}\n${out}${err}")
endif()
set(shot ${OUT}/gtkwave-thesis.png)
execute_process(COMMAND ${CMAKE_COMMAND} -E env ALP85_SHOT=${shot}
                        ${XVFB_RUN} -a -s "-screen 0 1440x900x24"
                        ${GTKWAVE} --script ${SRC}/tests/signals/gtkwave_shot.tcl ${OUT}/thesis.vcd ${SRC}/docs/signals/thesis.gtkw
                WORKING_DIRECTORY ${OUT} TIMEOUT 120 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gtkwave: exit ${rc}\n${err}")
endif()
if(NOT out MATCHES "PULSE ([0-9]+) ([0-9]+)")
  message(FATAL_ERROR "GTKWave found no pulse on PA0:\n${out}${err}")
endif()
math(EXPR ns "${CMAKE_MATCH_2} - ${CMAKE_MATCH_1}")
math(EXPR tstates "(${ns} * 3072000 + 500000000) / 1000000000")
if(NOT tstates EQUAL 6225)
  message(FATAL_ERROR "GTKWave reads port A's first pulse as ${ns} ns = ${tstates} T-states, not 3070*2 + 85 = 6225")
endif()
# A PNG (its signature), at least as large as the wave window needs: IHDR's width and height.
if(NOT EXISTS ${shot})
  message(FATAL_ERROR "GTKWave wrote no ${shot}")
endif()
file(READ ${shot} head LIMIT 24 HEX)
string(SUBSTRING "${head}" 0 16 signature)
string(SUBSTRING "${head}" 32 8 w)
string(SUBSTRING "${head}" 40 8 h)
math(EXPR w "0x${w}")
math(EXPR h "0x${h}")
if(NOT signature STREQUAL "89504e470d0a1a0a" OR w LESS 1000 OR h LESS 600)
  message(FATAL_ERROR "${shot} is not the window's picture (signature ${signature}, ${w} x ${h})")
endif()
message(STATUS "GTKWave: port A's pulse ${ns} ns = ${tstates} T-states; ${shot} ${w} x ${h}")
