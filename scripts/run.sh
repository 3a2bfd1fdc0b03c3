#!/usr/bin/env bash
# The main job: build ALP85 (which assembles the monitor and the other firmware sources), then
# start the board headless with its monitor: show the display after RESET, type R 7 0800 EXEC
# (thesis Appendix C: GO to 0800H) to run the demo program, and show the display again.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
echo
echo "Executables:  build/bin/ ($(ls build/bin | tr '\n' ' '))"
echo "Firmware:     $(find build/firmware -maxdepth 2 -name '*.hex' | sort | tr '\n' ' ')"
echo
build/bin/alp85 run firmware/demo/hello85.asm --keys "R 7 0800 EXEC"
