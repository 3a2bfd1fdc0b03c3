#!/usr/bin/env bash
# 8080EXM on ALP85 and on two open 8080 interpreters, interleaved on the same host in the same
# minutes (docs/cpu.md, "Against other interpreters"). The peers are not part of ALP85: check them
# out yourself OUTSIDE this repository and pass their directories; this script builds each with
# its own Makefile's flags into its own directory and never copies anything into the repository.
#   scripts/bench-peers.sh EXM_COM BEGOON_DIR SUPERZAZU_DIR [ROUNDS]
#     EXM_COM        8080EXM.COM (superzazu/8080 ships one in cpu_tests/)
#     BEGOON_DIR     a checkout of github.com/begoon/i8080-core
#     SUPERZAZU_DIR  a checkout of github.com/superzazu/8080
# Each round runs ALP85, begoon, superzazu once (A B C A B C ...); the table gives the minimum
# wall and process CPU (user + system) time of each. Needs build/bin/alp85 and a C compiler.
set -euo pipefail
cd "$(dirname "$0")/.."
exm=${1:?usage: $0 EXM_COM BEGOON_DIR SUPERZAZU_DIR [ROUNDS]}
begoon=${2:?usage}
zazu=${3:?usage}
rounds=${4:-3}
alp85=$PWD/build/bin/alp85
[ -x "$alp85" ] || { echo "$alp85 not found: build first" >&2; exit 2; }
exm=$(cd "$(dirname "$exm")" && pwd)/$(basename "$exm")

# begoon: its Makefile builds with `cc -O3 -flto` its own harness, which runs four programs; the
# harness's main is rewritten to run 8080EXM alone (same loop, same per-instruction checks).
mkdir -p "$begoon/assets"
cp "$exm" "$begoon/assets/8080EXM.COM"
sed -e '/execute_test("assets\/CPUTEST.COM"/d' -e '/execute_test("assets\/TEST.COM"/d' \
    -e '/execute_test("assets\/8080PRE.COM"/d' \
    -e 's|execute_test("assets/8080EX1.COM", 0);|execute_test("assets/8080EXM.COM", 0);|' \
    "$begoon/i8080_test.c" >"$begoon/i8080_test_exm.c"
(cd "$begoon" && cc -O3 -flto -o i8080_exm i8080.c i8080_hal.c i8080_test_exm.c)
# superzazu: its Makefile's CFLAGS (-O2 -std=c99), its own test driver with 8080EXM alone.
mkdir -p "$zazu/cpu_tests"
[ -f "$zazu/cpu_tests/8080EXM.COM" ] || cp "$exm" "$zazu/cpu_tests/8080EXM.COM"
grep -v -e 'TST8080.COM' -e 'CPUTEST.COM' -e '8080PRE.COM' "$zazu/i8080_tests.c" >"$zazu/exm_main.c"
(cd "$zazu" && cc -g -O2 -std=c99 -o i8080_exm i8080.c exm_main.c)

declare -A best_wall best_cpu
run() {  # name dir command...
  local name=$1 dir=$2
  shift 2
  local tf
  tf=$(mktemp)
  (cd "$dir" && /usr/bin/time -f "%e %U %S" -o "$tf" "$@" >/dev/null 2>&1) || { echo "$name failed" >&2; rm -f "$tf"; exit 1; }
  read -r wall user sys <"$tf"
  rm -f "$tf"
  local cpu
  cpu=$(echo "$user + $sys" | bc)
  printf '%-10s wall %6.2f s  CPU %6.2f s\n' "$name" "$wall" "$cpu"
  if [ -z "${best_wall[$name]:-}" ] || (( $(echo "$wall < ${best_wall[$name]}" | bc) )); then best_wall[$name]=$wall; fi
  if [ -z "${best_cpu[$name]:-}" ] || (( $(echo "$cpu < ${best_cpu[$name]}" | bc) )); then best_cpu[$name]=$cpu; fi
}
date -u
uptime
for ((i = 1; i <= rounds; ++i)); do
  run alp85 . "$alp85" cpm "$exm" --cpu 8080
  run begoon "$begoon" ./i8080_exm
  run superzazu "$zazu" ./i8080_exm
done
date -u
echo "minimum of $rounds:"
for n in alp85 begoon superzazu; do
  printf '%-10s wall %6.2f s  CPU %6.2f s  (alp85 / this: wall %.2f, CPU %.2f)\n' "$n" "${best_wall[$n]}" "${best_cpu[$n]}" \
    "$(echo "${best_wall[alp85]} / ${best_wall[$n]}" | bc -l)" "$(echo "${best_cpu[alp85]} / ${best_cpu[$n]}" | bc -l)"
done
