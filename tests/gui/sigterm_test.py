#!/usr/bin/env python3
"""SIGTERM ends `alp85 gui` within a second, also in the middle of a long reverse run.

The window runs under its own Xvfb. Hooks type the worked line's keys (debug_enter.alp), let
200 s of machine time (40 under the sanitizers) pass into the history, print a status line and start reverse-continue
towards a breakpoint that never hit (SOBE: the firmware waits at the feedrate prompt), which
re-executes the whole history. SIGTERM comes 0.3 s after the status line; the window must be
gone within 1 s of it, with status 143 (128 + SIGTERM), and say the reverse run was interrupted.

Usage: sigterm_test.py PATH/TO/alp85 PATH/TO/debug_enter.alp. Prints SKIP without Xvfb."""
import os
import select
import shutil
import signal
import subprocess
import sys
import time

ALP85, SCRIPT = sys.argv[1], sys.argv[2]
HISTORY_S = int(os.environ.get("ALP85_LONG_HISTORY_S", "200"))  # s of machine time (tests/CMakeLists.txt)


def start_xvfb():
    read_fd, write_fd = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(write_fd), "-screen", "0", "1400x900x24", "-nolisten", "tcp"],
                            pass_fds=(write_fd,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_fd)
    number = b""
    end = time.monotonic() + 20
    while not number.endswith(b"\n"):
        ready, _, _ = select.select([read_fd], [], [], max(0.0, end - time.monotonic()))
        chunk = os.read(read_fd, 16) if ready else b""
        if not chunk:
            xvfb.kill()
            raise AssertionError("Xvfb did not start")
        number += chunk
    os.close(read_fd)
    return xvfb, ":" + number.decode().strip()


def main():
    if not shutil.which("Xvfb"):
        print("SKIP: xvfb-run is missing: install xvfb (scripts/setup.sh --tests does) to run the GUI tests")
        return 0
    xvfb, display = start_xvfb()
    try:
        env = dict(os.environ, DISPLAY=display)
        # The history (tests/CMakeLists.txt: ALP85_LONG_HISTORY_S, 200 s, 40 under the sanitizers):
        # reverse-continue over it re-executes for seconds, far longer than the wait before SIGTERM.
        hooks = ["break SOBE", f"run {HISTORY_S}s", "status", "reverse-continue"]
        argv = [ALP85, "gui", "--speed", "max", "--debug", "--script", SCRIPT]
        for h in hooks:
            argv += ["--debug-command", h]
        gui = subprocess.Popen(argv, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        seen = b""
        end = time.monotonic() + 120
        while b"[gui] status:" not in seen:
            ready, _, _ = select.select([gui.stdout], [], [], max(0.0, end - time.monotonic()))
            chunk = os.read(gui.stdout.fileno(), 4096) if ready else b""
            if not chunk:
                gui.kill()
                raise AssertionError("no status line from the window:\n" + seen.decode(errors="replace"))
            seen += chunk
        time.sleep(0.3)  # reverse-continue is under way (it re-executes 200 s of machine time)
        asked = time.monotonic()
        gui.send_signal(signal.SIGTERM)
        try:
            rest, _ = gui.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            gui.kill()
            gui.communicate()
            raise AssertionError("the window was still there 5 s after SIGTERM")
        took = time.monotonic() - asked
        seen += rest
        text = seen.decode(errors="replace")
        print(text)
        print(f"the window ended {took * 1000:.0f} ms after SIGTERM, status {gui.returncode}")
        assert took < 1.0, f"SIGTERM took {took:.2f} s"
        assert gui.returncode == 128 + signal.SIGTERM, gui.returncode
        assert "Interrupted" in text, "the reverse run was not under way when SIGTERM came"
    finally:
        xvfb.terminate()
        xvfb.wait()
    return 0


if __name__ == "__main__":
    sys.exit(main())
