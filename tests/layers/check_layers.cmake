# Fails when a lower layer includes a higher one (docs/architecture.md). Run as
#   cmake -DROOT=<tree> -P check_layers.cmake
# Each folder may include only the folders listed for it (and the standard library and Debian
# packages, which are not checked). A front end (emu/cli, web) is included by nothing.
set(allowed_asm          "asm/")
set(allowed_emu/util     "emu/util/")
set(allowed_emu/core     "emu/core/;peripherals/state_io.h;asm/isa.h")
set(allowed_peripherals  "peripherals/")
set(allowed_emu/board    "emu/board/;emu/core/;emu/util/;peripherals/;asm/files/")
set(allowed_emu/program  "emu/program/;emu/board/;emu/core/;emu/util/;peripherals/;asm/")
set(allowed_emu/plot     "emu/plot/;emu/util/")
set(allowed_emu/gcode    "emu/gcode/;emu/util/")
set(allowed_emu/pisa     "emu/pisa/;emu/util/;emu/plot/;peripherals/;asm/pisa_isa.h")
set(allowed_emu/debug    "emu/debug/;emu/program/;emu/board/;emu/core/;emu/util/;emu/plot/;peripherals/;asm/")
set(allowed_emu/script   "emu/script/;emu/debug/;emu/program/;emu/board/;emu/core/;emu/util/;emu/plot/;peripherals/;asm/files/;asm/isa.h")
set(allowed_emu/cpm      "emu/cpm/;emu/program/ihex.h;emu/core/;emu/util/;asm/isa.h")
set(allowed_emu/bench    "emu/bench/;emu/dap/;emu/front/;emu/script/;emu/debug/;emu/program/;emu/board/;emu/core/;emu/util/;emu/plot/;peripherals/;asm/")
# The front ends (the window, DAP, the web page) reach the board only through the Session and the
# Debugger, and the library they share (emu/front: keys, the pacer, the toolpath, views of the
# display and the tool): nothing of emu/board, emu/core or peripherals/ (docs/architecture.md).
set(allowed_emu/front    "emu/front/;emu/script/;emu/debug/")
set(allowed_emu/gui      "emu/gui/;emu/front/;emu/script/;emu/debug/;emu/program/;emu/util/;emu/plot/;asm/files/;asm/isa.h")
set(allowed_emu/dap      "emu/dap/;emu/front/;emu/script/;emu/debug/;emu/program/;emu/util/;emu/plot/;asm/isa.h")
# The web page's binding: a front end as thin as the window, on the same shared library, none of SDL's.
set(allowed_web          "web/;emu/front/;emu/script/;emu/debug/;emu/program/;emu/util/;emu/gcode/;asm/asm85.h;asm/isa.h")
set(layers asm emu/util emu/core peripherals emu/board emu/program emu/plot emu/gcode emu/pisa emu/debug emu/script emu/front emu/cpm emu/bench emu/gui emu/dap web)

set(violations "")
foreach(layer ${layers})
  file(GLOB_RECURSE sources "${ROOT}/${layer}/*.h" "${ROOT}/${layer}/*.cpp")
  foreach(src ${sources})
    file(STRINGS "${src}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"")
    foreach(line ${includes})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([^\"]+)\".*" "\\1" inc "${line}")
      # Only project headers named from the root are checked (generated *_embed.h are local).
      if(NOT inc MATCHES "^(asm|emu|peripherals)/")
        continue()
      endif()
      set(ok FALSE)
      foreach(prefix ${allowed_${layer}})
        string(LENGTH "${prefix}" n)
        string(SUBSTRING "${inc}" 0 ${n} head)
        if(head STREQUAL prefix)
          set(ok TRUE)
        endif()
      endforeach()
      if(NOT ok)
        file(RELATIVE_PATH rel "${ROOT}" "${src}")
        list(APPEND violations "${rel}: layer ${layer} includes ${inc}")
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
message(STATUS "layers: every include points down")
