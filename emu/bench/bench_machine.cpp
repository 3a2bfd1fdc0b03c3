#include "emu/bench/bench_machine.h"

#include <cmath>
#include <ctime>

#include "machine_bench_program_embed.h"

namespace alp85 {
namespace {
double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}
}  // namespace

MachineBenchRun run_machine_bench(MachineBenchTool tool) {
    Machine::Options o;
    o.machine_tool = tool != MachineBenchTool::None;
    o.motor = tool == MachineBenchTool::Physical ? periph::MachineTool::MotorModel::Physical
                                                 : periph::MachineTool::MotorModel::Ideal;
    Machine m(o);
    m.load(bench::kMachineBenchProgram_origin,
           std::span(bench::kMachineBenchProgram, bench::kMachineBenchProgram_size));
    m.reset();
    m.cpu().regs().pc = bench::kMachineBenchProgram_origin;
    // Run to the HLT (a little over 25 s) and a moment more for the rotors to settle.
    const std::uint64_t limit = kMachineBenchSteps * kMachineBenchStepTStates + 3'072'000;
    const double start = cpu_seconds();
    m.run_until(limit, [&] { return m.cpu().halted(); });
    MachineBenchRun r;
    r.host_seconds = cpu_seconds() - start;
    r.tstates = m.now();
    for (int a = 0; a < 3; ++a) {
        if (!o.machine_tool) break;
        const auto axis = static_cast<periph::MachineTool::Axis>(a);
        r.steps[a] = std::llround(m.tool().table_steps(axis));
        r.lost[a] = m.tool().lost_steps(axis);
    }
    return r;
}

}  // namespace alp85
