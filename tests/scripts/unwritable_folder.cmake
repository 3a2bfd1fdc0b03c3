# A script whose folder cannot be written (an installed example under /usr/share, run by a user)
# writes its files into the current folder and says so, instead of failing with "cannot write".
#   cmake -DALP85=<alp85> -DSCRIPT=<cases/writes_files.alp> -DWORK=<folder> -P unwritable_folder.cmake
# Two such folders:
#  1. /dev/fd, the script given as /dev/fd/3 (its descriptor): no one, root included, makes files
#     in /proc/self/fd, so this case is real when the tests run as root (CI does);
#  2. a folder of mode 555 holding a copy of the script, as /usr/share is to a user. Root writes
#     there all the same; then only case 1 stands, and this case says so.
set(files writes_files.csv writes_files.svg writes_files.snap)
function(check_outputs case out err)
  foreach(f ${files})
    if(NOT EXISTS ${WORK}/${f})
      message(FATAL_ERROR "${case}: ${f} is not in the current folder ${WORK}\n${out}${err}")
    endif()
  endforeach()
  if(NOT err MATCHES "note: its folder [^\n]* is not writable; the files it writes \\(save, record, plot\\) go to the current folder, ${WORK} ")
    message(FATAL_ERROR "${case}: no note of where the files went:\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND sh -c "exec \"$0\" script /dev/fd/3 3<\"$1\"" ${ALP85} ${SCRIPT}
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "/dev/fd/3: exit status ${rc}, expected 0\n${out}${err}")
endif()
check_outputs("/dev/fd/3" "${out}" "${err}")
message(STATUS "/dev/fd: the files went to the current folder")

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/installed)
file(COPY ${SCRIPT} DESTINATION ${WORK}/installed)
file(CHMOD ${WORK}/installed PERMISSIONS OWNER_READ OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
execute_process(COMMAND ${ALP85} script installed/writes_files.alp
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(CHMOD ${WORK}/installed DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mode 555: exit status ${rc}, expected 0\n${out}${err}")
endif()
if(EXISTS ${WORK}/installed/writes_files.snap)
  message(STATUS "mode 555: written all the same (root writes into any folder); the /dev/fd case stands for it")
else()
  check_outputs("mode 555" "${out}" "${err}")
  message(STATUS "mode 555: the files went to the current folder")
endif()
file(REMOVE_RECURSE ${WORK})
