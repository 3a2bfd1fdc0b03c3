#!/usr/bin/env bash
# Copies the pictures the tests make in the build tree into docs/img, on request: the tests check
# each picture first (they run here), then it is copied.
#   signals:gtkwave-shot  GTKWave on the thesis's step pulses  -> docs/img/gtkwave-thesis.png
#   gui:signals-pane      the window's Signals pane at D = 1    -> docs/img/gui-signals.png
# (The other pictures of docs/img are written by their tests with -DALP85_DOC_IMAGES=ON.)
# Usage: bash scripts/doc-images.sh [BUILD_DIR]   (default build; alp85 and gui_pixels built there)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
if [ ! -f "$build/CTestTestfile.cmake" ]; then
  echo "scripts/doc-images.sh: no configured build in $build (cmake -S . -B build first)" >&2
  exit 2
fi
ctest --test-dir "$build" -R '^(signals:gtkwave-shot|gui:signals-pane)$' --output-on-failure
copy() {  # from (in the build tree), to (in docs/img)
  if [ ! -s "$build/$1" ]; then
    echo "scripts/doc-images.sh: $build/$1 was not made (is gtkwave, or xvfb-run, missing? scripts/setup.sh --tests)" >&2
    exit 1
  fi
  cp "$build/$1" "$root/docs/img/$2"
  echo "docs/img/$2 <- $1"
}
copy tests/signals/gtkwave/gtkwave-thesis.png gtkwave-thesis.png
copy tests/gui/signals-pane/signals-pane.png gui-signals.png
