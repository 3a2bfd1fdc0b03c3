// The thesis firmware's diagonal (alp85 bench thesis) with the countdown fast path and with every
// DL iteration interpreted: the same machine at the end, snapshot byte for byte, both motor models.
#include <gtest/gtest.h>

#include "emu/bench/bench_thesis.h"

namespace alp85 {
namespace {

using Model = periph::MachineTool::MotorModel;

TEST(ThesisFastLoops, TheDiagonalEndsInTheSameMachineEitherWay) {
    const std::uint64_t window = 60ull * 3'072'000;
    const ThesisBenchRun fast = run_thesis_bench(Model::Ideal, window, true);
    const ThesisBenchRun slow = run_thesis_bench(Model::Ideal, window, false);
    ASSERT_EQ(fast.error, "");
    ASSERT_EQ(slow.error, "");
    EXPECT_TRUE(fast.finished);
    // (0100, 0100) to (1514, 1514): 1414 steps on each axis, typed in by the walk-through.
    EXPECT_EQ(fast.x_steps, 1414);
    EXPECT_EQ(fast.y_steps, 1414);
    EXPECT_EQ(fast.tstates, slow.tstates);
    EXPECT_TRUE(fast.end_state == slow.end_state);
}

TEST(ThesisFastLoops, ThePhysicalMotorsEndInTheSameMachineEitherWay) {
    const std::uint64_t window = 2ull * 3'072'000;  // two seconds of motion
    const ThesisBenchRun fast = run_thesis_bench(Model::Physical, window, true);
    const ThesisBenchRun slow = run_thesis_bench(Model::Physical, window, false);
    ASSERT_EQ(fast.error, "");
    ASSERT_EQ(slow.error, "");
    EXPECT_GE(fast.tstates, window);  // to the end of the instruction that crosses it
    EXPECT_LT(fast.tstates, window + 18);
    EXPECT_EQ(fast.tstates, slow.tstates);
    EXPECT_TRUE(fast.end_state == slow.end_state);
}

}  // namespace
}  // namespace alp85
