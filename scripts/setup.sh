#!/usr/bin/env bash
# Installs everything ALP85's build and tests need, from Debian's packages, and the DAP tests'
# client (@vscode/debugadapter-testsupport) from the npm registry into tests/dap/node_modules.
# Non-interactive and idempotent: when all is present it only checks and returns.
set -euo pipefail
cd "$(dirname "$0")/.."

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

packages=(
  g++ cmake ninja-build make pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  libfmt-dev libcli11-dev nlohmann-json3-dev
  clang libclang-rt-14-dev
  zlib1g-dev python3
  libcairo2-dev
  libsdl2-dev libimgui-dev libgl-dev libgl1-mesa-dri
  xvfb xauth
  libedit-dev
  # the Debian package and its test (scripts/package.sh, tests/install): dpkg-shlibdeps, man -l,
  # the man pages from --help, the package check, the bash completion's helpers, fish (its completion)
  dpkg-dev man-db help2man lintian bash-completion fish
)
# node and npm: Debian's, unless the machine already has both (a nodejs package of another
# origin brings its own npm, which Debian's npm would conflict with).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
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
install_dap_client
