# Runs a script that records signals, then reads each VCD it wrote with sigrok-cli (Debian's
# sigrok-cli, scripts/setup.sh --tests) and with vcd_pulses.py:
#   -DALP85= -DSCRIPT= -DOUT= -DSIGROK= -DPYTHON= -DPULSES=vcd_pulses.py
#   -DVCDS=a.vcd;b.vcd           the files the script writes (in OUT), all read by sigrok-cli
#   -DCHECKS=a.vcd:PA0:3155:11;...   pin PIN of a.vcd: at least N high pulses, each T T-states long,
#                                 in the file and in sigrok-cli's rewrite of it
if(NOT SIGROK)
  message(FATAL_ERROR "sigrok-cli is missing: scripts/setup.sh --tests installs it")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/sigrok.cmake)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${ALP85} script ${SCRIPT} --out-dir ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 script ${SCRIPT}: exit ${rc}\n${out}${err}")
endif()
foreach(vcd ${VCDS})
  if(NOT EXISTS ${OUT}/${vcd})
    message(FATAL_ERROR "${SCRIPT} wrote no ${vcd}")
  endif()
  # (downsample=64: a 64 ns grid, a fifth of a T-state; a width read on it is off by less than 64 ns,
  # under half a T-state (163 ns), so widths still round to the exact T-states. sigrok-cli's time
  # is in the samples: 32 ns took 2.0 s of CPU for a recording of 11 pulses, 64 ns 1.1 s.)
  sigrok_read(${vcd} "" -I vcd:downsample=64 -i ${OUT}/${vcd} -O vcd -o ${OUT}/${vcd}.sigrok.vcd)
endforeach()
foreach(check ${CHECKS})
  string(REPLACE ":" ";" f ${check})
  list(GET f 0 vcd)
  list(GET f 1 pin)
  list(GET f 2 width)
  list(GET f 3 count)
  foreach(file ${OUT}/${vcd} ${OUT}/${vcd}.sigrok.vcd)
    execute_process(COMMAND ${PYTHON} ${PULSES} ${file} ${pin} --expect ${width} --count ${count}
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${err}")
    endif()
  endforeach()
endforeach()
# -DGTKW=gtkw_names.py;FILE.gtkw: the save file's signals are in the (first) VCD
if(GTKW)
  list(GET GTKW 0 names)
  list(GET GTKW 1 gtkw)
  list(GET VCDS 0 vcd)
  execute_process(COMMAND ${PYTHON} ${names} ${OUT}/${vcd} ${gtkw} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${err}")
  endif()
endif()
