#!/bin/sh
# The tests of a GoogleTest program that runs once for all its cases (tests/CMakeLists.txt:
# alp85_gtests). Each case keeps a CTest test of its own, which reads the verdict that the run
# left for it (tests/gtest_results.cpp).
#   gtest_case.sh --run RESULTS PROGRAM [ARG...]  the run: every case, verdicts into RESULTS, the
#                                                 program's output and exit status beside them
#   gtest_case.sh --exit RESULTS                  the run's own verdict: it ended, and with status
#                                                 0, or 1 for failed cases only (no leak, no
#                                                 sanitizer report, no crash)
#   gtest_case.sh RESULTS PROGRAM --gtest_filter=CASE ...   a case's verdict (as the program's
#                                                 CROSSCOMPILING_EMULATOR, which gtest_discover_tests
#                                                 puts before each case's command)
#   gtest_case.sh RESULTS PROGRAM --gtest_list_tests         the listing: runs PROGRAM
set -u
case $1 in
  --run)
    results=$2
    shift 2
    rm -rf "$results" && mkdir -p "$results" || exit 1
    ALP85_GTEST_RESULTS=$results "$@" > "$results/.output" 2>&1
    echo $? > "$results/.status"
    grep -E '^\[  (PASSED|FAILED|SKIPPED) +\]|tests? ran' "$results/.output"
    exit 0 ;;
  --exit)
    results=$2
    if [ ! -f "$results/.status" ]; then
      echo "the run left no exit status in $results: it did not end"
      exit 1
    fi
    read -r status < "$results/.status"
    [ "$status" -eq 0 ] && exit 0
    if [ "$status" -eq 1 ] && [ -f "$results/.complete" ] && grep -rqx FAILED "$results"; then
      echo "cases failed (their own tests say how); the program ended normally"
      exit 0
    fi
    cat "$results/.output"
    echo "the run ended with status $status"
    exit 1 ;;
esac
results=$1
shift
case_name=
for arg in "$@"; do
  case $arg in --gtest_filter=*) case_name=${arg#--gtest_filter=} ;; esac
done
[ -n "$case_name" ] || exec "$@"
file=$results/$case_name
if [ -f "$file" ]; then
  # The shell's own read, not cat: this runs once for each of some 800 cases.
  verdict= first=1
  while IFS= read -r line || [ -n "$line" ]; do
    [ "$first" = 1 ] && verdict=$line first=0
    printf '%s\n' "$line"
  done < "$file"
  [ "$verdict" != FAILED ]
  exit
fi
echo "$case_name: no verdict: the program's run ended before this case did (its test ...:exit says why)"
exit 1
