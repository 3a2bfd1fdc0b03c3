# A man page from a program's own --help and --version, by help2man, so that the two cannot drift:
#   cmake -DPROGRAM=<exe> -DNAME=<name> -DWHAT=<one line> -DCOMMANDS=0|1 -DHELP2MAN=<help2man>
#         -DGZIP=<gzip> -DOUT=<name.1.gz> -P manpage.cmake
# With COMMANDS=1 (alp85), the page gets a COMMANDS section: a subsection per command (and per
# subcommand, as `alp85 bench cpu`) holding that command's --help, as printed.
get_filename_component(dir "${OUT}" DIRECTORY)
set(include "${dir}/${NAME}.h2m")
set(page "${dir}/${NAME}.1")

# The names listed under "Subcommands:" in a CLI11 help text.
function(subcommands_of help out)
  set(names "")
  set(inside FALSE)
  string(REPLACE "\n" ";" lines "${help}")
  foreach(line IN LISTS lines)
    if(line MATCHES "^Subcommands:")
      set(inside TRUE)
    elseif(inside AND line MATCHES "^  ([a-z][a-z0-9-]*)( |$)")
      list(APPEND names "${CMAKE_MATCH_1}")
    elseif(inside AND NOT line MATCHES "^ ")
      set(inside FALSE)
    endif()
  endforeach()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

# `PROGRAM args --help`, as roff that shows it as printed.
function(help_as_roff out)
  execute_process(COMMAND "${PROGRAM}" ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME} ${ARGN} --help failed (${rc}): ${err}")
  endif()
  set(help "${text}" PARENT_SCOPE)
  string(REPLACE "Usage: ${PROGRAM} " "Usage: ${NAME} " text "${text}")  # CLI11 prints argv[0]
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  string(REGEX REPLACE "\n+$" "" text "${text}")
  set(${out} ".nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

set(h2m "")
if(COMMANDS)
  execute_process(COMMAND "${PROGRAM}" --help OUTPUT_VARIABLE top RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NAME} --help failed (${rc})")
  endif()
  subcommands_of("${top}" commands)
  if(NOT commands)
    message(FATAL_ERROR "${NAME} --help lists no command")
  endif()
  string(APPEND h2m "[COMMANDS]\nEach command's options, as \\fB${NAME} \\fICOMMAND\\fB --help\\fR prints them.\n")
  foreach(cmd IN LISTS commands)
    help_as_roff(roff ${cmd})
    string(APPEND h2m ".SS \"${NAME} ${cmd}\"\n${roff}")
    subcommands_of("${help}" subs)
    foreach(sub IN LISTS subs)
      help_as_roff(roff ${cmd} ${sub})
      string(APPEND h2m ".SS \"${NAME} ${cmd} ${sub}\"\n${roff}")
    endforeach()
  endforeach()
  string(APPEND h2m "[FILES]\nUnder the installation prefix (\\fI/usr\\fR for the Debian package):\n"
         ".TP\n.I share/alp85/examples\nExample scripts (\\fB${NAME} script\\fR), G-code (\\fB${NAME} gcode\\fR) and Pisa tapes (\\fB${NAME} pisa\\fR).\n"
         ".TP\n.I share/alp85/firmware\nThe firmware built into ${NAME}: sources, Intel HEX images, listings and symbol maps.\n"
         ".TP\n.I share/doc/alp85\nThe manual: README.md and docs/.\n"
         ".TP\n.I ~/.alp85_debug_history\nThe history of the debugger's prompt.\n")
endif()
string(APPEND h2m "[SEE ALSO]\n.BR alp85 (1),\n.BR asm85 (1),\n.BR pisa-asm (1);\nthe manual in\n.I share/doc/alp85\nunder the installation prefix.\n")
file(WRITE "${include}" "${h2m}")

execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr --section=1 "--name=${WHAT}"
                        "--include=${include}" "--output=${page}" "${PROGRAM}"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  file(REMOVE "${page}")
  message(FATAL_ERROR "help2man ${NAME} failed (${rc}): ${err}")
endif()
execute_process(COMMAND "${GZIP}" -9nf "${page}" RESULT_VARIABLE rc)  # ${page}.gz, = OUT
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip ${page} failed")
endif()
