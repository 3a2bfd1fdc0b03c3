# gtest-verdicts:report: the launcher of alp85_gtests (tests/gtest_case.sh) reports each case of a
# run as GoogleTest decided it, on a program with a case of each verdict (tests/gtest_selftest.cpp).
#   cmake -DLAUNCHER=gtest_case.sh -DPROGRAM=gtest_selftest -DOUT=folder -P gtest_case_test.cmake
set(results ${OUT}/verdicts)
function(launch expect_status expect_output)  # launcher arguments after these two
  execute_process(COMMAND sh ${LAUNCHER} ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL expect_status)
    message(FATAL_ERROR "gtest_case.sh ${ARGN}: status ${status}, expected ${expect_status}:\n${out}${err}")
  endif()
  if(NOT out MATCHES "${expect_output}")
    message(FATAL_ERROR "gtest_case.sh ${ARGN}: output does not match '${expect_output}':\n${out}${err}")
  endif()
endfunction()
function(case name expect_status expect_output)
  launch(${expect_status} "${expect_output}" ${results} ${PROGRAM} --gtest_filter=${name} --gtest_also_run_disabled_tests)
endfunction()

# A run with a failed case: the run's test passes, each case says its own verdict, and the run's
# own verdict is that it ended (status 1, for the failed case).
launch(0 "FAILED" --run ${results} ${PROGRAM})
case(Verdicts.Passes 0 "^PASSED")
case(Verdicts.Fails 1 "^FAILED\n[^\n]*gtest_selftest.cpp:[0-9]+: Failure\n.*four is not five")
case(Verdicts.IsSkipped 0 "\\[  SKIPPED \\] Verdicts.IsSkipped")
case(Verdicts.MayCrash 0 "^PASSED")
case(Verdicts.RunsLast 0 "^PASSED")
case(Small/Sized.IsPositive/1 0 "^PASSED")
case(Verdicts.NoSuchCase 1 "no verdict")
launch(0 "cases failed" --exit ${results})
# The listing (gtest_discover_tests' build step) runs the program itself.
launch(0 "Verdicts\\.\n  Passes" ${results} ${PROGRAM} --gtest_list_tests)

# A run that ends in the middle: the cases before keep their verdicts, the later ones have none,
# and the run's own verdict fails with the program's output.
set(ENV{VERDICTS_CRASH} 1)
launch(0 "" --run ${results} ${PROGRAM})
case(Verdicts.Passes 0 "^PASSED")
case(Verdicts.RunsLast 1 "no verdict")
launch(1 "Verdicts.MayCrash.*ended with status" --exit ${results})
unset(ENV{VERDICTS_CRASH})

# A run whose every case passed: its own verdict passes; a run that never ran fails it.
launch(0 "" --run ${results} ${PROGRAM} --gtest_filter=Verdicts.Passes:Verdicts.RunsLast)
launch(0 "" --exit ${results})
file(REMOVE_RECURSE ${results})
launch(1 "did not end" --exit ${results})
