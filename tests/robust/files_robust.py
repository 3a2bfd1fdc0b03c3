"""Files, inputs and arguments of the alp85 command line and its scripts (issue 24): outputs a
script names at run time on the files the session reads, devices and FIFOs as inputs, paths the
file system refuses, a recording that would not fit in memory, and arguments that were accepted
or misnamed. Every expectation is the documented behaviour (docs/testing.md "Bad input",
docs/scripting.md, each --help), never the tools' own earlier output.

  python3 files_robust.py BIN_DIR WORK_DIR CASE   (CASE: script_outputs, dap_outputs, gui_outputs, unbounded,
                                                   debug_script, fs_errors, record_cap, arguments)
"""
import json
import os
import re
import shutil
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from robust_harness import (ALP85, ASM85, ROOT, check, fresh, peak_resident_mb, run, run_case,  # noqa: E402
                            snapshot, write)


# 3E 05 3D C2 02 08 76: a countdown that halts
PROGRAM = "\tORG 0800H\nSTART:\tMVI A,5\nLOOP:\tDCR A\n\tJNZ LOOP\n\tHLT\n\tEND START\n"


def refused(args, d, what, code=2, stdin=None, says=None):
    """args must exit `code` with every file in d byte-identical and none added."""
    before = snapshot(d)
    rc, out, err = run(args, d, stdin=stdin)
    check(rc == code, f"{what}: exit {rc}, expected {code} ({(err or out).strip()[:300]})")
    after = snapshot(d)
    check(after == before, f"{what}: files changed or added: {sorted(set(after) ^ set(before)) or 'contents'}")
    if says:
        check(says in err + out, f"{what}: the message should say {says!r}: {(err + out).strip()[:300]}")
    return err + out


def script_outputs():
    """save, record and plot in a script may name no file the session reads: exit 2, input intact."""
    d = fresh("script_outputs")

    def refused(*args, **kwargs):  # each case from clean sources: one destroyed must not fail the next
        write(d, "x.asm", PROGRAM)
        write(d, "inc.alp", "reset\n")
        write(d, "p.svg", "reset\n")
        return globals()["refused"](*args, **kwargs)

    write(d, "x.asm", PROGRAM)
    # The reproduction.
    write(d, "a.alp", "load x.asm\nsave x.asm\n")
    refused([ALP85, "script", "a.alp"], d, "script: save over the loaded source", says="destroy")
    write(d, "b.alp", "load x.asm\nrecord b.alp\nrun 1ms\nrecord stop\n")
    refused([ALP85, "script", "b.alp"], d, "script: record over the script itself")
    # plot writes .svg or .png only: over an included script of that name.
    write(d, "c.alp", "include p.svg\nload x.asm\nrecord r.csv\nrun 2ms\nplot toolpath p.svg\n")
    refused([ALP85, "script", "c.alp"], d, "script: plot over an included script")
    write(d, "inc.alp", "reset\n")
    write(d, "m.alp", "load x.asm\ninclude inc.alp\nsave inc.alp\n")
    refused([ALP85, "script", "m.alp"], d, "script: save over an included script")
    # An output before the read it destroys: `save` on line 1, `load` on line 2.
    write(d, "e.alp", "save x.asm\nload x.asm\n")
    refused([ALP85, "script", "e.alp"], d, "script: save over a source loaded on a later line")
    # Command-line outputs on what the script reads beyond itself and its loads.
    write(d, "j.alp", "load x.asm\ninclude inc.alp\nrun 1ms\n")
    refused([ALP85, "script", "j.alp", "--junit", "inc.alp"], d, "script --junit an included script")
    write(d, "mk.alp", "load x.asm\nreset\nsave snap.snp\n")
    write(d, "x.asm", PROGRAM)
    rc, _, err = run([ALP85, "script", "mk.alp"], d)
    check(rc == 0 and os.path.exists(os.path.join(d, "snap.snp")), f"making the snapshot: {rc} {err}")
    write(d, "r.alp", "restore snap.snp\nrun 1ms\n")
    refused([ALP85, "script", "r.alp", "--trace", "snap.snp"], d, "script --trace a restored snapshot")
    refused([ALP85, "script", "r.alp", "--junit", "snap.snp"], d, "script --junit a restored snapshot")
    # A script's output on a command-line output: named as such, not "No such file or directory".
    write(d, "o.alp", "load x.asm\nreset\nsave o.snap\n")
    err = refused([ALP85, "script", "o.alp", "--trace", "o.snap"], d, "script --trace o.snap with save o.snap")
    check("No such file" not in err and "--trace" in err, f"--trace and save on one file: message: {err}")
    # Not refused: a snapshot saved, restored and saved again; the same snapshot twice.
    write(d, "ok.alp", "load x.asm\nreset\nsave s2.snp\nrestore s2.snp\nsave s2.snp\n")
    write(d, "x.asm", PROGRAM)
    rc, _, err = run([ALP85, "script", "ok.alp"], d)
    check(rc == 0, f"save, restore, save one snapshot: exit {rc} {err}")
    # The debugger: its console (commands from standard input) and --script.
    # docs/debugging.md: a command that fails in a batch session is status 1; the files stay.
    refused([ALP85, "debug", "x.asm", "--batch"], d, "debug console: save over the loaded source", code=1,
            stdin="save x.asm\n", says="destroy")
    refused([ALP85, "debug", "x.asm", "--batch"], d, "debug console: record over the loaded source", code=1,
            stdin="record x.asm\nrun 1ms\nrecord stop\n")
    write(d, "s.gdb", "save s.gdb\n")
    refused([ALP85, "debug", "x.asm", "--script", "s.gdb", "--batch"], d, "debug --script: save over the script", code=1)
    write(d, "t.gdb", "restore snap.snp\nsave snap.snp\n")
    refused([ALP85, "debug", "x.asm", "--script", "t.gdb", "--batch"], d, "debug --script: save over a restored snapshot",
            code=1)


