"""Hostile input to the command-line tools (issue 23): outputs on inputs, signals while writing,
directories and bad numbers as arguments, and the messages that must name what went wrong.
Every expectation is the documented behaviour (README's exit statuses, each --help), never the
tools' own earlier output.

  python3 cli_robust.py BIN_DIR WORK_DIR CASE      (CASE: same_path, signals, bad_input, messages,
                                                    disasm, debug_interrupt, debug_commands, max_time, ...)
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from robust_harness import ALP85, ASM85, PISA_ASM, ROOT, check, fresh, run, run_case, snapshot, write  # noqa: E402


PROGRAM = "\tORG 0800H\nSTART:\tMVI A,5\nLOOP:\tDCR A\n\tJNZ LOOP\n\tHLT\n\tEND START\n"  # 3E 05 3D C2 02 08 76


def refused(args, d, what, code=2):
    """args must exit `code` having changed and added nothing in d."""
    before = snapshot(d)
    rc, out, err = run(args, d)
    check(rc == code, f"{what}: exit {rc}, expected {code} ({err.strip()})")
    after = snapshot(d)
    check(after == before, f"{what}: files changed or added: {sorted(set(after) ^ set(before)) or 'contents'}")
    return err


def same_path():
    d = fresh("same_path")
    write(d, "x.asm", PROGRAM)
    write(d, "main.asm", "\tINCLUDE inc.asm\n\tEND\n")
    write(d, "inc.asm", "\tORG 0\n\tNOP\n")
    for opt in ["-o", "--lst", "--map", "--bin"]:
        err = refused([ASM85, "x.asm", opt, "x.asm"], d, f"asm85 x.asm {opt} x.asm")
        check("x.asm" in err and "destroy" in err, f"asm85 {opt}: the message names the source: {err}")
    refused([ASM85, "x.asm", "-o", "./sub/../x.asm"], d, "asm85 -o the source spelled another way")
    os.symlink("x.asm", os.path.join(d, "link.asm"))
    refused([ASM85, "x.asm", "-o", "link.asm"], d, "asm85 -o a link to the source")
    refused([ASM85, "main.asm", "-o", "inc.asm"], d, "asm85 -o an INCLUDEd file")
    refused([ASM85, "main.asm", "--lst", "inc.asm"], d, "asm85 --lst an INCLUDEd file")
    err = refused([ASM85, "x.asm", "-o", "out.hex", "--lst", "out.hex"], d, "asm85 -o and --lst on one file")
    check("one file" in err, f"asm85 two outputs: message: {err}")
    refused([ASM85, "x.asm", "--map", "m.json", "--bin", "./m.json"], d, "asm85 --map and --bin on one file")
    # pisa-asm
    shutil.copy(os.path.join(ROOT, "firmware/pisa/interp.pasm"), os.path.join(d, "p.pasm"))
    for opt in ["-o", "--lst", "--map"]:
        refused([PISA_ASM, "p.pasm", opt, "p.pasm"], d, f"pisa-asm {opt} the source")
    refused([PISA_ASM, "p.pasm", "-o", "a.rom", "--map", "a.rom"], d, "pisa-asm two outputs on one file")
    # alp85 gcode, pisa, cpm, disasm, script, gui
    write(d, "x.nc", "G01 F500 X10 Y10\n")
    refused([ALP85, "gcode", "x.nc", "-o", "x.nc"], d, "gcode -o the G-code file")
    shutil.copy(os.path.join(ROOT, "tests/pisa/good.tape"), os.path.join(d, "t.tape"))
    refused([ALP85, "pisa", "t.tape", "--record", "t.tape"], d, "pisa --record the tape")
    refused([ALP85, "pisa", "t.tape", "--rom", "p.pasm", "--record", "p.pasm"], d, "pisa --record the program")
    refused([ALP85, "pisa", "t.tape", "--record", "a.svg", "--plot", "a.svg"], d, "pisa --record and --plot on one file")
    write(d, "p.com", bytes([0xC3, 0x00, 0x00]), "wb")  # JMP 0: warm boot at once
    refused([ALP85, "cpm", "p.com", "--trace", "p.com"], d, "cpm --trace the program")
    rc, _, err = run([ASM85, "x.asm", "-o", "c.hex", "--map", "c.json"], d)
    check(rc == 0, f"asm85 c.hex: {err}")
    refused([ALP85, "disasm", "c.hex", "-o", "c.hex"], d, "disasm -o the image")
    refused([ALP85, "disasm", "c.hex", "--map", "c.json", "-o", "c.json"], d, "disasm -o the map")
    write(d, "s.alp", "load c.hex\nreset\nrun 1ms\n")
    refused([ALP85, "script", "s.alp", "--trace", "s.alp"], d, "script --trace the script")
    refused([ALP85, "script", "s.alp", "--junit", "s.alp"], d, "script --junit the script")
    refused([ALP85, "script", "s.alp", "--trace", "c.hex"], d, "script --trace a program it loads")
    refused([ALP85, "script", "s.alp", "--trace", "r.out", "--junit", "r.out"], d, "script --trace and --junit on one file")
    refused([ALP85, "gui", "x.asm", "--screenshot", "x.asm"], d, "gui --screenshot the firmware source")
    refused([ALP85, "gui", "--script", "s.alp", "--screenshot", "s.alp"], d, "gui --screenshot the script")
    # Not refused: distinct outputs, and /dev/null twice.
    rc, _, err = run([ASM85, "x.asm", "-o", "y.hex", "--lst", "/dev/null", "--map", "/dev/null"], d)
    check(rc == 0 and os.path.exists(os.path.join(d, "y.hex")), f"asm85 distinct outputs: {rc} {err}")


def leftovers(d):
    return [n for n in os.listdir(d) if ".tmp" in n or "partial" in n or "plot-tmp" in n]


def killed(args, d, sig, what, settle=1.5, wait_for=None):
    p = subprocess.Popen(args, cwd=d, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True)
    t0 = time.time()
    if wait_for:  # until the temporary exists: the kill lands mid-write
        while time.time() - t0 < 60 and not wait_for():
            time.sleep(0.05)
        check(wait_for(), f"{what}: the writer never started")
    else:
        time.sleep(settle)
    check(p.poll() is None, f"{what}: it ended before the signal")
    p.send_signal(sig)
    try:
        p.wait(timeout=30)
    except subprocess.TimeoutExpired:
        p.kill()
        p.wait()
        check(False, f"{what}: still running 30 s after {sig.name}")
    check(p.returncode == -sig, f"{what}: ended with {p.returncode}, expected death by {sig.name}")
    left = leftovers(d)
    check(not left, f"{what}: left {left}")
    return p


def signals():
    d = fresh("signals")
    write(d, "long.alp", "load loop.asm\nreset\nrun 600s\n")
    write(d, "loop.asm", "\tORG 0\nTOP:\tJMP TOP\n\tEND\n")
    write(d, "loop.com", bytes([0xC3, 0x00, 0x01]), "wb")  # JMP 0100H forever
    write(d, "x.asm", PROGRAM)
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        tmp_of = lambda name: (lambda: any(n.startswith(name + ".tmp") for n in os.listdir(d)))
        killed([ALP85, "script", "long.alp", "--trace", "t.csv"], d, sig, f"script --trace, {sig.name}",
               wait_for=tmp_of("t.csv"))
        check(not os.path.exists(os.path.join(d, "t.csv")), f"script --trace {sig.name}: a trace appeared")
        killed([ALP85, "cpm", "loop.com", "--trace", "c.csv"], d, sig, f"cpm --trace, {sig.name}",
               wait_for=tmp_of("c.csv"))
        # asm85 writes every output to a temporary, then the devices: a FIFO with no reader holds it
        # there, with x.hex's temporary on disk.
        fifo = os.path.join(d, "fifo.lst")
        if os.path.exists(fifo):
            os.unlink(fifo)
        os.mkfifo(fifo)
        killed([ASM85, "x.asm", "-o", "x.hex", "--map", "x.json", "--lst", "fifo.lst"], d, sig,
               f"asm85 with outputs staged, {sig.name}", wait_for=tmp_of("x.hex"))
        check(not os.path.exists(os.path.join(d, "x.hex")), f"asm85 {sig.name}: x.hex appeared")
        os.unlink(fifo)
    # A signal the user set to be ignored stays ignored (nohup): the run goes on.
    p = subprocess.Popen([ALP85, "cpm", "loop.com", "--trace", "n.csv", "--max-tstates", "50000"], cwd=d,
                         stdout=subprocess.DEVNULL, preexec_fn=lambda: signal.signal(signal.SIGHUP, signal.SIG_IGN))
    p.wait(timeout=60)
    check(p.returncode == 4 and os.path.exists(os.path.join(d, "n.csv")), f"cpm with SIGHUP ignored: {p.returncode}")


def debug_expressions():
    """alp85 debug --batch: the expressions that trapped give a value or an error (status 1)."""
    d = fresh("debug_expressions")
    rc, out, err = run([ALP85, "debug", "--batch", "--no-history"], d, stdin="print (1<<63)/-1\nprint 7 % -1\n")
    check(rc == 0 and "= -9223372036854775808\n" in out and "(0)" in out, f"debug: (1<<63)/-1: {rc}\n{out}{err}")
    for text, why in [("(" * 3000 + "1" + ")" * 3000, "nested too deeply"), ("+".join(["1"] * 200000), "too long"),
                      ("1/0", "division by zero")]:
        rc, out, err = run([ALP85, "debug", "--batch", "--no-history"], d, stdin=f"print {text}\nprint 6*7\n")
        check(rc == 1 and why in out + err and "(42)" in out, f"debug: print {text[:10]}...: {rc} {(out + err)[-300:]}")


def debug_interrupt():
    """Ctrl-C in alp85 debug --batch interrupts the run (as at the prompt); the session goes on."""
    d = fresh("debug_interrupt")
    write(d, "loop.asm", "\tORG 0\nTOP:\tJMP TOP\n\tEND\n")
    p = subprocess.Popen([ALP85, "debug", "--batch", "--no-history", os.path.join(d, "loop.asm")], cwd=d,
                         stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # A condition checked before every instruction (never true) keeps the run going for longer than
    # the test waits, however fast the host: 600 s of machine time at well under 100x real time.
    p.stdin.write("break TOP if A == 1\ncontinue\n")
    p.stdin.flush()
    time.sleep(2)
    p.send_signal(signal.SIGINT)  # during the run
    time.sleep(1)
    p.send_signal(signal.SIGINT)  # while it waits for the next command: the input goes on
    time.sleep(0.5)
    try:
        p.stdin.write("print 6*7\n")
        p.stdin.flush()
    except BrokenPipeError:
        check(False, "debug --batch: a Ctrl-C between commands ended the input")
    try:
        out, err = p.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        p.kill()
        out, err = p.communicate()
        check(False, "debug --batch: Ctrl-C did not interrupt the run")
    check(p.returncode == 0, f"debug --batch after Ctrl-C: exit {p.returncode}: {err}")
    check("interrupt" in out.lower(), f"debug --batch: the stop is not reported as an interrupt:\n{out}")
    check("42" in out, f"debug --batch: the next command did not run after the interrupt:\n{out}")


def bad_input():
    d = fresh("bad_input")
    for n in ["DIR.com", "DIR.hex", "DIR.bin", "DIR.alp", "DIR.tape"]:
        os.makedirs(os.path.join(d, n))
    for args, code, name in [
        ([ALP85, "cpm", "DIR.com"], 1, "DIR.com"),
        ([ALP85, "disasm", "DIR.hex"], 1, "DIR.hex"),
        ([ALP85, "disasm", "DIR.bin", "--org", "0800H"], 1, "DIR.bin"),
        ([ALP85, "script", "DIR.alp"], 2, "DIR.alp"),
        ([ALP85, "pisa", "DIR.tape"], 1, "DIR.tape"),
    ]:
        rc, _, err = run(args, d)
        check(rc == code, f"{' '.join(args[1:])}: exit {rc}, expected {code}")
        check(name in err and "directory" in err and "underflow" not in err and "holds no move" not in err,
              f"{' '.join(args[1:])}: message does not name the directory: {err}")
    write(d, "loop.com", bytes([0xC3, 0x00, 0x01]), "wb")
    for n in ["-1", "99999999999999999999999", "1e3", ""]:
        rc, _, err = run([ALP85, "cpm", "loop.com", "--max-tstates", n], d, timeout=20)
        check(rc == 2 and "--max-tstates" in err, f"cpm --max-tstates '{n}': exit {rc}: {err}")
    rc, _, _ = run([ALP85, "cpm", "loop.com", "--max-tstates", "1000"], d)
    check(rc == 4, f"cpm --max-tstates 1000: the limit ends the run with 4, got {rc}")
    for opt, v in [("--seconds", "-1"), ("--frames", "-5"), ("--seconds", "0")]:
        rc, _, err = run([ALP85, "gui", opt, v], d)
        check(rc == 2 and opt in err, f"gui {opt} {v}: exit {rc}: {err}")
    write(d, "u.asm", "\tDB X\n")
    for define in ["X=1+", "X=(", "1X=2"]:
        rc, _, err = run([ASM85, "u.asm", "-D", define], d)
        check(rc == 2 and "-D" in err, f"asm85 -D {define}: exit {rc}: {err}")
        check(not os.path.exists(os.path.join(d, "u.hex")), f"asm85 -D {define}: wrote u.hex")
    rc, _, err = run([ASM85, "u.asm", "-D", "X=1+2"], d)
    check(rc == 0, f"asm85 -D X=1+2 is good: {rc} {err}")
    write(d, "p.pasm", "\tEND\n")
    rc, _, err = run([PISA_ASM, "p.pasm", "-D", "X=1+"], d)
    check(rc == 2 and "-D" in err, f"pisa-asm -D X=1+: exit {rc}: {err}")


def messages():
    d = fresh("messages")
    # G-code: a number beyond any word of the machine is named, not wrapped; no UB (the
    # sanitizer pass runs this too).
    write(d, "big.nc", "G01 F500 X100000000000000000000 Y0\n")
    rc, _, err = run([ALP85, "gcode", "big.nc", "-o", "big.hex"], d)
    check(rc == 1 and "big.nc:1:10:" in err and "out of range" in err and "-46116" not in err, f"gcode X1e20: {rc} {err}")
    write(d, "g.nc", "G" + "9" * 400 + "\n")
    rc, _, err = run([ALP85, "gcode", "g.nc", "-o", "g.hex"], d)
    check(rc == 1 and "g.nc:1:1:" in err and "out of range" in err and "runtime error" not in err, f"gcode G9...9: {rc} {err}")
    write(d, "ok.nc", "G01 F500 X99999 Y0\n")  # in range as a word; beyond the travel: that message
    rc, _, err = run([ALP85, "gcode", "ok.nc", "-o", "ok.hex"], d)
    check(rc == 1 and "outside the table's travel" in err, f"gcode X99999: {rc} {err}")
    # pisa --plot into a folder that does not exist names the plot asked for.
    shutil.copy(os.path.join(ROOT, "tests/pisa/good.tape"), os.path.join(d, "t.tape"))
    rc, _, err = run([ALP85, "pisa", "t.tape", "--plot", "nodir/p.svg"], d)
    check(rc == 1 and "nodir/p.svg" in err and "plot-tmp" not in err and "partial" not in err, f"pisa --plot: {rc} {err}")
    # An output that cannot be written is status 1 (README), for every command.
    write(d, "ok.alp", "load x.asm\nreset\nrun 1ms\n")
    write(d, "x.asm", PROGRAM)
    for args in ([ALP85, "script", "ok.alp", "--trace", "nodir/t.csv"], [ALP85, "script", "ok.alp", "--junit", "nodir/j.xml"],
                 [ALP85, "gui", "--screenshot", "nodir/s.png"], [ALP85, "disasm", "x.asm", "-o", "nodir/x.lst"],
                 [ASM85, "x.asm", "-o", "nodir/x.hex"]):
        rc, _, err = run(args, d)
        check(rc == 1 and "nodir/" in err, f"{' '.join(args[1:])}: exit {rc}, expected 1: {err}")
    # Naming the unknown command; a caret under the bad firmware.
    rc, _, err = run([ALP85, "bogus"], d)
    check(rc == 2 and "'bogus'" in err and "A subcommand is required" not in err, f"alp85 bogus: {rc} {err}")
    rc, _, err = run([ALP85, "debug", "nosuchfw"], d)
    check(rc == 2 and err.startswith("alp85 debug:1:13: error: 'nosuchfw'") and
          "\n alp85 debug nosuchfw\n             ^\n" in err, f"alp85 debug nosuchfw: {rc} {err!r}")
    # A script that loads the thesis firmware without the monitor is told why it will hang.
    write(d, "nomon.alp", "firmware thesis-fixed\nreset\nrun 1ms\n")
    rc, _, err = run([ALP85, "script", "nomon.alp"], d)
    check("nomon.alp:1:1: warning:" in err and "monitor" in err, f"script without monitor: no hint: {err}")
    write(d, "mon.alp", "monitor\nfirmware thesis-fixed\nreset\nrun 1ms\n")
    rc, _, err = run([ALP85, "script", "mon.alp"], d)
    check(rc == 0 and "warning" not in err, f"script with the monitor: {rc} {err}")
    # A passing script that stops at its breakpoints and checks them prints no stop lines (-v does).
    write(d, "loop.asm", "\tORG 0\nTOP:\tNOP\n\tJMP TOP\n\tEND\n")
    write(d, "stops.alp", "load loop.asm\nreset\nbreak TOP\n" + "run 1ms\nexpect reg PC TOP\n" * 5)
    rc, out, err = run([ALP85, "script", "stops.alp"], d)
    check(rc == 0 and "stopped at" not in out + err, f"script with breakpoints is noisy: {rc}\n{out}{err}")
    rc, out, err = run([ALP85, "script", "-v", "stops.alp"], d)
    check(rc == 0 and "stopped at breakpoint" in out, f"script -v shows the stops: {rc}\n{out}")


def disasm():
    """disasm: an instruction that starts at --to is decoded whole; --source labels its targets."""
    d = fresh("disasm")
    write(d, "x.asm", PROGRAM)
    run([ASM85, "x.asm", "-o", "x.hex"], d)
    rc, out, err = run([ALP85, "disasm", "x.hex", "--no-symbols", "--from", "0800H", "--to", "0803H"], d)
    check(rc == 0 and out.endswith("0803  C2 02 08   JNZ 0802H\n"), f"disasm --to splits JNZ: {out}{err}")
    rc, out, err = run([ALP85, "disasm", "--monitor", "--from", "0", "--to", "20H"], d)
    last = out.strip().splitlines()[-1] if out.strip() else ""
    check(rc == 0 and " DB " not in last, f"disasm --monitor --to 20H ends in DB: {last}")
    rc, out, err = run([ALP85, "disasm", "x.hex", "--source", "-o", "y.asm"], d)
    src = open(os.path.join(d, "y.asm")).read() if rc == 0 else ""
    for want in ["START:\n", "L0802:\n", "JNZ L0802", "END START\n"]:
        check(want in src, f"disasm --source lacks {want!r}:\n{src}")
    rc, _, err = run([ASM85, "y.asm", "-o", "y.hex"], d)
    check(rc == 0, f"the --source output does not assemble: {err}")
    a = open(os.path.join(d, "x.hex")).read()
    b = open(os.path.join(d, "y.hex")).read() if rc == 0 else ""
    check(a == b, f"the --source output assembles to other bytes:\n{a}\n{b}")


def debug_commands():
    """Breakpoint commands that resume the run (jump, advance, run) end their list, as gdb's do,
    instead of running the next stop's commands inside them until the stack overflows (a SIGSEGV,
    exit 139); the session goes on to the next command."""
    d = fresh("debug_commands")
    # The reproduction, exactly: printf '...' | alp85 debug thesis-fixed --batch
    for resume in ("jump ANWEIN", "advance ANWEIN", "run 1ms"):
        for extra in ([], ["--no-history"]):
            stdin = f"break ANWEIN\ncommands\n{resume}\nend\ncontinue\nprint 6*7\n"
            what = f"debug --batch {' '.join(extra)} with '{resume}' in commands"
            try:
                rc, out, err = run([ALP85, "debug", "thesis-fixed", "--batch"] + extra, d, stdin=stdin, timeout=250)
            except subprocess.TimeoutExpired:
                check(False, f"{what}: no prompt again within 250 s")
                continue
            check(rc == 0, f"{what}: exit {rc}, expected 0: {err[-500:]}")
            tail = out[out.rfind("(alp85) print 6*7"):] if "(alp85) print 6*7" in out else ""
            check("42" in tail, f"{what}: print 6*7 did not answer 42 after the run:\n{out[-800:]}")


def determinism():
    """The same inputs give the same bytes: a trace and a recording made twice are identical."""
    d = fresh("determinism")
    write(d, "t.alp", "monitor\nfirmware thesis-fixed\nreset\nwait display \"-ALP 85-\" timeout 1s\n"
                      "type R 7 0 8 0 0 EXEC\nrun 20ms\n")
    outs = []
    for n in ("a", "b"):
        rc, _, err = run([ALP85, "script", "t.alp", "--trace", f"{n}.csv"], d)
        check(rc == 0, f"script --trace {n}: {rc} {err}")
        outs.append(open(os.path.join(d, f"{n}.csv"), "rb").read() if rc == 0 else b"")
    check(outs[0] == outs[1] and len(outs[0]) > 100000, f"two traces differ ({len(outs[0])} and {len(outs[1])} bytes)")


def max_time():
    """--max-time bounds the machine time of `script` and `debug` (default 1 h): a run past it stops
    there, the command fails with a message naming the option, the status is 1."""
    d = fresh("max_time")
    write(d, "long.alp", "monitor\nfirmware thesis-fixed\nreset\nrun 7200s\nrun 1ms\n")
    started = time.monotonic()
    rc, out, err = run([ALP85, "script", "long.alp", "--max-time", "1s"], d, timeout=60)
    took = time.monotonic() - started
    # 1 s of machine time is 3 072 000 T-states (the 6.144 MHz crystal halved): the script stops there.
    check(rc == 1 and "long.alp:4:" in out and "machine-time limit" in out and "--max-time" in out
          and "(3072000 T-states)" in out, f"script run 7200s --max-time 1s: exit {rc}\n{out}{err}")
    check(took < 10, f"script --max-time 1s took {took:.1f} s")
    # alp85 debug: the run stops with the message, the session goes on, a batch ends with 1.
    rc, out, err = run([ALP85, "debug", "thesis-fixed", "--batch", "--max-time", "2s"], d,
                       stdin="run 7200s\nprint $T\nprint 6*7\n", timeout=60)
    # $T: 2 s is 6 144 000 T-states; the run stops at the first instruction boundary at or after it
    # (an instruction takes at most 18 T-states).
    check(rc == 1 and "machine-time limit" in out and "(42)" in out and re.search(r"\$1 = 61440[01][0-9]\b", out),
          f"debug run 7200s --max-time 2s: exit {rc}\n{out}{err}")
    for bad in ("5parsecs", "0s", "-1s", "h"):
        rc, _, err = run([ALP85, "script", "long.alp", "--max-time", bad], d)
        check(rc == 2 and "--max-time" in err, f"script --max-time {bad}: exit {rc}: {err}")
    for cmd in ("script", "debug"):
        rc, out, _ = run([ALP85, cmd, "--help"], d)
        check("--max-time" in out and "1h" in out, f"{cmd} --help does not give --max-time's default:\n{out}")


run_case({"determinism": determinism, "debug_commands": debug_commands, "max_time": max_time, "debug_expressions": debug_expressions, "same_path": same_path, "signals": signals, "bad_input": bad_input, "messages": messages, "disasm": disasm,
 "debug_interrupt": debug_interrupt})
