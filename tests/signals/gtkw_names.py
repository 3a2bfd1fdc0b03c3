#!/usr/bin/env python3
"""Every signal a GTKWave save file shows is a variable of the VCD: gtkw_names.py FILE.vcd FILE.gtkw"""
import re
import sys

vcd, gtkw = sys.argv[1], sys.argv[2]
head = open(vcd, encoding="ascii").read().partition("$enddefinitions")[0]
names, scopes = set(), []
for m in re.finditer(r"\$(scope|upscope|var)\b(.*?)\$end", head, re.S):
    kind, rest = m.group(1), m.group(2).split()
    if kind == "scope":
        scopes.append(rest[1])
    elif kind == "upscope":
        scopes.pop()
    else:
        names.add(".".join(scopes + [rest[3]]))
shown = [l.strip() for l in open(gtkw, encoding="ascii") if l.strip() and l.strip()[0] not in "[@-*"]
missing = [s for s in shown if s not in names]
if missing or not shown:
    sys.exit(f"{gtkw}: not in {vcd}: {missing or 'no signals'}")
print(f"{len(shown)} signals of {gtkw} in {vcd}")