class Dap:
    def __init__(self, cwd):
        self.p = subprocess.Popen([ALP85, "dap"], cwd=cwd, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL)
        self.seq = 0
        self.msgs = []
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        f = self.p.stdout
        while True:
            line = f.readline()
            if not line:
                return
            if line.lower().startswith(b"content-length:"):
                n = int(line.split(b":")[1])
                while f.readline() not in (b"\r\n", b"\n", b""):
                    pass
                self.msgs.append(json.loads(f.read(n)))

    def request(self, command, arguments=None, timeout=30):
        self.seq += 1
        body = json.dumps({"seq": self.seq, "type": "request", "command": command, "arguments": arguments or {}}).encode()
        self.p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.p.stdin.flush()
        t0 = time.time()
        while time.time() - t0 < timeout:
            for m in self.msgs:
                if m.get("type") == "response" and m.get("request_seq") == self.seq:
                    return m
            time.sleep(0.02)
        return None

    def close(self):
        try:
            self.request("disconnect", {}, timeout=5)
        except (BrokenPipeError, OSError):
            pass
        try:
            self.p.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.p.kill()
            self.p.wait()


def dap_outputs():
    """The DAP REPL's save goes through the same session: refused, the launched program intact."""
    d = fresh("dap_outputs")
    write(d, "x.asm", PROGRAM)
    before = snapshot(d)
    dap = Dap(d)
    try:
        dap.request("initialize", {"adapterID": "alp85"})
        r = dap.request("launch", {"program": "x.asm", "cwd": d, "stopOnEntry": True, "monitor": False})
        check(r is not None and r.get("success"), f"dap launch: {r}")
        dap.request("configurationDone")
        r = dap.request("evaluate", {"expression": "save x.asm", "context": "repl"})
        check(r is not None and not r.get("success"), f"dap REPL save x.asm: answered {r}")
        check(r is not None and "destroy" in json.dumps(r), f"dap REPL save x.asm: message: {r}")
    finally:
        dap.close()
    check(snapshot(d) == before, "dap REPL save x.asm: the program changed")


