// The machine-tool benchmark: emu/bench/bench_machine.asm steps X, Y and Z together, 10 000 steps
// each at 400 steps/s (25 s of machine time), on the board with the ideal motors, the physical
// motors, and no machine tool at all. Used by `alp85 bench machine` and tests/bench/machine.
#pragma once

#include <cstdint>

#include "emu/board/machine.h"

namespace alp85 {

struct MachineBenchRun {
    std::uint64_t tstates = 0;   // machine time run
    double host_seconds = 0;     // CPU time of the host
    std::int64_t steps[3] = {};  // table positions 200 ms after the HLT (whole steps): 0 after the ten strokes
    std::int64_t lost[3] = {};   // lost steps at the end
};

enum class MachineBenchTool : std::uint8_t { None, Ideal, Physical };

// Boots a fresh board with the workload and runs it to its HLT; the fastest of `repeats` runs
// (host timing is noisy; the machine's own figures are identical every time). fast_loops false:
// every iteration of the workload's 16-bit delay loops interpreted (I8085::set_fast_loops).
MachineBenchRun run_machine_bench(MachineBenchTool tool, int repeats = 5, bool fast_loops = true);

inline constexpr std::uint64_t kMachineBenchSteps = 10'000;
inline constexpr std::uint64_t kMachineBenchStepTStates = 7'680;  // 2.5 ms at 3.072 MHz

}  // namespace alp85
