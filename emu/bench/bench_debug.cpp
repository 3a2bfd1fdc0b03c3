#include "emu/bench/bench_debug.h"

#include <chrono>

#include <nlohmann/json.hpp>

#include "emu/dap/adapter.h"
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

// The same motion through the Debug Adapter Protocol, as an editor drives it: launched stopped on
// entry, the walk-through typed at its debug console, then `continue` unpaced, the adapter's
// slices run back to back (what its server does while no message comes) until `window` of machine
// time has passed. Returns the host CPU seconds of the run, or a negative number with `error`.
double dap_run(std::uint64_t window, std::string& error) {
    using Json = nlohmann::json;
    std::vector<Json> sent;
    dap::Adapter a([&](const Json& m) { sent.push_back(m); });
    int seq = 0;
    const auto request = [&](const char* command, Json args) {
        a.receive(Json{{"seq", ++seq}, {"type", "request"}, {"command", command}, {"arguments", std::move(args)}}.dump());
        for (auto it = sent.rbegin(); it != sent.rend(); ++it)
            if ((*it)["type"] == "response" && (*it)["request_seq"] == seq) return *it;
        return Json{};
    };
    const auto now = [&]() -> std::uint64_t {
        const Json r = request("evaluate", {{"expression", "$time"}, {"context", "watch"}});
        return r.value("success", false) ? std::stoull(r["body"]["result"].get<std::string>()) : 0;
    };
    request("initialize", {{"adapterID", "alp85"}});
    if (!request("launch", {{"firmware", "thesis-fixed"}, {"stopOnEntry", true}, {"realTime", false}}).value("success", false)) {
        error = "the DAP launch failed";
        return -1;
    }
    request("configurationDone", Json::object());
    for (const char* line : kSetup) {
        const Json r = request("evaluate", {{"expression", line}, {"context", "repl"}});
        if (!r.value("success", false)) {
            error = std::string("DAP console: ") + line + ": " + r.dump();
            return -1;
        }
    }
    const std::uint64_t t0 = now();
    const Stopwatch w;
    request("continue", {{"threadId", 1}});
    // A slice is 20 ms of host time; the machine's time is read between slices as the client would.
    while (a.running()) {
        a.advance();
        if (now() - t0 >= window) break;
    }
    request("pause", {{"threadId", 1}});
    const double seconds = w.cpu_seconds();
    if (now() - t0 < window) {
        error = "the DAP run stopped before the window ended";
        return -1;
    }
    return seconds * static_cast<double>(window) / static_cast<double>(now() - t0);
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
    r.dap_seconds = dap_run(speed_window, r.error);
    if (!r.error.empty()) return r;
    // On to 60 s of simulated time since the start, a step, then one reverse-step.
    Machine& m = debugged.session().machine();
    const std::uint64_t sixty = 60ull * board::kCpuHz;
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
