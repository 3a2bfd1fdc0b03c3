#!/usr/bin/env bash
# Assembles period sources with asm85 and compares the bytes with their published binaries.
#
#   scripts/compare-period-sources.sh DIR [ASM85]
#
# DIR holds the sources (never kept in this repository). Two kinds of cases are found in it:
#   * NAME.{ASM,MAC,A80,SRC} (any case) next to NAME.{COM,BIN,HEX,LST}: a CP/M .COM loads at
#     0100H, a .BIN at the lowest address the source emits, an Intel .HEX where its records say;
#     a .LST is a listing printed by Intel's ISIS-II ASM80, whose LOC/OBJ columns give the bytes.
#   * NAME.modules, a list of source files (one a line, relative to the list), next to NAME.COM:
#     the modules are assembled separately and their images laid over each other in order, as
#     CP/M's own ASM.COM was built from seven Intel-assembled hex files.
# A file NAME.flags next to a case adds asm85 options (e.g. --name-length 6). A file NAME.errata
# corrects misprints of a published listing: "ADDR BYTE reason" per line (the count is reported).
# Every byte the source emits is compared. Bytes of the published file that the source does not
# emit (DS areas, the padding of the last 128-byte CP/M record) are compared against 00H and
# counted separately, since they hold whatever the original tool left there.
# Exit status: 0 when every emitted byte of every case matches.
set -euo pipefail
dir=${1:?usage: compare-period-sources.sh DIR [ASM85]}
asm85=${2:-$(cd "$(dirname "$0")/.." && pwd)/build/bin/asm85}
[ -x "$asm85" ] || { echo "asm85 not found at $asm85 (build it first)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

status=0
compare() {  # case-name published-binary load-address hex-files...
  local name=$1 bin=$2 load=$3; shift 3
  python3 - "$name" "$bin" "$load" "$@" <<'PY' || status=1
import re, sys
name, binpath, load, hexes = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]

def read_hex(path):
    mem = {}
    for line in open(path):
        line = line.strip()
        if not line.startswith(':'):
            continue
        n, a, t = int(line[1:3], 16), int(line[3:7], 16), int(line[7:9], 16)
        if t == 0:
            for i in range(n):
                mem[(a + i) & 0xFFFF] = int(line[9 + 2 * i:11 + 2 * i], 16)
    return mem

def read_isis_listing(path):
    # LOC and OBJ columns of an ISIS-II ASM80 listing. A transcribed listing may misread one digit
    # of LOC; a LOC one hex digit away from where the previous object code ended is taken as that.
    mem, expected = {}, None
    for ln in open(path, errors='replace'):
        m = re.match(r'^([0-9A-F]{4}) {1,4}([0-9A-F]{2,8})(\s+\d+.*|\s*)$', ln.rstrip('\n'))
        if not m:
            if re.match(r'^[0-9A-F]{4}\s+\d+\s', ln):
                expected = None  # ORG, DS or EQU: a jump is genuine
            continue
        a, obj = int(m.group(1), 16), m.group(2)
        if len(obj) % 2:
            continue
        if expected is not None and a != expected and \
                sum(x != y for x, y in zip('%04X' % a, '%04X' % expected)) == 1:
            a = expected
        for i in range(0, len(obj), 2):
            mem[a + i // 2] = int(obj[i:i + 2], 16)
        expected = a + len(obj) // 2
    return mem

mem = {}
for h in hexes:
    mem.update(read_hex(h))
kind = binpath.rsplit('.', 1)[-1].lower()
if kind == 'hex':
    pub = read_hex(binpath)
elif kind == 'lst':
    pub = read_isis_listing(binpath)
else:
    raw = open(binpath, 'rb').read()
    base = (min(mem) if mem else 0) if load == 'lowest' else int(load, 16)
    pub = {base + i: b for i, b in enumerate(raw)}
errata = 0
try:  # NAME.errata: "ADDR BYTE reason" lines correcting misprints/misreadings in the published file
    for line in open(binpath.rsplit('.', 1)[0] + '.errata'):
        f = line.split()
        if len(f) >= 2 and not line.startswith('#'):
            pub[int(f[0], 16)] = int(f[1], 16)
            errata += 1
except FileNotFoundError:
    pass
bad = [a for a in sorted(mem) if a in pub and mem[a] != pub[a]]
outside = [a for a in sorted(mem) if a not in pub]
rest = [a for a in sorted(pub) if a not in mem]
rest_nonzero = [a for a in rest if pub[a] != 0]
last = max(mem) if mem else 0
tail = sum(1 for a in rest if a > last)
verdict = 'IDENTICAL' if not bad and not outside and not rest_nonzero else ('MATCH' if not bad and not outside else 'DIFFER')
lo = min(pub) if pub else 0
print(f"{verdict:9} {name}: published {len(pub)} bytes ({kind.upper()} from {lo:04X}H"
      + (f", {errata} corrected by errata" if errata else "") + f"); asm85 emitted {len(mem)}, {len(bad)} differ", end='')
if outside:
    print(f", {len(outside)} not in the published image", end='')
print(f"; {len(rest)} published bytes not emitted ({tail} after the last emitted byte), "
      f"{len(rest_nonzero)} of them non-zero"
      + (f" ({rest_nonzero[0]:04X}H-{rest_nonzero[-1]:04X}H)" if rest_nonzero else ""))
for a in (bad + outside)[:10]:
    print(f"    {a:04X}H: published {pub[a]:02X}H, asm85 {mem[a]:02X}H" if a in pub else f"    {a:04X}H: asm85 {mem[a]:02X}H only")
sys.exit(1 if bad or outside else 0)
PY
}

assemble() {  # source out.hex flags-file
  local src=$1 out=$2 flags=()
  [ -f "$3" ] && read -r -a flags < "$3"
  if ! "$asm85" "$src" -o "$out" --quiet --no-unused-macro-warnings "${flags[@]}" 2> "$work/err"; then
    echo "FAILED    $src: asm85 reported errors:"; sed 's/^/    /' "$work/err" | head -20
    return 1
  fi
}

cases=0
while IFS= read -r -d '' src; do
  stem=${src%.*}
  pub=""
  for ext in COM com BIN bin HEX hex LST lst; do [ -f "$stem.$ext" ] && pub="$stem.$ext" && break; done
  [ -n "$pub" ] || continue
  cases=$((cases + 1))
  load=0100; case $pub in *.BIN|*.bin) load=lowest;; esac
  out="$work/$(basename "$stem").hex"
  assemble "$src" "$out" "$stem.flags" || { status=1; continue; }
  compare "$(basename "$src")" "$pub" "$load" "$out"
done < <(find "$dir" -type f \( -iname '*.asm' -o -iname '*.mac' -o -iname '*.a80' -o -iname '*.src' \) -print0 | sort -z)

while IFS= read -r -d '' list; do
  stem=${list%.modules}
  pub=""
  for ext in COM com BIN bin; do [ -f "$stem.$ext" ] && pub="$stem.$ext" && break; done
  [ -n "$pub" ] || { echo "SKIPPED   $list: no $stem.COM/.BIN"; continue; }
  cases=$((cases + 1))
  load=0100; case $pub in *.BIN|*.bin) load=lowest;; esac
  hexes=(); ok=1
  while read -r m; do
    [ -z "$m" ] && continue
    out="$work/$(basename "${m%.*}").hex"
    assemble "$(dirname "$list")/$m" "$out" "$stem.flags" || { ok=0; break; }
    hexes+=("$out")
  done < "$list"
  [ $ok = 1 ] || { status=1; continue; }
  compare "$(basename "$stem") (${#hexes[@]} modules)" "$pub" "$load" "${hexes[@]}"
done < <(find "$dir" -type f -name '*.modules' -print0 | sort -z)

echo "$cases cases compared"
exit $status
