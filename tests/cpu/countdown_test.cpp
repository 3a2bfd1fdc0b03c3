// The countdown fast paths (I8085::set_fast_loops): "L: DCR r / JNZ L" and the 16-bit
// "L: DCX rp / MOV A,r / ORA r' / JNZ L" run in one step must leave exactly what the interpreter
// leaves, instruction by instruction, wherever a run's deadline falls.
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

// ---- the 16-bit delay loop ----------------------------------------------------------------------

// By hand (data sheets): 8085 LXI 10, DCX 6, MOV r,r 4, ORA r 4, JNZ 10 taken / 7 not; 8080 LXI 10,
// DCX 5, MOV r,r 5, ORA r 4, JNZ 10. BC = 0100H: 256 passes, 255 JNZ taken and one not.
TEST_P(Countdown, TheSixteenBitDelayLoopEndsAsTheDataSheetTimesIt) {
    // 0100: LXI B,0100H / W: DCX B / MOV A,B / ORA C / JNZ W / NOP
    rig.load(0x0100, {0x01, 0x00, 0x01, 0x0B, 0x78, 0xB1, 0xC2, 0x03, 0x01, 0x00});
    rig.r().pc = 0x0100;
    rig.r().f = static_cast<std::uint8_t>(CY | AC | S);  // ORA clears CY and AC, and sets S, Z, P
    const std::uint64_t end = T(10 + 255 * 24 + 6 + 4 + 4 + 7, 10 + 256 * 24);
    rig.cpu.run(end - 1);  // the last JNZ starts before end - 1: it runs
    EXPECT_EQ(rig.cpu.tstates(), T(6151, 6154));
    EXPECT_EQ(rig.cpu.instructions(), 1u + 4 * 256);
    EXPECT_EQ(rig.r().pc, 0x0109);
    EXPECT_EQ(rig.r().b, 0x00);
    EXPECT_EQ(rig.r().c, 0x00);
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(Z | P));
    // One T-state short of the last JNZ's start: it has not run.
    Rig early(GetParam());
    early.load(0x0100, {0x01, 0x00, 0x01, 0x0B, 0x78, 0xB1, 0xC2, 0x03, 0x01, 0x00});
    early.r().pc = 0x0100;
    early.cpu.run(T(10 + 255 * 24 + 6 + 4 + 4, 10 + 255 * 24 + 5 + 5 + 4));
    EXPECT_EQ(early.r().pc, 0x0106);
    EXPECT_EQ(early.cpu.instructions(), 1u + 4 * 256 - 1);
}

// Every pair, both orders of the halves (MOV A,hi / ORA lo and MOV A,lo / ORA hi), pairs that
// start at 0 (65536 passes), 1, 2 and others, deadlines at random: the fast path and the interpreter
// agree after every run. Also two look-alikes that are not 16-bit loops (MOV A,B / ORA B, and
// DCX SP): interpreted, and they must agree too.
TEST_P(Countdown, SixteenBitLoopAgreesWithTheInterpreterAtEveryDeadline) {
    struct Loop {
        std::uint8_t dcx, mov, ora;
    };
    constexpr Loop kLoops[] = {{0x0B, 0x78, 0xB1}, {0x0B, 0x79, 0xB0}, {0x1B, 0x7A, 0xB3}, {0x1B, 0x7B, 0xB2},
                               {0x2B, 0x7C, 0xB5}, {0x2B, 0x7D, 0xB4}, {0x0B, 0x78, 0xB0}, {0x3B, 0x7C, 0xB5}};
    std::mt19937 rng(8085);
    for (const Loop& lp : kLoops) {
        for (const unsigned start : {0x0000u, 0x0001u, 0x0002u, 0x0100u, 0x1234u, 0x00FFu}) {
            Rig fast(GetParam()), slow(GetParam());
            slow.cpu.set_fast_loops(false);
            for (Rig* r : {&fast, &slow}) {
                // 02F0: JMP 0301, the JNZ of the loop at 02FE (across a page boundary), with Z clear.
                r->load(0x02F0, {0xC3, 0x01, 0x03});
                r->load(0x02FE, {lp.dcx, lp.mov, lp.ora, 0xC2, 0xFE, 0x02, 0x00, 0x76});
                r->r().pc = 0x02F0;
                r->r().f = static_cast<std::uint8_t>(CY | AC | S);
                r->r().a = 0x5A;
                r->r().b = r->r().d = r->r().h = static_cast<std::uint8_t>(start >> 8);
                r->r().c = r->r().e = r->r().l = static_cast<std::uint8_t>(start);
                r->r().sp = static_cast<std::uint16_t>(start);
            }
            std::uint64_t deadline = 0;
            const unsigned span = start == 0 ? 40000 : 400;
            while (!slow.cpu.halted() && slow.cpu.tstates() < 3'000'000) {
                deadline += std::uniform_int_distribution<unsigned>(1, span)(rng);
                fast.cpu.run(deadline);
                slow.cpu.run(deadline);
                expect_same(fast, slow, "resumed runs");
                EXPECT_EQ(fast.r().sp, slow.r().sp);
                if (::testing::Test::HasFailure()) return;
            }
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
