"""What the command-line attack scripts share (cli_robust.py, files_robust.py): their arguments,
the programs, the checks and the scratch folders.

  python3 SCRIPT.py BIN_DIR WORK_DIR CASE
"""
import os
import shutil
import subprocess
import sys
import tempfile
import threading

BIN, WORK, CASE = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), sys.argv[3]
ALP85 = os.path.join(BIN, "alp85")
ASM85 = os.path.join(BIN, "asm85")
PISA_ASM = os.path.join(BIN, "pisa-asm")
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(args, cwd, stdin=None, env=None, timeout=120):
    """(status, stdout, stderr); status None when it ran past `timeout` seconds (a hang)."""
    e = dict(os.environ)
    e.pop("DISPLAY", None)  # gui: the checks come before any window
    e.pop("WAYLAND_DISPLAY", None)
    if env:
        e.update(env)
    try:
        p = subprocess.run(args, cwd=cwd, input=stdin, capture_output=True, text=True, env=e, timeout=timeout,
                           errors="replace")
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout} s"
    return p.returncode, p.stdout, p.stderr


def peak_resident_mb(args, cwd, timeout=300):
    """(status, the process's own peak resident memory in MB, its standard error), the memory from
    its rusage as wait4 reaps it; killed after `timeout` seconds."""
    with tempfile.TemporaryFile() as err:
        p = subprocess.Popen(args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=err)
        timer = threading.Timer(timeout, p.kill)
        timer.start()
        try:
            _, status, usage = os.wait4(p.pid, 0)
        finally:
            timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)  # reaped here: Popen must not wait again
        err.seek(0)
        return p.returncode, usage.ru_maxrss / 1024, err.read().decode(errors="replace")


def fresh(name):
    d = os.path.join(WORK, name)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    return d


def write(d, name, text, mode="w"):
    with open(os.path.join(d, name), mode) as f:
        f.write(text)
    return os.path.join(d, name)


def snapshot(d):
    """Every file in d with its bytes: what must not change."""
    out = {}
    for n in sorted(os.listdir(d)):
        p = os.path.join(d, n)
        if os.path.isfile(p) and not os.path.islink(p):
            with open(p, "rb") as f:
                out[n] = f.read()
    return out


def run_case(cases):
    """Runs the case named on the command line; exit status 1 when a check failed."""
    cases[CASE]()
    if failures:
        print(f"{len(failures)} failure(s)")
        sys.exit(1)
    print("ok")
