#!/usr/bin/env python3
"""Pause in the window ends a long reverse run within 100 ms.

Under its own Xvfb the window types the worked line's keys (debug_enter.alp), lets 200 s of
machine time (40 under the sanitizers) pass into the history, and clicks Rev continue towards a breakpoint that never hit
(SOBE: the firmware waits at the feedrate prompt), which would re-execute the whole history.
0.2 s into it this test clicks the run pane's Pause button through the X server (XTEST), as a
person's click arrives, and times the click to the window's log line of the stop.

Usage: pause_reverse_test.py PATH/TO/alp85 PATH/TO/debug_enter.alp. Prints SKIP without Xvfb."""
import ctypes
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sigterm_test import start_xvfb  # noqa: E402

ALP85, SCRIPT = sys.argv[1], sys.argv[2]
HISTORY_S = int(os.environ.get("ALP85_LONG_HISTORY_S", "200"))  # s of machine time (tests/CMakeLists.txt)


def click(display, x, y):
    """A left click at screen (x, y), through the XTEST extension; when the press was sent."""
    x11 = ctypes.CDLL("libX11.so.6")
    xtst = ctypes.CDLL("libXtst.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    dpy = ctypes.c_void_p(x11.XOpenDisplay(display.encode()))
    assert dpy.value, f"cannot open {display}"
    xtst.XTestFakeMotionEvent(dpy, -1, x, y, 0)
    x11.XSync(dpy, 0)
    pressed = time.monotonic()
    xtst.XTestFakeButtonEvent(dpy, 1, 1, 0)
    xtst.XTestFakeButtonEvent(dpy, 1, 0, 0)
    x11.XFlush(dpy)
    x11.XCloseDisplay(dpy)
    return pressed


def main():
    if not shutil.which("Xvfb"):
        print("SKIP: xvfb-run is missing: install xvfb (scripts/setup.sh --tests does) to run the GUI tests")
        return 0
    xvfb, display = start_xvfb()
    gui = None
    try:
        # The history (tests/CMakeLists.txt: ALP85_LONG_HISTORY_S, 200 s, 40 under the sanitizers):
        # reverse-continue over it re-executes for seconds, far longer than the wait before the click.
        hooks = ["break SOBE", f"run {HISTORY_S}s", "where:debug.continue", "click:debug.reverse-continue"]
        argv = [ALP85, "gui", "--speed", "max", "--debug", "--script", SCRIPT]
        for h in hooks:
            argv += ["--debug-command", h]
        gui = subprocess.Popen(argv, env=dict(os.environ, DISPLAY=display), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT)
        seen = b""

        def wait_for(pattern, timeout):
            nonlocal seen
            end = time.monotonic() + timeout
            while not re.search(pattern, seen):
                ready, _, _ = select.select([gui.stdout], [], [], max(0.0, end - time.monotonic()))
                chunk = os.read(gui.stdout.fileno(), 4096) if ready else b""
                if not chunk:
                    raise AssertionError(f"waited for {pattern!r}; the window printed:\n" + seen.decode(errors="replace"))
                seen += chunk
            return re.search(pattern, seen)

        where = wait_for(rb"\[gui\] debug\.continue at (\d+),(\d+)", 120)
        wait_for(rb"\[gui\] reverse run under way", 30)
        time.sleep(0.2)
        clicked = click(display, int(where.group(1)), int(where.group(2)))
        wait_for(rb"\[gui\] paused ([0-9.]+) ms after the request", 10)
        ms = (time.monotonic() - clicked) * 1000  # the click sent to the stop's log line read here
        wait_for(rb"Interrupted", 10)
        text = seen.decode(errors="replace")
        print(text)
        assert "Interrupted" in text, "the reverse run did not end interrupted"
        print(f"Pause ended the reverse run {ms:.1f} ms after the click")
        assert ms < 100, f"Pause took {ms:.1f} ms"
    finally:
        if gui:
            gui.send_signal(signal.SIGTERM)
            gui.communicate(timeout=10)
        xvfb.terminate()
        xvfb.wait()
    return 0


if __name__ == "__main__":
    sys.exit(main())
