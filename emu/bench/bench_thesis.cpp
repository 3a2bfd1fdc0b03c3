#include "emu/bench/bench_thesis.h"

#include <array>
#include <cmath>

#include "emu/util/stopwatch.h"

#include "emu/script/parser.h"
#include "emu/script/session.h"

namespace alp85 {
namespace {


// Appendix C up to the feedrate (docs/thesis.md: Z, X1, Y1, X2, Y2, then the feedrate).
constexpr const char* kSetup = R"(firmware monitor
firmware thesis-fixed
reset
wait display "-ALP 85-" timeout 1s
type R 7 0 8 0 0 EXEC
wait display "?.=----" timeout 200ms
type 0 0 0 0
wait display "H1=----" timeout 500ms
type 0 1 0 0 EXEC
wait display "y1=----" timeout 200ms
type 0 1 0 0 EXEC
wait display "H2=----" timeout 200ms
type 1 5 1 4 EXEC
wait display "y2=----" timeout 200ms
type 1 5 1 4 EXEC
wait display "H=----" timeout 200ms
type 1 0 0 0
wait display "H=1000" timeout 200ms
)";
constexpr const char* kMotion = R"(press EXEC hold 30ms gap 0t
)";

}  // namespace

ThesisBenchRun run_thesis_bench(periph::MachineTool::MotorModel model, std::uint64_t window, bool fast_loops) {
    ThesisBenchRun r;
    std::vector<script::ParseError> errors;
    const auto setup = script::parse_script(kSetup, "bench-thesis", errors);
    const auto motion = script::parse_script(kMotion, "bench-thesis", errors);
    if (!errors.empty()) {
        r.error = errors.front().format();
        return r;
    }
    script::Session session(script::SessionOptions{});
    session.machine().tool().set_model(model);
    session.machine().cpu().set_fast_loops(fast_loops);
    for (const auto& c : setup) {
        if (const auto o = session.execute(c); o.status != script::Session::Status::Ok) {
            r.error = o.message;
            return r;
        }
    }
    const std::uint64_t t0 = session.machine().now();
    const Stopwatch watch;
    for (const auto& c : motion) {
        if (const auto o = session.execute(c); o.status != script::Session::Status::Ok) {
            r.error = o.message;
            return r;
        }
    }
    Machine& m = session.machine();
    // The display is decoded only when its segments change (the check runs after every batch).
    std::array<std::uint8_t, 8> last = m.display();
    r.finished = m.run_until(t0 + window, [&] {
                     const auto now = m.display();
                     if (now == last) return false;
                     last = now;
                     return m.display_text() == "  8itti ";
                 }) == Machine::RunEnd::Condition;
    r.host_seconds = watch.cpu_seconds();
    r.tstates = session.machine().now() - t0;
    const auto& tool = session.machine().tool();
    r.x_steps = std::llround(tool.table_steps(periph::MachineTool::Axis::X));
    r.y_steps = std::llround(tool.table_steps(periph::MachineTool::Axis::Y));
    r.end_state = session.machine().snapshot_bytes();
    return r;
}

}  // namespace alp85
