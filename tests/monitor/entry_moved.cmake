# Checks that the monitor's fixed entry points are enforced at assembly time: for each one, a
# copy of monitor.asm gets 200H more bytes just before it, and asm85 must refuse it with the
# message that names the entry point.
#   cmake -DASM85=... -DSOURCE_DIR=firmware/monitor -DWORK=dir -P entry_moved.cmake
file(READ "${SOURCE_DIR}/monitor.asm" text)
file(MAKE_DIRECTORY "${WORK}")
file(COPY "${SOURCE_DIR}/monitor.inc" DESTINATION "${WORK}")
foreach(entry "AUS at 05A8H|overruns AUS \\(05A8H\\)"
              "UMW at 05C9H|overruns UMW \\(05C9H\\)"
              "ANWEIN at 0701H|overruns ANWEIN \\(0701H\\)"
              "ANWAZL at 07BCH|overruns ANWAZL \\(07BCH\\)"
              "ANWAUS at 07C7H|overruns ANWAUS \\(07C7H\\)")
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 marker)
  list(GET parts 1 message)
  string(FIND "${text}" "; ---- ${marker}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "monitor.asm has no section '${marker}'")
  endif()
  string(REPLACE "; ---- ${marker}" "        DS      200H,0\n; ---- ${marker}" moved "${text}")
  string(REPLACE " " "_" name "${marker}")
  file(WRITE "${WORK}/${name}.asm" "${moved}")
  execute_process(COMMAND "${ASM85}" "${WORK}/${name}.asm" -o "${WORK}/${name}.hex"
                  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
  if(rc EQUAL 0)
    message(FATAL_ERROR "asm85 accepted a monitor whose ${marker} moved")
  endif()
  if(NOT err MATCHES "${message}")
    message(FATAL_ERROR "asm85 refused the moved ${marker} without saying so:\n${err}")
  endif()
endforeach()
# The unchanged source assembles.
file(WRITE "${WORK}/monitor.asm" "${text}")
execute_process(COMMAND "${ASM85}" "${WORK}/monitor.asm" -o "${WORK}/monitor.hex" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the unchanged monitor does not assemble:\n${err}")
endif()
