#!/usr/bin/env python3
"""No debugger command runs unbounded at the `alp85 debug` prompt, driven through a pseudo-terminal
as a person types: Ctrl-C ends continue, advance, finish and until (in the monitor's key loop)
and a reverse-continue that re-executes a long history, each within LIMIT of host time (the
prompt is back); reverse-finish in the outermost routine (the main loop at LOOP+6, no return
address on the stack) answers at once and changes nothing.

Usage: terminal_long_ops.py PATH/TO/alp85. Exit status 0 when every step saw what it expected."""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from terminal_test import PROMPT, Terminal  # noqa: E402

ALP85 = sys.argv[1]
HISTORY_S = int(os.environ.get("ALP85_LONG_HISTORY_S", "200"))  # s of machine time (tests/CMakeLists.txt)
LIMIT = 0.1  # s: Ctrl-C to the prompt


def interrupt(t, command, after=0.15):
    """Types `command`, presses Ctrl-C `after` s later; the time until the prompt is back."""
    t.type(command + "\r")
    time.sleep(after)
    asked = time.monotonic()
    os.write(t.fd, b"\x03")
    out = t.read_until(PROMPT, 10)
    took = time.monotonic() - asked
    assert b"Interrupted (Ctrl-C)" in out, (command, out)
    print(f"{command}: the prompt was back {took * 1000:.1f} ms after Ctrl-C")
    return took


def answer(t, command, timeout=10):
    t.type(command + "\r")
    return t.read_until(PROMPT, timeout)


def main():
    t = Terminal([ALP85, "debug", "thesis-fixed"])
    t.read_until(PROMPT, 10)
    took = [interrupt(t, "continue"), interrupt(t, "advance 0")]  # the PC never comes back to the RESET vector
    # GETKEY+3 (JZ GETKEY) loops until a key: the monitor's GETKEY does not return without one.
    for command in ["until 0", "finish"]:
        out = answer(t, "advance GETKEY+3")
        assert b"GETKEY+3" in out, out
        took.append(interrupt(t, command))
    # Machine time at the first prompt into the history (tests/CMakeLists.txt: ALP85_LONG_HISTORY_S,
    # 200 s, 40 under the sanitizers), then the worked line's keys: reverse-continue over it
    # re-executes for seconds, far longer than the wait before the interrupt.
    answer(t, f"run {HISTORY_S}s", 120)
    for line in ['type R 7 0 8 0 0 EXEC', 'wait display "?.=----" timeout 200ms', 'type 0 0 0 0',
                 'wait display "H1=----" timeout 1s', 'type 0 1 0 0 EXEC', 'wait display "y1=----" timeout 200ms',
                 'type 0 0 5 0 EXEC', 'wait display "H2=----" timeout 200ms', 'type 0 3 0 0 EXEC',
                 'wait display "y2=----" timeout 200ms', 'type 0 2 0 0 EXEC', 'wait display "H=----" timeout 200ms',
                 'type 0 7 5 0', 'break LOOP+6', 'press EXEC']:
        out = answer(t, line)
        assert b"error" not in out, (line, out)
    assert b"Breakpoint 1, LOOP+6" in out, out
    before = answer(t, "info registers")
    started = time.monotonic()
    out = answer(t, "reverse-finish", 1)
    print(f"reverse-finish in the outermost routine answered in {(time.monotonic() - started) * 1000:.1f} ms")
    assert b"not meaningful in the outermost routine" in out, out
    assert answer(t, "info registers") == before  # nothing moved (the T-state count included)
    # No earlier hit: reverse-continue would re-execute the whole history back to its start.
    took.append(interrupt(t, "reverse-continue", 0.2))
    out = answer(t, "reverse-stepi")
    assert b"error" not in out, out
    t.type("quit\r")
    _, status = os.waitpid(t.pid, 0)
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0, status
    assert max(took) < LIMIT, f"Ctrl-C took {max(took) * 1000:.0f} ms (at most {LIMIT * 1000:.0f})"
    print("long operations: every one ended by Ctrl-C, reverse-finish at once")


if __name__ == "__main__":
    main()
