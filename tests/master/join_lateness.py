"""How late the master program's pulses leave around each join of a sampling path: every sample's
pulse OUT (port F9H, an X or Y pulse bit set) logged in T-states by the debugger, against the host
model's time for it (sampling_ref.py: 6144 T-states a sample plus its pulse's place, the phase),
less the stretch's median offset (a stretch: the run between Z moves, which stop the timer; the
grid within one is exact and most pulses leave at their place, so that offset is the grid's and the
rest is lateness; negative: early, as a chord's last pulse, sent right after its sample's work).

Prints, for each chord's join, the lateness of the pulse the set-up holds up (the last sample of the
chord before, whose output leaves in the sample after the set-up) and of the three after it, then
the largest lateness and how many pulses leave more than 3000 T-states late (feed_replay.py: joins
1 ms late lose no step on the physical motors, 4000 T-states lose some). A measurement, not a test
(docs/results.md, the sampling method at 1500 mm/min).

  python3 join_lateness.py ALP85 PATH.hex WORKDIR [--path N]
  JL_ALL=1 python3 join_lateness.py ...   (also every moving sample: its lateness and phase)
"""
import os
import re
import subprocess
import sys

import contour_ref as ref
import sampling_ref as S

LATE_OK = 3000          # T-states: feed_replay.py's joins "1 ms late", none lost


def main():
    args = sys.argv[1:]
    pn = 1
    if "--path" in args:
        i = args.index("--path")
        pn = int(args[i + 1])
        del args[i:i + 2]
    alp85, hexf, work = args
    os.makedirs(work, exist_ok=True)
    hexf = os.path.abspath(hexf)
    gdb = os.path.join(work, "join_lateness.gdb")
    with open(gdb, "w") as f:
        f.write("\n".join([
            "motor physical", "firmware thesis-fixed", "firmware master", f"load {hexf}", "reset",
            'wait display "-ALP 85-" timeout 1s', "type R 7 3 0 0 0 EXEC",
            'wait display "P=-     " timeout 100ms', f"type {pn}",
            "watch port 0F9H out", "commands", "print/d $T", "print/d A", "continue", "end",
            "type EXEC", "continue", ""]))
    out = subprocess.run([alp85, "debug", "--script", gdb, "--batch", "--no-history"],
                         capture_output=True, text=True).stdout
    vals = [int(v) for v in re.findall(r"^\$\d+ = (-?\d+)", out, re.M)]
    pulses = [vals[i] for i in range(0, len(vals) - 1, 2) if vals[i + 1] & 0x05]
    run = S.Run(ref.paths(ref.read_hex(hexf))[pn - 1])
    model = [(i, i * S.PERIOD + run.phases[i]) for i, d in enumerate(run.samples) if d != (0, 0)]
    if len(pulses) != len(model):
        sys.exit(f"{len(pulses)} pulse OUTs logged, the model has {len(model)} moving samples")
    off = [t - m for t, (_, m) in zip(pulses, model)]
    late, start = [], 0
    for k in range(1, len(off) + 1):           # stretches: a jump of 50000 T-states is a Z move
        if k == len(off) or abs(off[k] - off[k - 1]) > 50000:
            base = sorted(off[start:k])[(k - start) // 2]
            late += [o - base for o in off[start:k]]
            start = k
    at = {i: k for k, (i, _) in enumerate(model)}
    if os.environ.get("JL_ALL"):
        for k, (i, _) in enumerate(model):
            print("sample %d late %d phase %d" % (i, late[k], run.phases[i]))
    for j in sorted(run.joins):
        row = [late[at[i]] if i in at else None for i in range(j - 1, j + 3)]
        print("join at sample %5d: " % j + "  ".join("%6s" % ("-" if v is None else v) for v in row))
    print("largest lateness %d T-states; %d of %d pulses more than %d late"
          % (max(late), sum(v > LATE_OK for v in late), len(late), LATE_OK))


if __name__ == "__main__":
    main()
