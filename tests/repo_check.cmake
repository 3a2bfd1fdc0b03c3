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
