#!/usr/bin/env bash
# The main job: build ALP85 and assemble the firmware sources; say where the outputs are.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
echo
echo "Executables:  build/bin/"
ls -1 build/bin/ 2>/dev/null | sed 's/^/  /'
echo "Firmware:     build/firmware/"
find build/firmware -maxdepth 2 \( -name '*.hex' -o -name '*.lst' -o -name '*.json' -o -name '*.bin' \) 2>/dev/null | sort | sed 's/^/  /'
