#!/usr/bin/env python3
"""alp85 debug at a terminal, driven as a person would: wait for the prompt, type a command (with
Tab completion), read the answer; start a long run and interrupt it with Ctrl-C; quit.

Usage: terminal_test.py PATH/TO/alp85. Exit status 0 when every step saw what it expected."""
import os
import pty
import select
import shutil
import sys
import tempfile
import time

ALP85 = sys.argv[1]
PROMPT = b"(alp85) "


class Terminal:
    def __init__(self, argv):
        self.pid, self.fd = pty.fork()
        if self.pid == 0:
            os.environ["HOME"] = os.environ.get("TMPDIR", "/tmp")  # the history file goes there
            os.execv(argv[0], argv)
        self.seen = b""

    def read_until(self, what, timeout):
        end = time.monotonic() + timeout
        while what not in self.seen:
            left = end - time.monotonic()
            if left <= 0:
                raise AssertionError(f"waited {timeout} s for {what!r}; the terminal shows:\n"
                                     + self.seen.decode(errors="replace"))
            ready, _, _ = select.select([self.fd], [], [], left)
            if ready:
                try:
                    chunk = os.read(self.fd, 4096)
                except OSError:
                    chunk = b""
                if not chunk:
                    raise AssertionError(f"alp85 ended while waiting for {what!r}:\n"
                                         + self.seen.decode(errors="replace"))
                self.seen += chunk
        at = self.seen.index(what) + len(what)
        before, self.seen = self.seen[:at], self.seen[at:]
        return before

    def type(self, text):
        for ch in text:  # a key at a time, as typed
            os.write(self.fd, ch.encode())
            time.sleep(0.002)


def main():
    t = Terminal([ALP85, "debug", "thesis-fixed"])
    banner = t.read_until(PROMPT, 10)
    # A banner as gdb's: what this is and where help is.
    assert b"alp85 debug" in banner and b"help" in banner, banner
    # Tab completes a file name after a command that takes one (libedit).
    folder = tempfile.mkdtemp()
    open(os.path.join(folder, "walkthrough_prog.asm"), "w").write("        END\n")
    t.type(f"load {folder}/walk\t\r")
    out = t.read_until(PROMPT, 10)
    assert b"through_prog.asm" in out and b"error" not in out, out  # the name completed, then loaded
    shutil.rmtree(folder)
    # Tab completes a command's name: "brea<Tab>" becomes "break ".
    t.type("brea\tOUT\r")
    out = t.read_until(PROMPT, 10)
    assert b"Breakpoint 1 at" in out and b"thesis.asm" in out, out
    t.type("info breakpoints\r")
    out = t.read_until(PROMPT, 10)
    assert b"in OUT at thesis.asm" in out, out
    # The firmware waits at the monitor for a key: a run of ten simulated minutes takes a while
    # on the host; Ctrl-C ends it and the prompt comes back.
    t.type("run 600s\r")
    time.sleep(0.3)
    started = time.monotonic()
    os.write(t.fd, b"\x03")
    out = t.read_until(PROMPT, 10)
    assert b"Interrupted (Ctrl-C)" in out, out
    assert time.monotonic() - started < 5, "Ctrl-C took too long"
    t.type("p $T < 600 * 3072000\r")
    out = t.read_until(PROMPT, 10)
    assert b"= 01H (1)" in out, out
    # Ctrl-C at the prompt abandons the line, not the session.
    t.type("info regi")
    os.write(t.fd, b"\x03")
    t.read_until(PROMPT, 10)
    t.type("info registers\r")
    out = t.read_until(PROMPT, 10)
    assert b"PC " in out, out
    # A mistake is an error with its column, and the session goes on.
    t.type("p 1 + \r")
    out = t.read_until(PROMPT, 10)
    assert b"error: expected a value" in out, out
    t.type("quit\r")
    _, status = os.waitpid(t.pid, 0)
    assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0, status
    print("terminal session: prompt, completion, Ctrl-C and quit as expected")


if __name__ == "__main__":
    main()
