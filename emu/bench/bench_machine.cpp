#include "emu/bench/bench_machine.h"

#include <cmath>

#include "emu/util/stopwatch.h"

#include "machine_bench_program_embed.h"

namespace alp85 {
namespace {
MachineBenchRun run_once(MachineBenchTool tool, bool fast_loops) {
    Machine::Options o;
    o.machine_tool = tool != MachineBenchTool::None;
    o.motor = tool == MachineBenchTool::Physical ? periph::MachineTool::MotorModel::Physical
                                                 : periph::MachineTool::MotorModel::Ideal;
    Machine m(o);
    m.load(bench::kMachineBenchProgram_origin,
           std::span(bench::kMachineBenchProgram, bench::kMachineBenchProgram_size));
    m.reset();
    m.cpu().regs().pc = bench::kMachineBenchProgram_origin;
    m.cpu().set_fast_loops(fast_loops);
    // Run to the HLT (a little over 25 s).
    const std::uint64_t limit = kMachineBenchSteps * kMachineBenchStepTStates + board::kCpuHz;
    m.cpu().on_halt = [&] { m.cpu().request_stop(); };  // end the batch at the HLT itself
    const Stopwatch watch;
    m.run_until(limit, [&] { return m.cpu().halted(); });
    MachineBenchRun r;
    r.host_seconds = watch.cpu_seconds();
    r.tstates = m.now();
    m.run_for(board::tstates_from_ms(200));  // (untimed) let the rotors settle before the check
    for (int a = 0; a < 3; ++a) {
        if (!o.machine_tool) break;
        const auto axis = static_cast<periph::MachineTool::Axis>(a);
        r.steps[a] = std::llround(m.tool().table_steps(axis));
        r.lost[a] = m.tool().lost_steps(axis);
    }
    return r;
}
}  // namespace

MachineBenchRun run_machine_bench(MachineBenchTool tool, int repeats, bool fast_loops) {
    MachineBenchRun best = run_once(tool, fast_loops);
    for (int i = 1; i < repeats; ++i) {
        const MachineBenchRun r = run_once(tool, fast_loops);
        if (r.host_seconds < best.host_seconds) best = r;
    }
    return best;
}

}  // namespace alp85
