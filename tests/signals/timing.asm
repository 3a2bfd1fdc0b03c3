; A STA for the debugger's `timing` (tests/signals/timing_cli.cmake).
        ORG     0800H
        STA     2050H
