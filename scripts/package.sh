#!/usr/bin/env bash
# Builds ALP85 (release) and its Debian package, build/alp85_<version>-1_<arch>.deb (CPack;
# scripts/packaging/CMakeLists.txt, docs/install.md). Install it with
#   sudo apt install ./build/alp85_*.deb
# Run scripts/setup.sh --tests once before (help2man for the man pages, dpkg-dev for the dependencies).
#   scripts/package.sh [--lintian]     --lintian: also check the package with lintian
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
log=build/cpack.log
(cd build && cpack -G DEB --config CPackConfig.cmake) >"$log" 2>&1 || { cat "$log"; exit 1; }
deb=$(ls -t build/alp85_*.deb | head -1)
echo "package: $deb"
dpkg-deb --info "$deb" | sed -n 's/^ \(Package\|Version\|Depends\|Installed-Size\):/  \1:/p'
if [ "${1:-}" = "--lintian" ]; then
  lintian --fail-on error "$deb"
fi
