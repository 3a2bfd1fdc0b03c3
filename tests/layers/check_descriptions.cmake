# The CPU describes itself, as the parts do (docs/architecture.md, "The CPU's description"): the
# front ends keep no list of the 8085's flags or registers of their own, the board's keys have one
# enum, and the scripts start the thesis program through scripts/include/thesis_start.alp.
#   cmake -DROOT=<tree> -P check_descriptions.cmake
# Looked for in every .h and .cpp under emu/ and web/ except emu/core (the CPU's own folder):
#   - a flag-name table: a flag's name as a string of its own ("CY", "AC", "X5"), or the flags
#     formatted by hand ("AC={}");
#   - a register switch: `case ...::A:` ... `case ...::PSW:` over an enum of the registers;
# and in the whole tree, `{Matrix, Reset, Vect}` (the keypad's keys and the two beside it) once.
# In the scripts (*.alp) under scripts/ and tests/: the thesis key entry inline (reset, the
# monitor's sign-on, R 7 0800 EXEC, the Z prompt, comments between), not through the include;
# docs/scripting.md's example (scripts/docs/) shows those keys typed, on purpose.
cmake_policy(VERSION 3.16)  # lists keep empty elements; GLOB_RECURSE follows no symlinks
set(found "")
file(GLOB_RECURSE sources "${ROOT}/emu/*.h" "${ROOT}/emu/*.cpp" "${ROOT}/web/*.h" "${ROOT}/web/*.cpp")
foreach(src ${sources})
  file(RELATIVE_PATH rel "${ROOT}" "${src}")
  if(rel MATCHES "^emu/core/")
    continue()
  endif()
  file(STRINGS "${src}" lines REGEX "\"(CY|AC|X5)\"|AC=\\{")
  foreach(line ${lines})
    string(STRIP "${line}" line)
    string(REPLACE ";" "" line "${line}")  # a list's separator: the line stays one item
    list(APPEND found "${rel}: a flag-name table outside emu/core: ${line}")
  endforeach()
  file(STRINGS "${src}" lines REGEX "case [A-Za-z_:]*::(A|B|C|D|E|H|L|F|M|BC|DE|HL|SP|PC|PSW):")
  foreach(line ${lines})
    string(STRIP "${line}" line)
    string(REPLACE ";" "" line "${line}")  # a list's separator: the line stays one item
    list(APPEND found "${rel}: a register switch outside emu/core: ${line}")
  endforeach()
endforeach()

file(GLOB_RECURSE all "${ROOT}/emu/*.h" "${ROOT}/emu/*.cpp" "${ROOT}/web/*.h" "${ROOT}/web/*.cpp"
                      "${ROOT}/peripherals/*.h" "${ROOT}/peripherals/*.cpp")
set(key_enums "")
foreach(src ${all})
  file(STRINGS "${src}" lines REGEX "{ *Matrix *, *Reset *, *Vect *}")
  if(lines)
    file(RELATIVE_PATH rel "${ROOT}" "${src}")
    list(APPEND key_enums "${rel}")
  endif()
endforeach()
list(LENGTH key_enums n)
if(n GREATER 1)
  list(JOIN key_enums ", " text)
  list(APPEND found "${n} copies of the key enum {Matrix, Reset, Vect}: ${text}")
endif()

file(GLOB_RECURSE scripts "${ROOT}/scripts/*.alp" "${ROOT}/tests/*.alp")
set(comments "(#[^\n]*\n)*")
foreach(script ${scripts})
  file(RELATIVE_PATH rel "${ROOT}" "${script}")
  if(rel STREQUAL "scripts/include/thesis_start.alp" OR rel MATCHES "^scripts/docs/" OR rel MATCHES "^tests/layers/fixture")
    continue()
  endif()
  file(READ "${script}" text)
  if(text MATCHES "reset\n${comments}wait display \"-ALP 85-\"[^\n]*\n${comments}type R 7 0 8 0 0 EXEC\n${comments}wait display \"\\?\\.=----\"")
    list(APPEND found "${rel}: the thesis key entry inline (include thesis_start.alp)")
  endif()
endforeach()

if(found)
  list(JOIN found "\n  " text)
  message(FATAL_ERROR "the CPU's description, the key enum and the thesis start are not each one:\n  ${text}")
endif()
message(STATUS "descriptions: one flag table and no register switch outside emu/core, one key enum, the thesis start included")