def gui_outputs():
    """gui --screenshot on a file the script includes: refused (2) after the script is read, the
    file intact. The window needs a display: xvfb-run (SKIP when it is missing)."""
    xvfb = shutil.which("xvfb-run")
    if not xvfb:
        print("SKIP: xvfb-run is missing")
        return
    d = fresh("gui_outputs")
    write(d, "inc.alp", "reset\n")
    write(d, "g.alp", "include inc.alp\nmonitor\nreset\nrun 10ms\n")
    e = dict(os.environ)
    before = snapshot(d)
    # alp85's own exit status, said by the shell xvfb-run starts: xvfb-run exits 5 when it cannot
    # clean up its temporary directory, whatever the program did (seen under a loaded parallel run).
    p = subprocess.run([xvfb, "-a", "sh", "-c", '"$@"; echo "alp85 exit $?" >&2', "sh",
                        ALP85, "gui", "--script", "g.alp", "--screenshot", "inc.alp"], cwd=d,
                       capture_output=True, text=True, env=e, timeout=120)
    status = re.search(r"alp85 exit (\d+)", p.stderr)
    code = int(status.group(1)) if status else p.returncode
    check(code == 2 and "destroy" in p.stderr, f"gui --screenshot an included script: exit {code}: {p.stderr}")
    check(snapshot(d) == before, "gui --screenshot an included script: files changed")


def unbounded():
    """A device or an endless FIFO as an input: refused at once (seconds, not gigabytes)."""
    d = fresh("unbounded")
    write(d, "x.asm", PROGRAM)
    for name in ["z.hex", "z.bin", "z.alp", "z.com", "z.nc", "z.tape", "z.json"]:
        os.symlink("/dev/zero", os.path.join(d, name))
    os.symlink("/dev/urandom", os.path.join(d, "u.alp"))
    write(d, "inc.alp", "include z.alp\n")
    cases = [
        ([ALP85, "script", "/dev/zero"], "script /dev/zero", 2),
        ([ALP85, "script", "u.alp"], "script a link to /dev/urandom", 2),
        ([ALP85, "script", "inc.alp"], "script include /dev/zero", 2),
        ([ALP85, "cpm", "z.com"], "cpm /dev/zero", 1),
        ([ALP85, "gcode", "z.nc", "-o", "out.hex"], "gcode /dev/zero", 2),
        ([ALP85, "disasm", "z.hex"], "disasm .hex /dev/zero", 1),
        ([ALP85, "disasm", "z.bin", "--org", "0"], "disasm .bin /dev/zero", 1),
        ([ALP85, "disasm", "x.asm", "--map", "z.json"], "disasm --map /dev/zero", 1),
        ([ALP85, "pisa", "z.tape"], "pisa /dev/zero", 1),
        ([ALP85, "run", "z.hex"], "run /dev/zero", 2),
    ]
    for args, what, code in cases:
        t0 = time.time()
        rc, _, err = run(args, d, timeout=20)
        check(rc == code, f"{what}: exit {rc}, expected {code}: {err.strip()[:200]}")
        check(time.time() - t0 < 10, f"{what}: took {time.time() - t0:.1f} s")
        check("device" in err, f"{what}: the message should say it is a device: {err.strip()[:200]}")
    # A FIFO is read, up to the cap of its kind (a script: 4 MiB, docs/testing.md).
    fifo = os.path.join(d, "f.alp")
    os.mkfifo(fifo)

    def feed(n):
        try:
            with open(fifo, "wb") as f:
                f.write(b"#" * n + b"\n")
        except BrokenPipeError:
            pass

    t = threading.Thread(target=feed, args=(5 << 20,))
    t.start()
    rc, _, err = run([ALP85, "script", "f.alp"], d, timeout=30)
    t.join(10)
    check(rc == 2 and "4 MiB" in err, f"script from a FIFO of 5 MiB: exit {rc}: {err.strip()[:200]}")
    t = threading.Thread(target=feed, args=(100,))
    t.start()
    rc, out, err = run([ALP85, "script", "f.alp"], d, timeout=30)
    t.join(10)
    check(rc == 0, f"script from a FIFO holding a comment: exit {rc}: {err.strip()[:200]}")


