// The thesis firmware's diagonal (alp85 bench thesis) with the countdown fast path and with every
// DL iteration interpreted: the same machine at the end, snapshot byte for byte, both motor models.
// And the 16-bit fast path: bench_machine.asm's three axes, which wait in DCX B / MOV A,B / ORA C /
// JNZ loops, end in the same machine either way.
#include <gtest/gtest.h>

#include <span>

#include "emu/bench/bench_machine.h"
#include "emu/bench/bench_thesis.h"
#include "machine_bench_program_embed.h"

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

// Two strokes' worth of the machine bench (1000 steps out, some back) on the physical motors.
std::vector<std::uint8_t> machine_bench_end(bool fast_loops) {
    Machine::Options o;
    o.machine_tool = true;
    o.motor = Model::Physical;
    Machine m(o);
    m.load(bench::kMachineBenchProgram_origin, std::span(bench::kMachineBenchProgram, bench::kMachineBenchProgram_size));
    m.reset();
    m.cpu().regs().pc = bench::kMachineBenchProgram_origin;
    m.cpu().set_fast_loops(fast_loops);
    m.run_for(1500 * kMachineBenchStepTStates);
    return m.snapshot_bytes();
}

TEST(ThesisFastLoops, SixteenBitDelayLoopsEndInTheSameMachineEitherWay) {
    const std::vector<std::uint8_t> fast = machine_bench_end(true);
    const std::vector<std::uint8_t> slow = machine_bench_end(false);
    ASSERT_FALSE(fast.empty());
    EXPECT_TRUE(fast == slow);
}

}  // namespace
}  // namespace alp85
