// The fetch fence (I8085::set_fetch_fence): the plain path stops before fetching an opcode at a
// fenced address, lets it through once on pass_fence(), never runs a delay loop at once over a
// fenced address, and notes where LXI SP and SPHL put the stack (stack_load).
#include <gtest/gtest.h>

#include <bitset>
#include <cstdint>

#include "tests/cpu/both.h"

namespace alp85::test {
namespace {

// Param: the variant, and whether memory is one flat block (the core's Flat path) or paged.
class Fence : public ::testing::TestWithParam<std::tuple<Variant, bool>> {
protected:
    Rig rig{std::get<0>(GetParam())};
    std::bitset<0x10000> fence;
    void SetUp() override {
        if (!std::get<1>(GetParam())) rig.bus.unmap(0xFF00, 0x100);  // no longer one flat block
        rig.cpu.set_fetch_fence(&fence);
    }
    bool i8080() const { return rig.is8080(); }
    // The CPU reads which pages hold a fenced address when the set is installed.
    void arm() { rig.cpu.set_fetch_fence(&fence); }
};

// 0100H: MVI A,1 / INR A / INR A / HLT, fenced at the second INR (0103H).
// Data sheets: MVI r 7 T-states on both; INR r 4 on the 8085, 5 on the 8080.
TEST_P(Fence, StopsBeforeTheFencedInstructionAndPassesItOnce) {
    rig.load(0x0100, {0x3E, 0x01, 0x3C, 0x3C, 0x76});
    rig.r().pc = 0x0100;
    fence[0x0103] = true;
    arm();
    rig.cpu.run(1000);
    EXPECT_TRUE(rig.cpu.fence_stopped());
    EXPECT_EQ(rig.r().pc, 0x0103);
    EXPECT_EQ(rig.r().a, 2);  // the instruction at 0103H has not run
    const std::uint64_t inr = i8080() ? 5 : 4;
    EXPECT_EQ(rig.cpu.tstates(), 7 + inr);
    EXPECT_EQ(rig.cpu.instructions(), 2u);
    EXPECT_EQ(rig.cpu.fence_previous(), 0x0102);

    rig.cpu.run(1000);  // not passed: it stops there again, nothing run
    EXPECT_TRUE(rig.cpu.fence_stopped());
    EXPECT_EQ(rig.cpu.tstates(), 7 + inr);
    EXPECT_EQ(rig.r().a, 2);

    rig.cpu.pass_fence();
    rig.cpu.run(1000);
    EXPECT_FALSE(rig.cpu.fence_stopped());
    EXPECT_TRUE(rig.cpu.halted());
    EXPECT_EQ(rig.r().a, 3);
    EXPECT_EQ(rig.cpu.instructions(), 4u);
}

// A loop back over a fenced address stops there every time round: a pass is for one fetch.
TEST_P(Fence, APassIsForOneFetchOnly) {
    // 0200H: MVI B,3 / L: DCR B / JNZ L / HLT, fenced at L's DCR (0202H).
    rig.load(0x0200, {0x06, 0x03, 0x05, 0xC2, 0x02, 0x02, 0x76});
    rig.r().pc = 0x0200;
    fence[0x0202] = true;
    arm();
    int stops = 0;
    while (!rig.cpu.halted() && stops < 10) {
        rig.cpu.run(10000);
        if (rig.cpu.fence_stopped()) {
            ++stops;
            EXPECT_EQ(rig.r().pc, 0x0202);
            EXPECT_EQ(rig.r().b, 3 - (stops - 1));
            rig.cpu.pass_fence();
        }
    }
    EXPECT_EQ(stops, 3);
    EXPECT_EQ(rig.r().b, 0);
}

// The 16-bit delay loop (thesis DL style) with the fence on its JNZ: every iteration is seen,
// and the loop ends where the data sheets put it. With the fence only after the loop, the loop is
// run at once and ends at the same T-state.
TEST_P(Fence, DelayLoopsStopAtEveryFencedIteration) {
    // 0300H: LXI B,5 / L: DCX B / MOV A,B / ORA C / JNZ L / HLT (0309H, fenced: the end)
    for (const bool inside : {true, false}) {
        rig.load(0x0300, {0x01, 0x05, 0x00, 0x0B, 0x78, 0xB1, 0xC2, 0x03, 0x03, 0x76});
        rig.r().pc = 0x0300;
        rig.cpu.reset_counters();
        fence.reset();
        fence[0x0309] = true;
        if (inside) fence[0x0306] = true;  // the JNZ
        arm();
        int stops = 0;
        for (int runs = 0; runs < 20; ++runs) {
            rig.cpu.run(100000);
            ASSERT_TRUE(rig.cpu.fence_stopped());
            if (rig.r().pc == 0x0309) break;
            ++stops;
            rig.cpu.pass_fence();
        }
        EXPECT_EQ(stops, inside ? 5 : 0) << inside;
        // 8085: LXI 10, DCX 6, MOV 4, ORA 4, JNZ 10 taken / 7 not.
        // 8080: LXI 10, DCX 5, MOV 5, ORA 4, JNZ 10 either way.
        const std::uint64_t t = i8080() ? 10 + 5 * (5 + 5 + 4 + 10) : 10 + 5 * (6 + 4 + 4) + 4 * 10 + 7;
        EXPECT_EQ(rig.cpu.tstates(), t) << inside;
        EXPECT_EQ(rig.cpu.instructions(), 1u + 5 * 4) << inside;
        EXPECT_EQ(rig.r().b, 0);
        EXPECT_EQ(rig.r().c, 0);
    }
}

// An interrupt acknowledged before the passed instruction takes the pass away: on return the
// fenced instruction stops the run again, and fence_previous names the RET that came back.
// INTR with RST 4 on the data bus (INTA), on both CPUs.
TEST_P(Fence, AnInterruptFirstTakesThePassAway) {
    rig.load(0x0020, {0xC9});              // RST 4: RET
    rig.load(0x00FE, {0xFB, 0x00});        // EI / NOP (the instruction after EI runs first)
    rig.load(0x0100, {0x3C, 0x76});        // INR A / HLT
    rig.cpu.on_inta = [](unsigned) -> std::uint8_t { return 0xE7; };  // RST 4
    rig.r().pc = 0x00FE;
    fence[0x0100] = true;
    arm();
    rig.cpu.run(1000);
    ASSERT_TRUE(rig.cpu.fence_stopped());
    ASSERT_EQ(rig.r().pc, 0x0100);
    rig.cpu.pass_fence();
    rig.cpu.set_intr(true);  // acknowledged before the next instruction
    rig.cpu.run(1000);
    EXPECT_TRUE(rig.cpu.fence_stopped());
    EXPECT_EQ(rig.r().pc, 0x0100);
    EXPECT_EQ(rig.r().a, 0);
    EXPECT_EQ(rig.cpu.fence_previous(), 0x0020);
    rig.cpu.set_intr(false);
    rig.cpu.pass_fence();
    rig.cpu.run(1000);
    EXPECT_TRUE(rig.cpu.halted());
    EXPECT_EQ(rig.r().a, 1);
}

// Opcodes in a page with no fenced address come through a page table of the CPU's own: a jump
// from such a page into a fenced one stops at the fenced address, and the fence's pages follow
// the set as it is installed again.
TEST_P(Fence, AJumpFromAnUnfencedPageStopsInTheFencedOne) {
    rig.load(0x0100, {0x3E, 0x05, 0xC3, 0x00, 0x04});  // MVI A,5 / JMP 0400H
    rig.load(0x0400, {0x3C, 0x3C, 0x76});              // INR A / INR A / HLT
    rig.r().pc = 0x0100;
    fence[0x0401] = true;
    arm();
    rig.cpu.run(1000);
    ASSERT_TRUE(rig.cpu.fence_stopped());
    EXPECT_EQ(rig.r().pc, 0x0401);
    EXPECT_EQ(rig.r().a, 6);
    EXPECT_EQ(rig.cpu.fence_previous(), 0x0400);
    // Moved to the HLT and installed again: the INR runs, the run stops before the HLT.
    fence.reset();
    fence[0x0402] = true;
    arm();
    rig.cpu.run(1000);
    ASSERT_TRUE(rig.cpu.fence_stopped());
    EXPECT_EQ(rig.r().pc, 0x0402);
    EXPECT_EQ(rig.r().a, 7);
}

// A mapping change between runs is seen by the fenced path's own page table: with the code's
// page unmapped the opcode fetch reads the floating bus, FFH (RST 7), not the RAM behind it.
TEST_P(Fence, AMappingChangeReachesTheFencedPath) {
    rig.load(0x0200, {0x00, 0x00, 0x76});  // NOP / NOP / HLT
    rig.load(0x0038, {0x76});              // RST 7's vector: HLT
    rig.r().pc = 0x0200;
    fence[0x8000] = true;  // somewhere else: page 02 holds no fenced address
    arm();
    rig.cpu.run(4);  // the first NOP
    ASSERT_EQ(rig.r().pc, 0x0201);
    rig.bus.unmap(0x0200, 0x100);
    rig.cpu.run(1000);
    EXPECT_TRUE(rig.cpu.halted());
    EXPECT_EQ(rig.r().pc, 0x0039);  // RST 7 was taken, then its HLT
}

TEST_P(Fence, StackLoadIsWhereLxiSpAndSphlPutTheStack) {
    rig.cpu.set_fetch_fence(nullptr);
    EXPECT_FALSE(rig.cpu.stack_load().has_value());
    // LXI SP,2345H / LXI H,3456H / SPHL / INX SP / HLT
    rig.load(0x0100, {0x31, 0x45, 0x23, 0x21, 0x56, 0x34, 0xF9, 0x33, 0x76});
    rig.r().pc = 0x0100;
    rig.cpu.step();
    ASSERT_TRUE(rig.cpu.stack_load().has_value());
    EXPECT_EQ(*rig.cpu.stack_load(), 0x2345);
    rig.cpu.run(1000);
    EXPECT_EQ(*rig.cpu.stack_load(), 0x3456);  // SPHL; INX SP is not a load
    EXPECT_EQ(rig.r().sp, 0x3457);
}

std::string fence_name(const ::testing::TestParamInfo<std::tuple<Variant, bool>>& info) {
    return std::string(std::get<0>(info.param) == Variant::I8085 ? "i8085" : "i8080") +
           (std::get<1>(info.param) ? "_flat" : "_paged");
}

INSTANTIATE_TEST_SUITE_P(Variants, Fence,
                         ::testing::Combine(::testing::Values(Variant::I8085, Variant::I8080), ::testing::Bool()),
                         fence_name);

}  // namespace
}  // namespace alp85::test
