#!/usr/bin/env bash
# Runs the period 8080/8085 CPU diagnostics through `alp85 cpm` and checks their verdicts.
#   scripts/run-cpu-diagnostics.sh DIR [--skip-exm]
# DIR holds TST8080.COM, CPUTEST.COM, 8080PRE.COM and 8080EXM.COM (public, but not part of
# ALP85: fetch them yourself). Needs build/bin/alp85 (scripts/run.sh builds it).
# 8080EXM takes about 2.4e10 T-states: several seconds at full speed; --skip-exm leaves it out.
set -uo pipefail
cd "$(dirname "$0")/.."

dir=${1:-}
skip_exm=0
[ "${2:-}" = "--skip-exm" ] && skip_exm=1
if [ -z "$dir" ] || [ ! -d "$dir" ]; then
  echo "usage: $0 DIR [--skip-exm]   (DIR with TST8080.COM CPUTEST.COM 8080PRE.COM 8080EXM.COM)" >&2
  exit 2
fi
alp85=build/bin/alp85
if [ ! -x "$alp85" ]; then
  echo "$alp85 not found: build first (scripts/run.sh)" >&2
  exit 2
fi

failures=0
known=0
out=$(mktemp)
trap 'rm -f "$out"' EXIT

# check NAME CPU SUCCESS-REGEX [FAIL-REGEX]
check() {
  local name=$1 cpu=$2 ok=$3 bad=${4:-}
  local file
  file=$(find "$dir" -maxdepth 1 -iname "$name.COM" | head -n 1)
  if [ -z "$file" ]; then
    echo "SKIP  $name ($cpu): $name.COM not in $dir"
    return
  fi
  local start=$SECONDS
  "$alp85" cpm "$file" --cpu "$cpu" --stats >"$out" 2>&1
  local rc=$?
  local tstates
  tstates=$(sed -n 's/^T-states: *//p' "$out")
  if [ $rc -eq 0 ] && grep -Eq "$ok" "$out" && { [ -z "$bad" ] || ! grep -Eq "$bad" "$out"; }; then
    echo "PASS  $name (i$cpu): $tstates T-states, $((SECONDS - start)) s"
  else
    echo "FAIL  $name (i$cpu): exit status $rc"
    sed 's/^/      /' "$out" | tail -n 25
    failures=$((failures + 1))
  fi
}

check TST8080 8080 "CPU IS OPERATIONAL"
check TST8080 8085 "CPU IS OPERATIONAL"
check 8080PRE 8080 "8080 Preliminary tests complete"
check CPUTEST 8080 "CPU TESTS OK"
# CPUTEST's tables expect the 8080's flag byte: bit 1 always 1, and ANA's AC from bit 3 of the
# operands. A faithful 8085 has V in bit 1 and always sets AC on ANA (docs/cpu.md, "CPUTEST on
# the 8085"), so the run stops at test 000BH (INR B clears V where CPUTEST expects bit 1 set).
# That exact outcome is reported as a known difference; any other failure counts.
cputest_8085() {
  local file
  file=$(find "$dir" -maxdepth 1 -iname "CPUTEST.COM" | head -n 1)
  [ -z "$file" ] && { echo "SKIP  CPUTEST (8085): CPUTEST.COM not in $dir"; return; }
  "$alp85" cpm "$file" --cpu 8085 >"$out" 2>&1
  if grep -q "CPU TESTS OK" "$out"; then
    echo "PASS  CPUTEST (i8085)"
  elif grep -q "TEST NUMBER  000BH" "$out" && grep -q "REGISTER f CONTAINS 00H" "$out" &&
       grep -q "BUT SHOULD CONTAIN 02H" "$out"; then
    echo "KNOWN CPUTEST (i8085): stops at test 000BH, flag bit 1 (the 8085's V) - see docs/cpu.md"
    known=$((known + 1))
  else
    echo "FAIL  CPUTEST (i8085)"
    sed 's/^/      /' "$out" | tail -n 25
    failures=$((failures + 1))
  fi
}
cputest_8085
if [ $skip_exm -eq 0 ]; then
  # All 25 groups must pass with the CRCs of real 8080 silicon, which the exerciser compares.
  check 8080EXM 8080 "Tests complete" "ERROR"
  if [ -f "$out" ] && grep -q "Tests complete" "$out"; then
    passes=$(grep -c "PASS!" "$out")
    echo "      8080EXM groups passed: $passes of 25"
    [ "$passes" -eq 25 ] || failures=$((failures + 1))
  fi
fi

if [ $failures -eq 0 ] && [ $known -eq 0 ]; then
  echo "all diagnostics passed"
elif [ $failures -eq 0 ]; then
  echo "no unexpected failures; $known known difference(s) from the 8080-made tables (not a pass)"
else
  echo "$failures diagnostic run(s) failed"
  exit 1
fi
