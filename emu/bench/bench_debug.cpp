#include "emu/bench/bench_debug.h"

#include <chrono>

#include "emu/program/firmware.h"
#include "emu/script/debug_shell.h"
#include "emu/util/stopwatch.h"

namespace alp85 {
namespace {

constexpr const char* kSetup[] = {
    "monitor", "firmware thesis-fixed", "reset",
    "type R 7 0 8 0 0 EXEC", "wait display \"?.=----\" timeout 200ms",
    "type 0 0 0 0", "wait display \"H1=----\" timeout 500ms",
    "type 0 1 0 0 EXEC", "wait display \"y1=----\" timeout 200ms",
    "type 0 1 0 0 EXEC", "wait display \"H2=----\" timeout 200ms",
    "type 3 0 0 0 EXEC", "wait display \"y2=----\" timeout 200ms",
    "type 2 0 0 0 EXEC", "wait display \"H=----\" timeout 200ms",
    "type 0 3 0 0", "wait display \"H=0300\" timeout 200ms",
    "press EXEC hold 30ms gap 0t",
};

double wall_ms(const std::function<void()>& fn) {
    const auto t0 = std::chrono::steady_clock::now();
    fn();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

DebugBenchResult run_debug_bench(std::uint64_t speed_window) {
    DebugBenchResult r;
    script::SessionOptions o;
    if (firmware::have_monitor()) o.monitor_rom = firmware::monitor;
    // Two shells over the same motion: one a plain script session, one the debugger with history.
    script::DebugShell plain(o), debugged(o);
    for (script::DebugShell* s : {&plain, &debugged}) {
        for (const char* line : kSetup) {
            const std::string out = s->execute(line);
            if (s->console().errors()) {
                r.error = std::string(line) + ": " + out;
                return r;
            }
        }
    }
    debugged.debugger().set_history(true);
    // Speed: the plain machine runs through the script session (what `alp85 script` does with run
    // TIME), the other through the debugger's run loop with snapshots and nothing armed.
    {
        const std::uint64_t t0 = plain.session().machine().now();
        const Stopwatch w;
        plain.session().debugger().run_for(speed_window);
        r.script_seconds = w.cpu_seconds();
        r.tstates = plain.session().machine().now() - t0;
    }
    {
        const Stopwatch w;
        debugged.execute("run " + std::to_string(speed_window) + "t");
        r.debugger_seconds = w.cpu_seconds();
    }
    // On to 60 s of simulated time since the start, a step, then one reverse-step.
    Machine& m = debugged.session().machine();
    const std::uint64_t sixty = 60ull * 3'072'000;
    if (m.now() < sixty) debugged.execute("run " + std::to_string(sixty - m.now()) + "t");
    const std::vector<std::uint8_t> before = m.snapshot_bytes();
    debugged.execute("stepi");
    r.reverse_at = m.now();
    r.snapshots = debugged.debugger().history_snapshots();
    r.snapshot_bytes = r.snapshots * before.size();
    r.reverse_step_ms = wall_ms([&] { debugged.execute("reverse-step"); });
    r.exact = m.snapshot_bytes() == before;
    debugged.execute("break OUT");
    r.reverse_continue_ms = wall_ms([&] { debugged.execute("reverse-continue"); });
    return r;
}

}  // namespace alp85
