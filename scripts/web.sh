#!/usr/bin/env bash
# Builds the web page (docs/web.md) into build/web/ and serves it on 127.0.0.1.
#   scripts/web.sh              build, then serve on http://127.0.0.1:8085/ (Ctrl-C ends it)
#   scripts/web.sh --build      build only
#   scripts/web.sh --port N     serve on port N
# ALP85_WERROR=ON: warnings are errors (the test command's build). The page needs the native
# build's generated firmware (build/, which this builds first when it
# is missing: asm85 assembles the monitor, thesis and master) and Debian's emscripten.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

serve=1
port=8085
native=${ALP85_NATIVE_BUILD:-$root/build}
out=${ALP85_WEB_OUT:-$root/build/web}
while [ $# -gt 0 ]; do
  case $1 in
    --build) serve=0 ;;
    --port) port=$2; shift ;;
    *) echo "scripts/web.sh: unknown option $1 (--build, --port N)" >&2; exit 2 ;;
  esac
  shift
done

if ! command -v emcmake >/dev/null 2>&1; then
  echo "scripts/web.sh: emscripten is not installed; run scripts/setup.sh --tests" >&2
  exit 1
fi
# Debian's emscripten finds Debian's node-acorn only here.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
# Debian's emscripten runs its tools (em++, emcmake) on the "python3" first on the PATH. Debian's
# own is the one it is packaged for, and a version manager's shim there costs each start dearly
# (pyenv's resolves the version: an em++ took 0.39 CPU-s through it, 0.13 on Debian's python);
# the module's build from nothing starts 27 of them.
if [ -z "${EMSDK_PYTHON:-}" ] && [ -x /usr/bin/python3 ]; then
  export EMSDK_PYTHON=/usr/bin/python3
fi

# The firmware the page carries, assembled by the native build: only its generated texts (the
# monitor ROM and map, the thesis and master images and maps) and the SDK-85 test program's ROM,
# which wait for asm85 alone, not for the native programs. A folder that has built alp85 has them already.
if [ ! -f "$native/emu/program/embed_kMasterHex.cpp" ] || [ ! -f "$native/firmware/monitor/monitor_embed.cpp" ] ||
   [ ! -f "$native/firmware/sdk85/sdk85test.bin" ]; then
  echo "web: assembling the firmware the page carries with asm85 (native build in $native)"
  [ -f "$native/CMakeCache.txt" ] || cmake -S . -B "$native" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON >/dev/null
  cmake --build "$native" --target alp85_firmware_text monitor_embed firmware_sdk85test
fi

launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
wasm_build=$out-build
werror=${ALP85_WERROR:-OFF}
config=(-S web -B "$wasm_build" -G Ninja -DALP85_NATIVE_BUILD="$native" -DALP85_WERROR="$werror" "${launcher[@]}")
# Configured once: a folder configured with the same native build and warnings goes straight to
# the build step (which reconfigures by itself when a CMakeLists.txt changed).
if grep -qx "ALP85_NATIVE_BUILD:[A-Z]*=$native" "$wasm_build/CMakeCache.txt" 2>/dev/null &&
   grep -qx "ALP85_WERROR:[A-Z]*=$werror" "$wasm_build/CMakeCache.txt" 2>/dev/null; then
  :
else
  echo "web: configuring the WebAssembly build with emscripten ($wasm_build)"
  emcmake cmake "${config[@]}" >/dev/null 2>&1 ||
    { echo "scripts/web.sh: configuring $wasm_build failed" >&2; emcmake cmake "${config[@]}" >&2; exit 1; }
fi
echo "web: compiling the module (a few minutes from nothing, seconds when it is built)"
cmake --build "$wasm_build"

# The site: the module and the page's own files, nothing from elsewhere.
mkdir -p "$out"
cp "$wasm_build/site/alp85.js" "$wasm_build/site/alp85.wasm" "$out/"
cp web/index.html web/style.css web/main.js web/walkthrough.js web/favicon.svg "$out/"
echo "web: $out ready ($(du -k "$out/alp85.wasm" | cut -f1) KB of WebAssembly)"

if [ $serve -eq 1 ]; then
  echo "web: http://127.0.0.1:$port/  (Ctrl-C ends it)"
  cd "$out" && exec python3 -m http.server "$port" --bind 127.0.0.1
fi
