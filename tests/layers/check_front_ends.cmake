# Fails when a front end (the window, DAP, the page, their shared library emu/front) drives the
# board around the Session: its own boot (the Machine's reset, load_image, a symbol table's
# add_table), its own keys (schedule_key, schedule_press on the Machine), its own sampler or motor
# model; or reaches the Machine at all (a call of machine(): state is read and written through the
# Session and the Debugger). And when alp85 run builds script Commands or runs them through the
# interpreter instead of making the Session's typed calls. Run as
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
# alp85 run is a client of the Session's typed API: no Command built, none executed, no Machine.
set(typed_clients emu/cli/cmd_run.cpp)
set(typed_patterns
    "(^|[^A-Za-z0-9_])(script::)?Command[ ({>&]|Op::[A-Z][A-Za-z]*" "a script Command built by hand"
    "(^|[^A-Za-z0-9_])(execute|check)\\(" "a Command run through the interpreter"
    "(^|[^A-Za-z0-9_])machine\\(\\)" "the Machine reached around the Session")

set(found "")
# Appends to `found` every line of `sources` (full paths) matching one of the (regex, what) pairs.
function(scan sources)
  set(pairs ${ARGN})
  list(LENGTH pairs n)
  math(EXPR last "${n} - 1")
  foreach(src ${sources})
    if(NOT EXISTS "${src}")
      continue()
    endif()
    file(STRINGS "${src}" lines)
    file(RELATIVE_PATH rel "${ROOT}" "${src}")
    foreach(i RANGE 0 ${last} 2)
      math(EXPR j "${i} + 1")
      list(GET pairs ${i} re)
      list(GET pairs ${j} what)
      foreach(line ${lines})
        if(line MATCHES "${re}")
          string(STRIP "${CMAKE_MATCH_0}" call)
          list(APPEND found "${rel}: ${what}: ${call}")
        endif()
      endforeach()
    endforeach()
  endforeach()
  set(found "${found}" PARENT_SCOPE)
endfunction()
foreach(folder ${folders})
  file(GLOB_RECURSE sources "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  scan("${sources}" ${patterns})
endforeach()
list(TRANSFORM typed_clients PREPEND "${ROOT}/")
scan("${typed_clients}" ${typed_patterns})
if(found)
  list(JOIN found "\n  " text)
  message(FATAL_ERROR "front ends around the Session:\n  ${text}")
endif()
message(STATUS "front ends: every boot, key and read through the Session; alp85 run through its typed calls")
