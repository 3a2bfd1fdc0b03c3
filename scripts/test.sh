#!/usr/bin/env bash
# Builds ALP85 and runs every test through CTest.
#   scripts/test.sh               release build (-Werror) + all tests, then the same under ASan+UBSan
#   scripts/test.sh --fast        release build + all tests only
set -euo pipefail
cd "$(dirname "$0")/.."

sanitize=1
[ "${1:-}" = "--fast" ] && sanitize=0
jobs=$(nproc)

run_suite() {  # build dir, extra cmake args...
  local dir=$1; shift
  # Unity builds: each library and test program compiles in a few large units, so that the
  # headers every file includes (fmt, nlohmann-json, GoogleTest) are compiled once a unit, not
  # once a file (the build is most of this command's time on a fresh machine).
  cmake -S . -B "$dir" -G Ninja -DALP85_WERROR=ON -DCMAKE_UNITY_BUILD=ON "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
  (cd "$dir" && ctest --output-on-failure -j "$jobs")
}

echo "== release build and tests (build/)"
# ... which also makes the GUI's pictures in docs/img (tests/gui)
run_suite build -DCMAKE_BUILD_TYPE=Release -DALP85_DOC_IMAGES=ON

if [ $sanitize -eq 1 ]; then
  echo "== ASan + UBSan build and tests (build-asan/)"
  # fontconfig's process-lifetime caches are not leaks of ours (tests/lsan.supp)
  export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
  run_suite build-asan -DCMAKE_BUILD_TYPE=Release -DALP85_SANITIZE=ON -DALP85_BENCH=OFF
fi
