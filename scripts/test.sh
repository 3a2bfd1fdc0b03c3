#!/usr/bin/env bash
# Builds ALP85 and runs every test through CTest. Each test program is built and run once, under
# AddressSanitizer and UndefinedBehaviorSanitizer; the release build makes only what ships.
#   scripts/test.sh          1. build/: the release build of what ships (`shipped`: alp85, asm85,
#                               pisa-asm, the firmware, the man pages; -Werror) and the web page's
#                               module, at low priority beside step 2
#                            2. build-asan/ (clang): every test program, and every other test
#                            3. build/: the tests that need the shipped programs themselves (label
#                               `release`): the web page built and run in chromium, the Debian
#                               package, the chord sweep, the master firmware's runs
#   scripts/test.sh --fast   step 1, then every test in build/ without the sanitizers
# Screenshots land in the build trees; scripts/doc-images.sh refreshes docs/img on request.
set -euo pipefail
cd "$(dirname "$0")/.."

fast=0
case "${1:-}" in
  "") ;;
  --fast) fast=1 ;;
  *) echo "scripts/test.sh: unknown option $1 (--fast: no sanitizer pass)" >&2; exit 2 ;;
esac
jobs=$(nproc)

configure() {  # build dir, extra cmake args...
  local dir=$1; shift
  # Unity builds: each library and test program compiles in a few large units, so that the
  # headers every file includes (fmt, nlohmann-json, GoogleTest) are compiled once a unit, not
  # once a file (the build is most of this command's time on a fresh machine).
  cmake -S . -B "$dir" -G Ninja -DALP85_WERROR=ON -DCMAKE_UNITY_BUILD=ON "$@" >/dev/null
}

phase() { echo "== $* (at ${SECONDS} s)"; }
seed_costs() {  # build dir: ctest's cost data from tests/test-costs.txt, unless it has measured its own
  local data=$1/Testing/Temporary/CTestCostData.txt
  [ -f "$data" ] && return 0
  mkdir -p "$1/Testing/Temporary"
  { grep -v '^#' tests/test-costs.txt; echo ---; } > "$data"
}
configure build -DCMAKE_BUILD_TYPE=Release -DALP85_DOC_IMAGES=OFF
if [ $fast -eq 1 ]; then
  phase "release build and every test in build/, without the sanitizers"
  cmake --build build -j "$jobs"
  (cd build && ctest --output-on-failure -j "$jobs")
  exit 0
fi

# The release build runs beside the sanitizer pass at the lowest priority (nice 19): it takes the
# CPU the sanitizer pass leaves idle (links, and the tests that wait on Xvfb, the DAP client and
# Python) and does not slow the tests that time themselves against the wall clock. Its tests run
# after the sanitizer pass's, at normal priority (the web page's waits, the package's timeout).
# One job more than the cores: its last links, after the sanitizer pass, are single-threaded.
# It runs in a process group of its own (job control), ended with this script, and in this
# script's session: with the kernel's autogroups, a niceness counts only inside its session (under
# setsid the build took half the CPU). Its log is printed when it ends.
# The web page's module (web:build's compile, in build/web-build) is built there too, beside the
# release build, once asm85 has assembled the firmware the page carries: it fills the cores the
# release build's last, serial steps leave (its largest unit, its link, the man pages), and
# web:build then finds it built. Should it fail, web:build builds it again and says why.
release_log=build/release-build.log
web_log=build/web-build.log
release_build() {
  local native status=0
  native=$(cd build && pwd -P)
  cmake --build build -j "$((jobs + 1))" --target alp85_firmware_text monitor_embed firmware_sdk85test || return
  ALP85_NATIVE_BUILD=$native ALP85_WEB_OUT=$native/web ALP85_WERROR=ON scripts/web.sh --build > "$web_log" 2>&1 &
  local web_pid=$!
  cmake --build build -j "$((jobs + 1))" --target shipped || status=$?
  wait "$web_pid" || echo "scripts/test.sh: the web page's module did not build beside it ($web_log); web:build builds it again"
  return "$status"
}
phase "release build of what ships (build/) and the web page's module, beside the sanitizer pass; log: $release_log"
set -m
( set +m; renice -n 19 -p "$BASHPID" >/dev/null && release_build ) > "$release_log" 2>&1 &
release_pid=$!
set +m
trap 'kill -- -$release_pid 2>/dev/null || true' EXIT
trap 'exit 143' TERM INT

phase "ASan + UBSan build (build-asan/)"
# fontconfig's process-lifetime caches are not leaks of ours (tests/lsan.supp)
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
# A quarantine of 16 MB instead of ASan's 256: a use after free is still caught while the block is
# among the last 16 MB freed, and a test that allocates and frees much (reverse execution's
# snapshots, the DAP's messages) reuses its memory instead of mapping and faulting in fresh pages
# 64 KB at a time (one reverse-debugging test mapped 400 MB). The sanitizer pass's 60 longest tests:
# 215 CPU-s against 236 (docs/testing.md).
export ASAN_OPTIONS="quarantine_size_mb=16${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
# Clang compiles the instrumented build in about two thirds of GCC's CPU time (455 against 702
# CPU-s on a fresh clone), and its programs start in half the time (alp85: 0.13 against 0.26 s,
# most of GCC's in LeakSanitizer scanning UBSan's 31 MB of check descriptors at each exit).
# scripts/setup.sh --tests installs it; without it the pass is built with the default compiler.
sanitizer_compiler=()
if command -v clang++ >/dev/null && command -v clang >/dev/null; then
  sanitizer_compiler=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
else
  echo "scripts/test.sh: no clang++ (scripts/setup.sh --tests installs it): the sanitizer build uses $(c++ --version | head -1)"
fi
configure build-asan -DCMAKE_BUILD_TYPE=Release -DALP85_SANITIZE=ON -DALP85_BENCH=OFF "${sanitizer_compiler[@]}"
cmake --build build-asan -j "$jobs"
phase "ASan + UBSan tests"
# One test more than the cores: a sixth of the sanitizer pass waits (Xvfb and the window's frames,
# the DAP client, python drivers); the tests that time against wall time are RUN_SERIAL.
# The longest tests start first (tests/test-costs.txt), so that none of them is left running alone
# at the end.
seed_costs build-asan
asan_status=0
(cd build-asan && ctest --output-on-failure -j "$((jobs + 1))") || asan_status=$?

phase "waiting for the release build"
release_status=0
wait "$release_pid" || release_status=$?
trap - EXIT
tail -n 5 "$release_log"
if [ "$release_status" -ne 0 ]; then
  cat "$release_log"
  echo "scripts/test.sh: the release build failed (status $release_status)"
else
  phase "release tests (build/, label release)"
  # One test more than the cores: web:build's link and the package's lintian are single-threaded.
  (cd build && ctest --output-on-failure -j "$((jobs + 1))" -L release) || release_status=$?
fi
[ "$asan_status" -eq 0 ] || echo "scripts/test.sh: the sanitizer pass failed (status $asan_status)"
phase "done"
[ "$release_status" -eq 0 ] && [ "$asan_status" -eq 0 ]