def debug_script():
    """An unreadable or empty debug --script is a usage error (2) that names it."""
    d = fresh("debug_script")
    write(d, "x.asm", PROGRAM)
    write(d, "empty.gdb", "")
    rc, _, err = run([ALP85, "debug", "x.asm", "--script", "empty.gdb", "--batch"], d)
    check(rc == 2 and "empty.gdb" in err and "empty" in err, f"debug --script empty.gdb: exit {rc}: {err}")
    p = write(d, "locked.gdb", "info registers\n")
    os.chmod(p, 0)
    if os.access(p, os.R_OK):  # root reads it anyway
        print("skipped: the unreadable script (running as root)")
    else:
        rc, _, err = run([ALP85, "debug", "x.asm", "--script", "locked.gdb", "--batch"], d)
        check(rc == 2 and "locked.gdb" in err and "ermission" in err, f"debug --script locked.gdb: exit {rc}: {err}")
    os.chmod(p, 0o644)


def fs_errors():
    """A link loop or a 300-character name: a sentence, never `filesystem error`, and the status
    the command documents for an input it cannot read."""
    d = fresh("fs_errors")
    os.symlink("loop.asm", os.path.join(d, "loop.asm"))
    os.symlink("loop.alp", os.path.join(d, "loop.alp"))
    long_name = "n" * 300 + ".asm"
    for path, what in [("loop.asm", "a symbolic link loop"), (long_name, "a 300-character name")]:
        alp = path.replace(".asm", ".alp")
        for args, code in [([ALP85, "run", path], 2), ([ALP85, "script", alp], 2), ([ALP85, "debug", path, "--batch"], 2),
                           ([ALP85, "debug", "--script", alp, "--batch"], 2), ([ALP85, "cpm", path], 1),
                           ([ALP85, "disasm", path], 1), ([ALP85, "pisa", path], 1), ([ALP85, "gcode", path, "-o", "out.hex"], 2)]:
            rc, _, err = run(args, d, stdin="")
            name = f"{args[1]} {what}"
            check("filesystem error" not in err, f"{name}: raw filesystem error: {err.strip()[:200]}")
            check(rc == code, f"{name}: exit {rc}, expected {code}: {err.strip()[:200]}")
            check("symbolic links" in err or "too long" in err, f"{name}: no sentence: {err.strip()[:200]}")


def record_cap():
    """record every 1t: at most ToolRecorder::kMaxSamples (1,000,000) samples, written, and said."""
    d = fresh("record_cap")
    write(d, "x.asm", PROGRAM)
    # 500 ms at 3.072 MHz (docs/board.md: the 6.144 MHz crystal divided by two) is 1,536,000 T-states: past the cap.
    write(d, "r.alp", "load x.asm\nreset\nrecord r.csv every 1t\nrun 500ms\nrecord stop\n")
    rc, peak_500, err = peak_resident_mb([ALP85, "script", "r.alp"], d)
    rows = 0
    if os.path.exists(os.path.join(d, "r.csv")):
        with open(os.path.join(d, "r.csv"), "rb") as f:
            rows = sum(1 for _ in f)
    check(rc == 1, f"record every 1t over the cap: exit {rc}: {err.strip()[:200]}")
    check(rows == 1 + 1_000_000, f"record every 1t: {rows} lines, expected the header and 1,000,000 samples")
    # What it keeps is bounded by the cap, not by the run: recording twice as long (3,072,000
    # T-states) takes no more memory. Kept in full, 1,536,000 more samples would add some 190 MB
    # (the release build's 128 MB for the first million); the sanitizers' own overhead is the same
    # in both runs, so the difference holds in either build.
    write(d, "r2.alp", "load x.asm\nreset\nrecord r2.csv every 1t\nrun 1000ms\nrecord stop\n")
    rc2, peak_1000, err2 = peak_resident_mb([ALP85, "script", "r2.alp"], d)
    print(f"record every 1t: peak resident {peak_500:.0f} MB over 500 ms, {peak_1000:.0f} MB over 1000 ms")
    check(rc2 == 1, f"record every 1t over the cap for 1000 ms: exit {rc2}: {err2.strip()[:200]}")
    check(peak_1000 - peak_500 < 30, f"record every 1t: {peak_500:.0f} MB over 500 ms but {peak_1000:.0f} MB over 1000 ms")


