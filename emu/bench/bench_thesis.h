// The thesis-firmware benchmark (issue #13): thesis-fixed draws a 100 mm diagonal at 1000 mm/min,
// typed in through the keypad as Appendix C says: from (0100, 0100) to (1514, 1514) steps, 1414
// steps on each axis = 70.7 mm, sqrt(2) x 70.7 = 100.0 mm. Only the motion (from the EXEC that
// starts it to "Bitti") is timed. Used by `alp85 bench thesis`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "peripherals/machine_tool.h"

namespace alp85 {

struct ThesisBenchRun {
    bool finished = false;      // "Bitti" within the window
    std::uint64_t tstates = 0;  // machine time of the motion (to Bitti, or the whole window)
    double host_seconds = 0;    // host CPU time of the motion
    std::int64_t x_steps = 0, y_steps = 0;  // where the tables ended (1414, 1414 expected)
    std::vector<std::uint8_t> end_state;  // the machine's snapshot at the end
    std::string error;          // empty when the walk-through went as expected
};

// Runs the motion until Bitti or for at most `window` T-states; `fast_loops` as
// I8085::set_fast_loops (off: the interpreter executes every delay-loop iteration).
ThesisBenchRun run_thesis_bench(periph::MachineTool::MotorModel model, std::uint64_t window, bool fast_loops = true);

}  // namespace alp85
