#!/usr/bin/env bash
# Installs what ALP85 needs, from Debian's packages (and, for the tests, npm's registry).
#   scripts/setup.sh           what the main job needs (scripts/run.sh): the compiler, CMake and the
#                              libraries alp85 and asm85 link; a minute or two on a fresh machine
#   scripts/setup.sh --tests   that, and what only the tests need (scripts/test.sh): clang's
#                              runtime, Xvfb, the package tools, emscripten and chromium for the web
#                              page, node with the DAP tests' client (@vscode/debugadapter-testsupport,
#                              tests/dap/node_modules) and the page's (puppeteer-core,
#                              tests/web/node_modules); then readies emscripten's cache
# Non-interactive and idempotent: when all is present it only checks and returns.
set -euo pipefail
cd "$(dirname "$0")/.."

tests=0
case "${1:-}" in
  "") ;;
  --tests) tests=1 ;;
  *) echo "scripts/setup.sh: unknown option $1 (--tests installs what the tests need too)" >&2; exit 2 ;;
esac

# The DAP tests' client, pinned by tests/dap/package-lock.json; node and npm from Debian when
# the machine has neither.
install_dap_client() {
  local want have
  want=$(sed -n 's/.*"@vscode\/debugadapter-testsupport": "\([^"]*\)".*/\1/p' tests/dap/package.json)
  have=$(sed -n 's/.*"version": "\([^"]*\)".*/\1/p' tests/dap/node_modules/@vscode/debugadapter-testsupport/package.json 2>/dev/null | head -1 || true)
  if [ -n "$have" ] && [ "$have" = "$want" ]; then
    echo "setup: @vscode/debugadapter-testsupport $have present"
    return
  fi
  echo "setup: installing @vscode/debugadapter-testsupport $want (tests/dap)"
  (cd tests/dap && npm ci --no-audit --no-fund --loglevel=error)
}

# The web page's test client (puppeteer-core, pinned by tests/web/package-lock.json); it drives
# Debian's chromium, so it downloads no browser.
install_web_client() {
  local want have
  want=$(sed -n 's/.*"puppeteer-core": "\([^"]*\)".*/\1/p' tests/web/package.json)
  have=$(sed -n 's/.*"version": "\([^"]*\)".*/\1/p' tests/web/node_modules/puppeteer-core/package.json 2>/dev/null | head -1 || true)
  if [ -n "$have" ] && [ "$have" = "$want" ]; then
    echo "setup: puppeteer-core $have present"
    return
  fi
  echo "setup: installing puppeteer-core $want (tests/web)"
  (cd tests/web && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
}

# emscripten builds a system library it lacks into its cache (Debian's: /usr/share/emscripten/cache,
# which comes with the libraries the web build uses already built) on first use; one tiny module
# with the web build's flags (web/CMakeLists.txt) does any such work here, not in the test command,
# and shows the tool chain works (7 s).
prepare_emscripten() {
  local dir
  dir=$(mktemp -d)
  printf '#include <emscripten/bind.h>\n#include <string>\nstd::string f() { try { throw 1; } catch (int) { return "ok"; } }\nEMSCRIPTEN_BINDINGS(m) { emscripten::function("f", &f); }\n' > "$dir/warm.cpp"
  if NODE_PATH=/usr/share/nodejs em++ -std=c++20 -O2 -sDISABLE_EXCEPTION_CATCHING=0 --bind -sMODULARIZE=1 -sEXPORT_ES6=1 \
       -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web -sFILESYSTEM=1 "$dir/warm.cpp" -o "$dir/warm.js"; then
    echo "setup: emscripten ready"
  else
    echo "setup: emscripten could not build a test module" >&2
    rm -rf "$dir"
    return 1
  fi
  rm -rf "$dir"
}

# The main job: build alp85 (its window: SDL2, Dear ImGui, OpenGL; plots: cairo; the debugger's
# prompt: libedit) and asm85. GoogleTest and Google Benchmark are small and the build's
# configuration looks for them, so they come here too.
packages=(
  g++ cmake ninja-build make pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  libfmt-dev libcli11-dev nlohmann-json3-dev
  zlib1g-dev python3
  libcairo2-dev
  libsdl2-dev libimgui-dev libgl-dev libgl1-mesa-dri
  libedit-dev
)
# Only the tests: clang (the sanitizer build, scripts/test.sh; the fuzz targets) and LLVM's linker (the test programs link in half the
# time; CMakeLists.txt), the window under Xvfb, the Debian package and its test
# (scripts/package.sh, tests/install: dpkg-shlibdeps, man -l, the man pages from --help, the
# package check, the bash completion's helpers, fish for its completion), the web page
# (scripts/web.sh, tests/web: emscripten, whose tools need node-acorn, and a browser),
# sigrok-cli, which reads every VCD the tests record (tests/signals), and GTKWave, whose window
# on the thesis's pulses a test grabs for docs/signals.md (File > Grab To File: no other tool).
test_packages=(
  clang libclang-rt-14-dev lld
  xvfb xauth
  dpkg-dev man-db help2man lintian bash-completion fish
  emscripten node-acorn chromium
  sigrok-cli gtkwave
)
if [ $tests -eq 1 ]; then
  packages+=("${test_packages[@]}")
  # node and npm: Debian's, unless the machine already has both (a nodejs package of another
  # origin brings its own npm, which Debian's npm would conflict with).
  if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
    packages+=(nodejs npm)
  fi
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
else
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ $tests -eq 1 ]; then
  install_dap_client
  install_web_client
  prepare_emscripten
fi
