// The debugger's benchmark (issue #15, `alp85 bench debug`): thesis-fixed drawing a line from
// (0100, 0100) to (3000, 2000) steps at 300 mm/min (D = 5, about 14 ms a step: a minute of motion),
// typed in as Appendix C says.
//   - the run's speed under the debugger (history of snapshots on, nothing armed) against a plain
//     script session over the same motion;
//   - the same run through DAP, unpaced (an editor's continue with the runaway guard on);
//   - one reverse-step after 60 s of simulated time, and a reverse-continue to a breakpoint.
#pragma once

#include <cstdint>
#include <string>

namespace alp85 {

struct DebugBenchResult {
    std::uint64_t tstates = 0;       // machine time of the speed runs
    double script_seconds = 0;       // host CPU time, plain script session
    double debugger_seconds = 0;     // host CPU time, under the debugger with history on
    double dap_seconds = 0;          // host CPU time through DAP, unpaced (scaled to the same machine time)
    std::uint64_t reverse_at = 0;    // machine time when the reverse-step was asked for
    double reverse_step_ms = 0;      // wall time of that one reverse-step
    double reverse_continue_ms = 0;  // wall time of a reverse-continue back to the last OUT
    std::size_t snapshots = 0;       // the history's checkpoints at 60 s
    std::size_t snapshot_bytes = 0;  // and their total size
    bool exact = false;              // the reverse-step landed on the state saved one step before
    std::string error;
};

DebugBenchResult run_debug_bench(std::uint64_t speed_window);

}  // namespace alp85
