"""master.asm names thesis-fixed's routines by address (EQUs marked '; thesis-fixed NAME'): each
must be that routine's address in the thesis-fixed map."""
import json
import re
import sys

syms = {s["name"]: s["value"] for s in json.load(open(sys.argv[2]))["symbols"]}
bad = 0
n = 0
for line in open(sys.argv[1]):
    m = re.match(r"(\w+)\s+EQU\s+([0-9A-F]+)H\s*;\s*thesis-fixed (\w+)", line)
    if m:
        n += 1
        want = syms.get(m.group(3))
        if want != int(m.group(2), 16):
            print(f"{m.group(1)} = {m.group(2)}H, but thesis-fixed's {m.group(3)} is {want:04X}H" if want is not None
                  else f"thesis-fixed has no {m.group(3)}")
            bad += 1
print(f"{n} thesis-fixed addresses checked, {bad} wrong")
sys.exit(1 if bad or n == 0 else 0)
