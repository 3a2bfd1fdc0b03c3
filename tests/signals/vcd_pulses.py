#!/usr/bin/env python3
"""Widths of a pin's high pulses in a VCD file, in T-states of the 8085's 3.072 MHz clock.

    vcd_pulses.py FILE.vcd PIN [--expect T] [--count N]

PIN is a variable's name ("PA0") or scope.name ("i8155.PA0", X.PULSE). The file may be alp85's
or sigrok-cli's (-O vcd) rewrite of it: times are read with the file's $timescale and turned into
T-states by the clock (a T-state is 325.52 ns, so rounding a difference of nanoseconds gives the
T-states exactly). A pulse is a rising edge to the next falling one (the level the recording
starts with is no edge). Prints one width per line; with --expect, exits 1 unless every pulse is T
T-states long, and with --count unless there are at least N of them.
"""
import argparse
import re
import sys

CPU_HZ = 3_072_000  # the 8085's clock on the ALP 85 (emu/board/board_map.h, kCpuHz)
UNITS = {"s": 1, "ms": 1e-3, "us": 1e-6, "ns": 1e-9, "ps": 1e-12, "fs": 1e-15}


def read(path, pin):
    text = open(path, encoding="ascii").read()
    head, _, body = text.partition("$enddefinitions")
    m = re.search(r"\$timescale\s+(\d+)\s*(\w+)\s+\$end", head)
    if not m:
        sys.exit(f"{path}: no $timescale")
    unit = int(m.group(1)) * UNITS[m.group(2)]
    ident = None
    by_name = {}  # a bare name: sigrok-cli's rewrite puts every channel in one scope
    scopes = []
    for tok in re.finditer(r"\$(scope|upscope|var)\b(.*?)\$end", head, re.S):
        kind, rest = tok.group(1), tok.group(2).split()
        if kind == "scope":
            scopes.append(rest[1])
        elif kind == "upscope":
            scopes.pop()
        else:
            by_name.setdefault(rest[3], []).append(rest[2])
            if rest[3] == pin or f"{scopes[-1] if scopes else ''}.{rest[3]}" == pin:
                ident = rest[2]
    bare = by_name.get(pin.split(".")[-1], [])
    if ident is None and len(bare) == 1:
        ident = bare[0]
    if ident is None:
        sys.exit(f"{path}: no variable {pin}")
    changes = []  # (time in units, level)
    now = 0
    body = re.sub(r"\$comment.*?\$end", " ", body, flags=re.S)
    for word in body.split():
        if word.startswith("#"):
            now = int(word[1:])
        elif word[0] in "01xzXZ" and word[1:] == ident:
            changes.append((now, word[0]))
    return unit, changes


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("vcd")
    ap.add_argument("pin")
    ap.add_argument("--expect", type=int)
    ap.add_argument("--count", type=int, default=1)
    a = ap.parse_args()
    unit, changes = read(a.vcd, a.pin)
    widths = []
    rose = None
    last = None
    for t, level in changes:
        if level == last:
            continue
        first = last is None  # the level the recording starts with is no edge
        last = level
        if first:
            continue
        if level == "1":
            rose = t
        elif rose is not None:
            widths.append(round((t - rose) * unit * CPU_HZ))
            rose = None
    for w in widths:
        print(w)
    if a.expect is not None:
        wrong = [w for w in widths if w != a.expect]
        if wrong or len(widths) < a.count:
            print(f"{a.vcd}: {a.pin}: expected at least {a.count} pulses of {a.expect} T-states, "
                  f"found {len(widths)}: {widths}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
