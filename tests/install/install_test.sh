#!/usr/bin/env bash
# install_test.sh BUILD_DIR SOURCE_DIR VERSION [LINTIAN]
# Builds the .deb from BUILD_DIR with CPack, unpacks it into a fresh root with dpkg -x and, from a
# folder outside the source tree, runs what a user of the package would: the thesis walk-through
# to Bitti, an installed example script, asm85 and pisa-asm on installed sources, the debugger on
# the built-in firmware's installed source, every man page, and the bash completion. Then lintian:
# no error. Expected values come from the thesis walk-through (docs/thesis.md) and from the files
# the build itself assembled, not from the installed programs.
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd) version=$3 lintian=${4:-}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/alp85-install.XXXXXX")
lintian_pid=
trap '[ -n "$lintian_pid" ] && kill "$lintian_pid" 2>/dev/null; rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# (Output is captured before grep -q reads it: grep -q stops at its first match, and under pipefail
# the writer's SIGPIPE would fail a pipeline at random.)
step() { echo "== $* (at ${SECONDS} s)"; }

step "cpack -G DEB"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$tmp/pkg" >"$tmp/cpack.log" 2>&1 || { cat "$tmp/cpack.log"; fail "cpack"; }
debs=("$tmp"/pkg/alp85_*.deb)
[ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || fail "no single alp85_*.deb in $tmp/pkg"
deb=${debs[0]}
info=$(dpkg-deb --field "$deb" Package Version Maintainer Depends Section Description)
sed -n '1,8s/^/  /p' <<<"$info"
grep -qx "Package: alp85" <<<"$info" || fail "Package is not alp85"
grep -qx "Version: $version-1" <<<"$info" || fail "Version is not $version-1"
grep -q "^Maintainer: .*<.*@.*>" <<<"$info" || fail "no Maintainer"
# dpkg-shlibdeps found the libraries the programs link (libc, the C++ runtime, SDL2, cairo, libedit).
for lib in libc6 libstdc++6 libsdl2 libcairo2 libedit2; do
  grep -q "^Depends:.*\b$lib\b" <<<"$info" || fail "Depends does not name $lib"
done

# lintian (several seconds) checks the package meanwhile; its verdict is read at the end.
if [ -n "$lintian" ]; then
  "$lintian" --fail-on error "$deb" >"$tmp/lintian.log" 2>&1 &
  lintian_pid=$!
fi

step "dpkg -x into a fresh root"
root=$tmp/root
dpkg -x "$deb" "$root"
usr=$root/usr share=$root/usr/share/alp85
for f in bin/alp85 bin/asm85 bin/pisa-asm share/doc/alp85/copyright share/doc/alp85/changelog.Debian.gz \
         share/man/man1/alp85.1.gz share/man/man1/asm85.1.gz share/man/man1/pisa-asm.1.gz \
         share/bash-completion/completions/alp85 share/alp85/editors/vscode/package.json \
         share/alp85/firmware/thesis/thesis.asm share/alp85/firmware/thesis/thesis-fixed.hex \
         share/alp85/firmware/monitor/monitor.json share/alp85/examples/demo/thesis.alp \
         share/alp85/examples/master/contour.nc share/alp85/examples/pisa/contour.tape; do
  [ -f "$usr/$f" ] || fail "the package lacks /usr/$f"
done
cmp -s "$usr/share/doc/alp85/copyright" "$src/LICENSE" || fail "copyright is not LICENSE"
# The installed maps name the installed sources, not the source tree.
! grep -rl "$src" "$share/firmware" --include=*.json || fail "an installed map names the source tree"
grep -q "\"/usr/share/alp85/firmware/thesis/thesis.asm\"" "$share/firmware/thesis/thesis-fixed.json" ||
  fail "thesis-fixed.json does not name /usr/share/alp85/firmware/thesis/thesis.asm"

work=$tmp/work
mkdir "$work"
cd "$work"
export PATH="$usr/bin:$PATH"
[ "$(command -v alp85)" = "$usr/bin/alp85" ] || fail "alp85 is not the unpacked one"

step "--version"
for p in alp85 asm85 pisa-asm; do
  v=$("$p" --version)
  echo "  $v"
  [[ $v =~ ^$p\ $version( \(git [0-9a-f]{7,}(-dirty)?\))?$ ]] || fail "$p --version: '$v'"
done

step "alp85 run --firmware thesis-fixed to Bitti"
# Thesis Appendix C (scripts/demo/thesis.alp): R 7 0800 EXEC, Z = 0012, the line from (0100, 0050)
# to (0300, 0200) in 0.05 mm steps at F = 0750 mm/min; the move takes 2.85 s of machine time.
alp85 run --firmware thesis-fixed --text --for 4s \
  --keys "R 7 0800 EXEC 0012 0100 EXEC 0050 EXEC 0300 EXEC 0200 EXEC 0750 EXEC" >run.txt ||
  { cat run.txt; fail "alp85 run"; }
grep -q "8itti" run.txt || { cat run.txt; fail "alp85 run did not reach Bitti"; }
# 200 steps in X, 150 in Y, 12 in Z (10 mm, 7.5 mm, Z = 12).
grep -Eq "^ *X +200 steps" run.txt && grep -Eq "^ *Y +150 steps" run.txt && grep -Eq "^ *Z +12 steps" run.txt || { cat run.txt; fail "the tables did not end at 200, 150"; }

step "alp85 script on installed examples"
alp85 script "$share/examples/demo/hello85.alp" --out-dir out >script.txt || { cat script.txt; fail "hello85.alp"; }
alp85 script "$share/examples/demo/thesis.alp" --out-dir out >>script.txt || { cat script.txt; fail "thesis.alp"; }
[ -s out/thesis-toolpath.svg ] || fail "thesis.alp wrote no toolpath plot into --out-dir"
# Every file an installed example loads or includes is installed (no path into tests/ or elsewhere).
refs=0
while IFS= read -r f; do
  dir=$(dirname "$f")
  while IFS= read -r ref; do
    ref=${ref%%@*}
    refs=$((refs + 1))
    [ -f "$dir/$ref" ] || fail "$f: $ref is not installed"
  done < <(sed -nE 's/^[[:space:]]*(load|INCLUDE)[[:space:]]+([^[:space:];]+).*/\2/Ip' "$f")
done < <(find "$share/examples" -name '*.alp' -o -name '*.asm')
[ "$refs" -gt 5 ] || fail "only $refs load/INCLUDE lines found in the installed examples"

step "asm85 and pisa-asm on installed sources"
asm85 "$share/firmware/demo/hello85.asm" -o hello85.hex --lst hello85.lst
cmp -s hello85.hex "$share/firmware/demo/hello85.hex" || fail "asm85 hello85.asm differs from the build's image"
asm85 "$share/firmware/thesis/thesis.asm" -D FIXED=1 -o fixed.hex
cmp -s fixed.hex "$share/firmware/thesis/thesis-fixed.hex" || fail "asm85 thesis.asm -D FIXED=1 differs from the build's thesis-fixed"
asm85 "$share/examples/machine/axes.asm" -o axes.hex  # INCLUDE ../../firmware/lib/dl.inc
pisa-asm "$share/firmware/pisa/interp.pasm" -o interp.rom
cmp -s interp.rom "$share/firmware/pisa/interp.rom" || fail "pisa-asm interp.pasm differs from the build's ROM"

step "the debugger reads the installed firmware source"
# Mark the installed copy of thesis.asm (the source tree's stays as it is): the listing the
# debugger shows for BITTI must come from the installed copy.
sed -i 's/^; ; BITTI SUBROUTINE /; ; BITTI SUBROUTINE (installed copy)/' "$share/firmware/thesis/thesis.asm"
grep -q "(installed copy)" "$share/firmware/thesis/thesis.asm" || fail "thesis.asm has no BITTI SUBROUTINE line to mark"
printf 'break BITTI\nlist BITTI\n' | alp85 debug thesis-fixed --batch >debug.txt 2>&1 || { cat debug.txt; fail "alp85 debug"; }
line=$(grep -n "^BITTI:" "$src/firmware/thesis/thesis.asm" | cut -d: -f1)
grep -q "^Breakpoint 1 at .*: file thesis.asm, line $line\.$" debug.txt || { cat debug.txt; fail "no breakpoint on BITTI at thesis.asm:$line"; }
grep -q "BITTI SUBROUTINE (installed copy)" debug.txt || { cat debug.txt; fail "the debugger did not list the installed thesis.asm"; }

step "man -l"
for p in alp85 asm85 pisa-asm; do
  page=$usr/share/man/man1/$p.1.gz
  MANWIDTH=100 man --warnings -l "$page" >"$p.man" 2>"$p.warn" || fail "man -l $p"
  [ ! -s "$p.warn" ] || { cat "$p.warn"; fail "man -l $p: warnings"; }
  grep -q "^NAME" "$p.man" && grep -q "^SYNOPSIS" "$p.man" || fail "$p(1) has no NAME or SYNOPSIS"
  # Each option --help lists is in the page (the page is made from --help).
  for o in $("$p" --help | awk '/^ +-/ { n = split($1, a, ","); for (i = 1; i <= n; i++) if (a[i] ~ /^--/) print a[i] }'); do
    grep -q -- "$o" "$p.man" || fail "$p(1) lacks $o"
  done
done
# alp85(1): a section per command, holding that command's options.
for c in $(alp85 --help | awk '/^Subcommands:/ { s = 1; next } s && /^  [a-z]/ { print $1 }'); do
  grep -q "^   alp85 $c\$" alp85.man || fail "alp85(1) has no section for $c"
  for o in $(alp85 "$c" --help | awk '/^ +-/ { n = split($1, a, ","); for (i = 1; i <= n; i++) if (a[i] ~ /^--/) print a[i] }'); do
    grep -q -- "$o" alp85.man || fail "alp85(1) lacks $c $o"
  done
done

step "bash completion"
if [ -f /usr/share/bash-completion/bash_completion ]; then
  complete_words() {  # the words bash would offer for the command line "$*"
    bash "$(dirname "$0")/complete_words.sh" "$usr/share/bash-completion/completions/alp85" "$@"
  }
  grep -qx script <<<"$(complete_words alp85 "")" || fail "completion: no command script"
  grep -qx -- --firmware <<<"$(complete_words alp85 run --f)" || fail "completion: no run --firmware"
  got=$(complete_words alp85 run --firmware "" | sort | tr '\n' ' ')
  # The built-in firmware as alp85 itself names them (alp85 gui --help).
  gui_help=$(alp85 gui --help)
  for fw in monitor thesis thesis-fixed master; do
    grep -q "\b$fw\b" <<<"$got" || fail "completion: firmware $fw missing ($got)"
    grep -q "\b$fw\b" <<<"$gui_help" || fail "alp85 gui --help does not name $fw"
  done
  mkdir completion && touch completion/a.alp completion/b.txt
  [ "$(cd completion && complete_words alp85 script "")" = "a.alp" ] || fail "completion: script does not offer a.alp alone"
  grep -qx -- --cpu <<<"$(complete_words asm85 --c)" || fail "completion: asm85 --cpu"
  [ "$(complete_words asm85 --cpu 8085 | sort | tr '\n' ' ')" = "8085 8085u " ] || fail "completion: asm85 --cpu 8085"
else
  fail "bash-completion is not installed (scripts/setup.sh --tests installs it)"
fi

step "fish completion"
command -v fish >/dev/null || fail "fish is not installed (scripts/setup.sh --tests installs it)"
fish_words() {  # the words fish would offer for the command line "$1" (alp85.fish loaded as fish does)
  (cd completion && fish --no-config -c "set fish_complete_path $usr/share/fish/vendor_completions.d; complete -C '$1'" | cut -f1 | sort | tr '\n' ' ')
}
[ "$(fish_words "alp85 run --firmware ")" = "master monitor thesis thesis-fixed " ] || fail "fish: run --firmware: $(fish_words "alp85 run --firmware ")"
grep -qw script <<<"$(fish_words "alp85 ")" || fail "fish: no command script"
grep -qw thesis <<<"$(fish_words "alp85 bench ")" || fail "fish: no bench thesis"
grep -qw -- --for <<<"$(fish_words "alp85 run --f")" || fail "fish: no run --for"
grep -qw a.alp <<<"$(fish_words "alp85 script ")" || fail "fish: script does not offer a.alp"
[ "$(fish_words "asm85 --cpu 8085")" = "8085 8085u " ] || fail "fish: asm85 --cpu 8085"

if [ -n "$lintian" ]; then
  step "lintian"
  status=0
  wait "$lintian_pid" || status=$?
  lintian_pid=
  sed 's/^/  /' "$tmp/lintian.log"
  [ "$status" -eq 0 ] || fail "lintian found errors (status $status)"
fi
echo "install:deb passed (${SECONDS} s)"
