#!/usr/bin/env bash
# The main job: build ALP85's programs (which assembles the monitor, the thesis firmware in its two builds and
# the other firmware sources), then walk through thesis Appendix C headless on the reconstructed
# firmware (scripts/demo/thesis.alp): the display at each prompt, the line drawn by the simulated
# machine tool, the time it took, where the tables ended and the toolpath plot; then the same
# session on the build as printed (scripts/demo/thesis-as-printed.alp), which draws no line. With a
# display ($DISPLAY set, CI not true) it then opens alp85 gui on the same walk-through.
set -euo pipefail
cd "$(dirname "$0")/.."
# Only what ships (the `shipped` target: alp85, asm85, pisa-asm and the firmware), not the tests'
# programs; a unity build, as the test command's, so that the two share this folder.
echo "== building alp85, asm85 and the firmware (build/)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build -j "$(nproc)" --target shipped
out=build/run
echo
echo "Executables:  build/bin/ ($(ls build/bin | tr '\n' ' '))"
echo "Firmware:     $(find build/firmware -maxdepth 2 -name '*.hex' | sort | tr '\n' ' ')"
echo
echo "== thesis Appendix C on thesis-fixed (the errata repaired)"
build/bin/alp85 script scripts/demo/thesis.alp --out-dir "$out"
echo
echo "== the same session on the thesis firmware as printed"
build/bin/alp85 script scripts/demo/thesis-as-printed.alp --out-dir "$out"
echo
echo "Toolpath plot: $out/thesis-toolpath.svg (recording: $out/thesis-line.csv)"
# With a display (and not in CI): the same walk-through in the window, which stays open.
if [ -n "${DISPLAY:-}" ] && [ "${CI:-}" != "true" ]; then
  echo
  echo "== alp85 gui: the walk-through in a window (close it to end)"
  build/bin/alp85 gui --script scripts/demo/thesis.alp --out-dir "$out"
fi
