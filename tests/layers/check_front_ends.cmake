# Fails when a front end (the window, DAP, the page, their shared library emu/front) drives the
# board around the Session: its own boot (the Machine's reset, load_image, a symbol table's
# add_table), its own keys (schedule_key, schedule_press on the Machine), its own sampler or motor
# model; or reaches the Machine at all (a call of machine(): state is read and written through the
# Session and the Debugger). Run as
#   cmake -DROOT=<tree> -P check_front_ends.cmake
cmake_minimum_required(VERSION 3.20)  # list() keeps empty elements (CMP0007)
set(folders emu/front emu/gui emu/dap web)
set(patterns
    "(^|[^A-Za-z0-9_])(m|machine\\(\\))\\.reset\\(\\)" "the Machine's reset"
    "(^|[^A-Za-z0-9_.>])load_image\\(" "load_image on the Machine"
    "add_table\\(" "add_table"
    "schedule_(key|press)\\(" "a key scheduled on the Machine"
    "set_sampler\\(" "a sampler on the Machine"
    "tool\\(\\)\\.set_model\\(" "the motor model set on the tool"
    "(^|[^A-Za-z0-9_])machine\\(\\)" "the Machine reached around the Session")
list(LENGTH patterns n)
math(EXPR last "${n} - 1")
set(found "")
foreach(folder ${folders})
  file(GLOB_RECURSE sources "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  foreach(src ${sources})
    file(STRINGS "${src}" lines)
    file(RELATIVE_PATH rel "${ROOT}" "${src}")
    foreach(i RANGE 0 ${last} 2)
      math(EXPR j "${i} + 1")
      list(GET patterns ${i} re)
      list(GET patterns ${j} what)
      foreach(line ${lines})
        if(line MATCHES "${re}")
          string(STRIP "${CMAKE_MATCH_0}" call)
          list(APPEND found "${rel}: ${what}: ${call}")
        endif()
      endforeach()
    endforeach()
  endforeach()
endforeach()
if(found)
  list(JOIN found "\n  " text)
  message(FATAL_ERROR "front ends around the Session:\n  ${text}")
endif()
message(STATUS "front ends: every boot, key and read through the Session")
