// The countdown fast path (I8085::set_fast_loops): "L: DCR r / JNZ L" run in one step must leave
// exactly what the interpreter leaves, instruction by instruction, wherever a run's deadline falls.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "tests/cpu/both.h"

namespace alp85::test {
namespace {

class Countdown : public Both {};

// The thesis's DL inner loop at 0100H: MVI B,0DAH / IDI: DCR B / JNZ IDI, then NOP.
void load_dl(Rig& r) {
    r.load(0x0100, {0x06, 0xDA, 0x05, 0xC2, 0x02, 0x01, 0x00});
    r.r().pc = 0x0100;
}

void expect_same(const Rig& fast, const Rig& slow, const char* where) {
    const Registers &a = fast.cpu.regs(), &b = slow.cpu.regs();
    EXPECT_EQ(a.pc, b.pc) << where;
    EXPECT_EQ(a.a, b.a) << where;
    EXPECT_EQ(a.f, b.f) << where;
    EXPECT_EQ(a.b, b.b) << where;
    EXPECT_EQ(a.c, b.c) << where;
    EXPECT_EQ(a.d, b.d) << where;
    EXPECT_EQ(a.e, b.e) << where;
    EXPECT_EQ(a.h, b.h) << where;
    EXPECT_EQ(a.l, b.l) << where;
    EXPECT_EQ(fast.cpu.tstates(), slow.cpu.tstates()) << where;
    EXPECT_EQ(fast.cpu.instructions(), slow.cpu.instructions()) << where;
}

// By hand (data sheets): 8085 MVI 7, DCR 4, JNZ 10 taken / 7 not; 8080 MVI 7, DCR 5, JNZ 10.
// 218 passes of DCR B: 217 taken JNZ and one not taken.
TEST_P(Countdown, TheDelayLoopEndsAsTheDataSheetTimesIt) {
    load_dl(rig);
    rig.r().f = CY;  // DCR leaves CY alone
    rig.cpu.run(1);   // MVI only starts before T-state 1
    rig.cpu.run(T(7 + 217 * 14 + 4 + 7, 7 + 218 * 15));
    EXPECT_EQ(rig.cpu.tstates(), T(3056, 3277));
    EXPECT_EQ(rig.cpu.instructions(), 1u + 2 * 218);
    EXPECT_EQ(rig.r().pc, 0x0106);
    EXPECT_EQ(rig.r().b, 0x00);
    // DCR 01H -> 00H: Z, P; AC (no borrow out of bit 4 when the low digit is non-zero); S, V, K clear.
    EXPECT_EQ(rig.r().f, F(Z | AC | P | CY));
}

// Every deadline from inside the first pass to past the end, each register, r = 0 on entry (256
// passes): the fast path and the interpreter agree after every run, including runs resumed
// where the previous one stopped.
TEST_P(Countdown, AgreesWithTheInterpreterAtEveryDeadline) {
    constexpr std::uint8_t kDcr[] = {0x05, 0x0D, 0x15, 0x1D, 0x25, 0x2D, 0x3D};
    std::mt19937 rng(85);
    for (const std::uint8_t dcr : kDcr) {
        for (const unsigned start : {0u, 1u, 2u, 3u, 17u, 255u}) {
            Rig fast(GetParam()), slow(GetParam());
            slow.cpu.set_fast_loops(false);
            for (Rig* r : {&fast, &slow}) {
                // JMP into the JNZ with Z clear: the loop is entered from outside, as code may.
                r->load(0x0200, {0xC3, 0x04, 0x02, dcr, 0xC2, 0x03, 0x02, 0x00, 0x76});
                r->r().pc = 0x0200;
                r->r().f = static_cast<std::uint8_t>(CY | S);
                r->r().a = r->r().b = r->r().c = r->r().d = r->r().e = r->r().h = r->r().l =
                    static_cast<std::uint8_t>(start);
            }
            std::uint64_t deadline = 0;
            while (!slow.cpu.halted()) {
                deadline += std::uniform_int_distribution<unsigned>(1, 400)(rng);
                fast.cpu.run(deadline);
                slow.cpu.run(deadline);
                expect_same(fast, slow, "resumed runs");
                if (::testing::Test::HasFailure()) return;
            }
            EXPECT_TRUE(fast.cpu.halted());
        }
    }
}

// A debugger sees every iteration: with hooks installed the loop is interpreted.
TEST_P(Countdown, DebugHooksSeeEveryInstruction) {
    struct Counter : DebugHooks {
        unsigned seen = 0;
        bool before_instruction(I8085&) override {
            ++seen;
            return true;
        }
    } hooks;
    load_dl(rig);
    rig.cpu.set_debug_hooks(&hooks);
    rig.cpu.run(T(3056, 3277));
    EXPECT_EQ(hooks.seen, 1u + 2 * 218);
    EXPECT_EQ(rig.r().pc, 0x0106);
}

INSTANTIATE_TEST_SUITE_P(Variants, Countdown, ::testing::Values(Variant::I8085, Variant::I8080), variant_name);

}  // namespace
}  // namespace alp85::test
