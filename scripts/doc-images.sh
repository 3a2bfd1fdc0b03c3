#!/usr/bin/env bash
# Refreshes the pictures of docs/img, on request (the test command writes its screenshots into the
# build tree only). Each picture is made by its test, which checks it first, then copied:
#   gui:screen-1366x768, gui:scale-2x, gui:debugger-panes  the window     -> docs/img/gui-*.png
#   signals:timing-cli     the bus-cycle diagrams of docs/signals.md      -> docs/img/timing-*.svg
#   signals:gtkwave-shot   GTKWave on the thesis's step pulses            -> docs/img/gtkwave-thesis.png
#   gui:signals-pane       the window's Signals pane at D = 1             -> docs/img/gui-signals.png
#   --web: web:build, web:page  the page (docs/web.md)                     -> docs/img/web-*.png
# Usage: bash scripts/doc-images.sh [--web] [BUILD_DIR]   (default build/, configured or not)
# Needs what scripts/setup.sh --tests installs (Xvfb, GTKWave, sigrok-cli; emscripten and chromium
# for --web). The build folder is configured with ALP85_DOC_IMAGES on for the run and off after it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
web=0
build=$root/build
for a in "$@"; do
  case $a in
    --web) web=1 ;;
    -*) echo "scripts/doc-images.sh: unknown option $a (--web)" >&2; exit 2 ;;
    *) build=$a ;;
  esac
done
cd "$root"
configure() { cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DALP85_DOC_IMAGES="$1" >/dev/null; }
if [ -f "$build/CMakeCache.txt" ] && ! grep -q "^CMAKE_GENERATOR:INTERNAL=Ninja$" "$build/CMakeCache.txt"; then
  echo "scripts/doc-images.sh: $build was configured with another generator than Ninja" >&2
  exit 2
fi
configure ON
trap 'configure OFF' EXIT
cmake --build "$build" --target shipped gui_pixels
tests='gui:screen-1366x768|gui:scale-2x|gui:debugger-panes|signals:timing-cli|signals:gtkwave-shot|gui:signals-pane'
[ $web -eq 1 ] && tests="$tests|web:tools-installed|web:build|web:page"
ctest --test-dir "$build" -R "^($tests)\$" --output-on-failure
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