def arguments():
    d = fresh("arguments")
    write(d, "x.asm", PROGRAM)
    # gui: NaN and bad --click-line are usage errors named before any window (no display here).
    for args, word in [(["--seconds", "nan"], "--seconds"), (["--scale", "nan"], "--scale"),
                       (["--debug", "--click-line", "x.asm:999999999999999999999999999"], "--click-line"),
                       (["--debug", "--click-line", "x.asm:-5"], "--click-line"),
                       (["--click-line", "x.asm:3"], "--debug")]:
        rc, _, err = run([ALP85, "gui", "x.asm"] + args, d)
        check(rc == 2 and word in err and "display" not in err, f"gui {' '.join(args)}: exit {rc}: {err.strip()[:200]}")
    # An input that exists but is no file is named for what it is, not "no such file".
    os.mkdir(os.path.join(d, "d.asm"))
    os.mkdir(os.path.join(d, "d.alp"))
    os.mkdir(os.path.join(d, "d.hex"))
    os.mkfifo(os.path.join(d, "p.asm"))
    os.symlink("gone.asm", os.path.join(d, "dangling.asm"))
    for args, what in [(["run", "d.asm"], "directory"), (["debug", "--script", "d.alp", "--batch"], "directory"),
                       (["disasm", "x.asm", "--map", "d.hex"], "directory"), (["run", "/dev/null"], "device"),
                       (["debug", "/dev/null", "--batch"], "device"), (["script", "d.alp"], "directory"),
                       (["run", "dangling.asm"], "gone.asm"), (["debug", "dangling.asm", "--batch"], "gone.asm"),
                       (["run", "p.asm"], "FIFO"), (["debug", "p.asm", "--batch"], "FIFO"),
                       (["cpm", "d.asm"], "directory"), (["gcode", "d.asm", "-o", "out.hex"], "directory")]:
        rc, _, err = run([ALP85] + args, d, stdin="")
        check(rc in (1, 2) and what in err and "no such file" not in err, f"{' '.join(args)}: exit {rc}: {err.strip()[:200]}")
    write(d, "s.alp", "load x.asm\nreset\nrun 1ms\n")
    before = snapshot(d)
    rc, _, err = run([ALP85, "script", "s.alp", "--junit", ""], d)
    check(rc == 2 and "--junit" in err, f"script --junit '': exit {rc}: {err.strip()[:200]}")
    rc, _, err = run([ASM85, "x.asm", "-o", ""], d)
    check(rc == 2 and "-o" in err, f"asm85 -o '': exit {rc}: {err.strip()[:200]}")
    write(d, "p.com", bytes([0xC3, 0x00, 0x00]), "wb")  # JMP 0: warm boot at once
    write(d, "x.nc", "G01 F500 X10 Y10\n")
    shutil.copy(os.path.join(ROOT, "tests/pisa/good.tape"), os.path.join(d, "t.tape"))
    before = snapshot(d)
    for args, opt in [(["cpm", "p.com", "--trace", ""], "--trace"), (["disasm", "x.asm", "-o", ""], "--output"),
                      (["gcode", "x.nc", "-o", ""], "--output"), (["pisa", "t.tape", "--record", ""], "--record"),
                      (["gui", "x.asm", "--screenshot", ""], "--screenshot")]:
        rc, _, err = run([ALP85] + args, d)
        check(rc == 2 and opt in err, f"{' '.join(args)}'': exit {rc}: {err.strip()[:200]}")
    check(snapshot(d) == before, f"empty output names: files changed: {sorted(set(snapshot(d)) ^ set(before))}")
    # docs/scripting.md: nesting deeper than 16 is an error, so 16 levels are not.
    for depth, ok in [(16, True), (17, False)]:
        sub = fresh(f"arguments/include{depth}")
        write(sub, "top.alp", "include l1.alp\n")
        for i in range(1, depth):
            write(sub, f"l{i}.alp", f"include l{i + 1}.alp\n")
        write(sub, f"l{depth}.alp", "print \"deep\"\n")
        rc, out, err = run([ALP85, "script", "top.alp"], sub)
        if ok:
            check(rc == 0 and "deep" in out, f"16 levels of include: exit {rc}: {err.strip()[:300]}")
        else:
            check(rc == 2 and "deeper than 16" in err, f"17 levels of include: exit {rc}: {err.strip()[:300]}")


run_case({"script_outputs": script_outputs, "dap_outputs": dap_outputs, "gui_outputs": gui_outputs, "unbounded": unbounded, "debug_script": debug_script,
 "fs_errors": fs_errors, "record_cap": record_cap, "arguments": arguments})
