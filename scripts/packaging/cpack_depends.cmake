# The Debian package's Depends (CPACK_PROJECT_CONFIG_FILE, read by cpack before it packages):
# dpkg-shlibdeps on the three programs, as CPACK_DEBIAN_PACKAGE_SHLIBDEPS would do it, without
# that option's search for them: it runs `file` once for each of the package's 250 files, which
# took 15 of cpack's 16 s of CPU. The programs are the build tree's (CPACK_ALP85_PROGRAMS); the
# package's copies are the same files stripped, which link the same libraries.
if(NOT CPACK_GENERATOR STREQUAL "DEB")
  return()
endif()
find_program(ALP85_SHLIBDEPS dpkg-shlibdeps)
if(NOT ALP85_SHLIBDEPS)
  message(FATAL_ERROR "dpkg-shlibdeps is missing (package dpkg-dev): the package's Depends come from it")
endif()
foreach(program IN LISTS CPACK_ALP85_PROGRAMS)
  if(NOT EXISTS "${program}")
    message(FATAL_ERROR "${program} is not built: build the target shipped before packaging")
  endif()
endforeach()
# dpkg-shlibdeps reads debian/control in its working folder; an empty one will do.
set(work "${CPACK_PACKAGE_DIRECTORY}/_alp85_shlibdeps")
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}/debian")
file(WRITE "${work}/debian/control" "")
execute_process(COMMAND ${CMAKE_COMMAND} -E env LC_ALL=C ${ALP85_SHLIBDEPS} --ignore-missing-info -O
                        ${CPACK_ALP85_PROGRAMS}
                WORKING_DIRECTORY "${work}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err
                OUTPUT_STRIP_TRAILING_WHITESPACE)
file(REMOVE_RECURSE "${work}")
if(NOT status EQUAL 0 OR NOT out MATCHES "^shlibs:Depends=(.+)$")
  message(FATAL_ERROR "dpkg-shlibdeps on ${CPACK_ALP85_PROGRAMS} failed (status ${status}):\n${out}\n${err}")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${CMAKE_MATCH_1}")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
