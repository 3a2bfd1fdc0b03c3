# The serial line on SID/SOD (docs/signals.md): firmware/demo/echo85.asm, started at the entry of
# a rate, echoes what `alp85 run --serial BAUD` sends it from standard input; standard output is
# exactly that text (the run goes on 100 ms after the last character sent: the terminal takes the
# echo of the last one 9 bits after it, 82 ms at 110 baud). The same run records SOD (--vcd --pins SOD), and
# sigrok-cli's UART decoder (Debian's sigrok-cli, scripts/setup.sh --tests) reads the same text
# from the file.
#   cmake -DALP85= -DECHO=echo85.asm -DBAUD=9600 -DENTRY=0800 -DTEXT=... -DOUT=dir -DSIGROK= -P serial_echo.cmake
if(NOT SIGROK)
  message(FATAL_ERROR "sigrok-cli is missing: scripts/setup.sh --tests installs it")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/sigrok.cmake)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
file(WRITE ${OUT}/input.txt "${TEXT}")
execute_process(COMMAND ${ALP85} run ${ECHO} --keys "R 7 ${ENTRY} EXEC" --serial ${BAUD} --for 100ms
                        --vcd ${OUT}/sod.vcd --pins SOD
                INPUT_FILE ${OUT}/input.txt RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "alp85 run --serial ${BAUD}: exit ${rc}\n${out}${err}")
endif()
if(NOT out STREQUAL TEXT)
  message(FATAL_ERROR "alp85 run --serial ${BAUD} wrote '${out}', expected the text sent, '${TEXT}'\n${err}")
endif()
if(err MATCHES "serial: ")
  message(FATAL_ERROR "errors on the line:\n${err}")
endif()
# The report (display, time) went to standard error, beside the line's text.
if(NOT err MATCHES "after R 7 ${ENTRY} EXEC:" OR NOT err MATCHES "simulated, PC=")
  message(FATAL_ERROR "no report on standard error:\n${err}")
endif()

# sigrok-cli: the VCD's SOD channel through its UART decoder at the same rate and frame. The file's
# unit is 1 ns; downsample=1000 reads it on a 1 us grid (a 9600-baud bit is 104 us), so that 110
# baud's second of recording is a million samples, not a thousand million.
sigrok_read(sod.vcd decoded -I vcd:downsample=1000 -i ${OUT}/sod.vcd
            -P uart:rx=SOD:baudrate=${BAUD}:data_bits=8:parity=none:stop_bits=1.0 -A uart=rx-data)
# One line per character, "uart-1: 48" (hex; at log level 5 with the samples and the annotation's
# name: "933639-934473 uart-1: rx-data: "48""); the text sent, as hex, for comparison.
string(REGEX MATCHALL "uart-1: (rx-data: \")?[0-9A-Fa-f][0-9A-Fa-f]" lines "${decoded}")
set(got "")
foreach(l ${lines})
  string(LENGTH "${l}" n)
  math(EXPR at "${n} - 2")
  string(SUBSTRING "${l}" ${at} 2 h)
  string(TOUPPER "${h}" h)
  string(APPEND got "${h}")
endforeach()
string(HEX "${TEXT}" want)
string(TOUPPER "${want}" want)
if(NOT got STREQUAL want)
  message(FATAL_ERROR "sigrok-cli's UART decoder read ${got} from SOD at ${BAUD} baud, alp85 run --serial wrote ${want}\n${decoded}")
endif()
message(STATUS "${BAUD} baud: '${TEXT}' echoed; sigrok-cli decodes ${got} from SOD")
