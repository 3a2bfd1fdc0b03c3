#!/usr/bin/env python3
"""The window's CPU use under Xvfb, standing and moving (issue 33, item 16).

    tests/bench/gui/gui_bench.py [ALP85] [--speed 1] [--screen 1366x768x24]

Starts its own Xvfb, runs `alp85 gui --stats --script gui_bench.alp` on it and reads the script's
"bench:" lines as they are printed: the window stands at the thesis firmware's feed prompt for 10 s
of machine time, then the table moves 62.5 mm at 400 mm/min, then it stands at Bitti (halted).
For each phase it prints the wall time and the CPU time of alp85 and of Xvfb (from /proc), as a
percentage of one core, and at the end the OpenGL renderer the window drew with. The first second
of each phase is left out (the frame rate settles). Figures are reported, never asserted.
"""
import os
import pty
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
TICK = os.sysconf("SC_CLK_TCK")


def cpu_s(pid):
    with open(f"/proc/{pid}/stat") as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICK  # utime + stime (fields 14, 15)


def iter_lines(f):
    while True:
        try:
            line = f.readline()
        except OSError:  # the terminal closed with the process
            return
        if not line:
            return
        yield line


def main():
    args = sys.argv[1:]
    alp85 = os.path.join(HERE, "..", "..", "..", "build", "bin", "alp85")
    speed, screen = "1", "1366x768x24"
    i = 0
    while i < len(args):
        if args[i] == "--speed":
            speed, i = args[i + 1], i + 2
        elif args[i] == "--screen":
            screen, i = args[i + 1], i + 2
        else:
            alp85, i = args[i], i + 1
    rfd, wfd = os.pipe()
    xvfb = subprocess.Popen(["Xvfb", "-displayfd", str(wfd), "-screen", "0", screen, "-nolisten", "tcp"],
                            pass_fds=(wfd,), stderr=subprocess.DEVNULL)
    os.close(wfd)
    display = os.read(rfd, 64).decode().strip()
    os.close(rfd)
    env = dict(os.environ, DISPLAY=":" + display)
    # A terminal for its output, so that each line arrives as it is printed (a pipe is buffered).
    master, slave = pty.openpty()
    gui = subprocess.Popen([alp85, "gui", "--stats", "--speed", speed, "--script", os.path.join(HERE, "gui_bench.alp")],
                           env=env, stdout=slave, stderr=subprocess.DEVNULL)
    os.close(slave)
    lines = os.fdopen(master, "r", errors="replace")
    marks = {}

    def mark(name):
        marks[name] = (time.monotonic(), cpu_s(gui.pid), cpu_s(xvfb.pid))

    phases = [("standing at the feed prompt", "standing", "moving"),
              ("the table moving (400 mm/min)", "moving", "stopped"),
              ("standing at Bitti (halted)", "stopped", "end")]
    renderer = "?"
    try:
        for line in iter_lines(lines):
            if line.startswith("bench: "):
                name = line.split()[1]
                mark(name)
                time.sleep(1)  # the phase's first second left out
                mark(name + "+1")
                if name == "stopped":
                    time.sleep(5)
                    mark("end")
                    gui.terminate()
            elif line.startswith("stats: renderer"):
                renderer = line.split(" ", 2)[2].strip()
        gui.wait(timeout=10)
    finally:
        if gui.poll() is None:
            gui.kill()
        xvfb.terminate()
        xvfb.wait()
    print(f"alp85 gui --speed {speed} on Xvfb {screen}, OpenGL renderer: {renderer}")
    print(f"{'phase':32} {'wall s':>7} {'alp85 %':>8} {'Xvfb %':>8}")
    for label, a, b in phases:
        if a + "+1" not in marks or b not in marks:
            print(f"{label:32} (not reached)")
            continue
        t0, g0, x0 = marks[a + "+1"]
        t1, g1, x1 = marks[b]
        wall = t1 - t0
        print(f"{label:32} {wall:7.1f} {100 * (g1 - g0) / wall:8.1f} {100 * (x1 - x0) / wall:8.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
