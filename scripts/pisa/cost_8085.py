#!/usr/bin/env python3
"""The 8085's computing cost of a run, from alp85 script's instruction trace (docs/pisa.md).

  alp85 script scripts/pisa/line_8085.alp --trace /tmp/line.csv
  scripts/pisa/cost_8085.py /tmp/line.csv build/firmware/thesis/thesis-fixed.json PARAM BITTI 240 8.602
  scripts/pisa/cost_8085.py record circle.csv DELAY_T START_X START_Y PATH_MM   (see from_record)

Counts the T-states from the first instruction at START to the first at END, and of those the
ones spent in the pulse delay (DELAY and DL, up to INPUT: the listing's L725-L740, which hold the
step pulse for D ms a half): what is left is computing. Prints
both, per step (STEPS unit steps) and per mm (PATH_MM), and in ms at 3.072 MHz.
"""
import csv
import json
import sys


def main():
    trace, mapfile, start, end, steps, path_mm = sys.argv[1:7]
    steps, path_mm = int(steps), float(path_mm)
    syms = {s["name"]: s["value"] for s in json.load(open(mapfile))["symbols"] if s["kind"] == "label"}
    dl, dl_end = syms["DELAY"], syms["INPUT"]
    t_start = t_end = None
    in_dl = 0
    prev_t = prev_pc = None
    with open(trace) as f:
        rows = csv.reader(f)
        for row in rows:
            if not row or not row[0].strip().isdigit():
                continue
            t, pc = int(row[0]), int(row[1], 16)
            if prev_t is not None and t_start is not None and dl <= prev_pc < dl_end:
                in_dl += t - prev_t
            if t_start is None and pc == syms[start]:
                t_start = t
            if t_start is not None and pc == syms[end]:
                t_end = t
                break
            prev_t, prev_pc = t, pc
    total = t_end - t_start
    compute = total - in_dl
    print(f"{start}..{end}: {total} T-states, of which DELAY/DL {in_dl}; computing {compute} T-states")
    print(f"per step: {compute / steps:.0f} T; per mm: {compute / path_mm:.0f} T = {compute / path_mm / 3072:.2f} ms at 3.072 MHz")
    print(f"whole run per mm: {total / path_mm:.0f} T = {total / path_mm / 3072:.2f} ms")




def from_record(record, delay_per_step, start_x, start_y, path_mm):
    """A run too long to trace: its recording (alp85 script `record`, every 1 ms) from the moment
    the commanded position stands at (start_x, start_y) to its last change; each step calls the
    pulse delay once (delay_per_step T-states, measured from a trace at the same D)."""
    t0 = t1 = None
    prev = None
    steps = 0
    for r in csv.DictReader(open(record)):
        p = (int(r["x_commanded"]), int(r["y_commanded"]))
        t = float(r["t_ms"])
        if t0 is None and p == (start_x, start_y):
            t0 = t
        if t0 is not None and prev is not None and p != prev:
            steps += abs(p[0] - prev[0]) + abs(p[1] - prev[1])
            t1 = t
        prev = p
    total = (t1 - t0) * 3072
    compute = total - steps * delay_per_step
    print(f"from ({start_x},{start_y}): {steps} steps in {t1 - t0:.0f} ms = {total:.0f} T-states; "
          f"computing {compute:.0f} T-states ({compute / steps:.0f} a step)")
    print(f"per mm: {compute / path_mm:.0f} T = {compute / path_mm / 3072:.2f} ms at 3.072 MHz")


if __name__ == "__main__":
    if sys.argv[1] == "record":
        from_record(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6]))
    else:
        main()
