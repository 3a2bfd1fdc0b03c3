# Facts about the repository itself: a LICENSE file that README.md names.
#   cmake -DROOT=<source dir> -P repo_check.cmake
if(NOT EXISTS ${ROOT}/LICENSE)
  message(FATAL_ERROR "no LICENSE file")
endif()
file(READ ${ROOT}/LICENSE licence)
if(NOT licence MATCHES "^MIT License\n" OR NOT licence MATCHES "Permission is hereby granted, free of charge")
  message(FATAL_ERROR "LICENSE is not the MIT License text")
endif()
file(READ ${ROOT}/README.md readme)
if(NOT readme MATCHES "## Licence" OR NOT readme MATCHES "MIT License \\(\\[LICENSE\\]\\(LICENSE\\)\\)")
  message(FATAL_ERROR "README.md does not state the licence")
endif()
# What the docs must say (issue #11): the undriven 8155 inputs, what `expect port` checks on an
# input port, the decision on the 8155 timer's read-back, the rules for addresses, image regions
# and the folder snapshots are read from and written to.
foreach(pair
    "docs/board.md|Undriven 8155 inputs"
    "docs/board.md|port A programmed as input reads \\*\\*FFH\\*\\*; port C's six pins \\(PC0-PC5\\) read \\*\\*3FH\\*\\*"
    "docs/scripting.md|On a port programmed as input it checks that latch all the same"
    "docs/scripting.md|a bare number with a leading zero"
    "docs/scripting.md|is \\*\\*refused\\*\\*, a script error; a `.hex` or `.asm` image that does so is loaded with a \\*\\*warning\\*\\*"
    "docs/scripting.md|relative to the \\*\\*script's folder\\*\\* \\(not the working directory\\), for writing as well as reading"
    "docs/peripherals.md|Read-back in the pulse modes: kept as N - e")
  string(REPLACE "|" ";" parts "${pair}")
  list(GET parts 0 doc)
  list(GET parts 1 want)
  file(READ ${ROOT}/${doc} text)
  if(NOT text MATCHES "${want}")
    message(FATAL_ERROR "${doc} does not say: ${want}")
  endif()
endforeach()
