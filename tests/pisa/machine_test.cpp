// Every instruction of the Pisa interpolator run from assembled source, with values and times
// worked by hand (docs/pisa.md: encodings, the step counts of the timing model).
#include <gtest/gtest.h>

#include "asm/pisa_asm.h"
#include "emu/pisa/interpolator.h"

namespace alp85::pisa {
namespace {

Interpolator machine(const std::string& src) {
    auto r = pisa_asm::assemble_string(src);
    for (auto& d : r.out.diagnostics) ADD_FAILURE() << asm85::format_diagnostic(d);
    return Interpolator(r.rom);
}

std::int64_t value(const Interpolator& m, int a) { return to_int(m.rwm(a)).value_or(-999'999'999); }

TEST(PisaInstructions, AddSubtractAndTheirTimes) {
    auto m = machine(
        "  STO 758,1\n"
        "  STO 367,2\n"
        "  ADD 1,2,3\n"      // 758 + 367 = 1125
        "  SUB 1,2,4\n"      // 367 - 758 = -391 (99999609)
        "  SUB 2,1,5\n"      // 758 - 367 = 391
        "  SET 5\n");
    EXPECT_EQ(m.run(1000).reason, StopReason::End);
    EXPECT_EQ(value(m, 1), 758);
    EXPECT_EQ(value(m, 3), 1125);
    EXPECT_EQ(to_text(m.rwm(4)), "99999609");
    EXPECT_EQ(value(m, 5), 391);
    // STO 9, STO 9, ADD 25, SUB 25, SUB 25, SET 2 digit steps.
    EXPECT_EQ(m.now(), 9u + 9 + 25 + 25 + 25 + 2);
    EXPECT_EQ(m.instructions(), 6u);
}

TEST(PisaInstructions, OverflowSetsTheIndicator) {
    auto m = machine(
        "  STO 5,1\n"
        "  SHL 1,7,1\n"      // 50000000: the sign changes -> OVF
        "  RST 4\n"
        "  STO 1,2\n"
        "  STO 4,3\n"
        "  SHL 3,7,3\n"      // 40000000
        "  ADD 3,3,4\n"      // 80000000 = -20000000: overflow
        "  SET 5\n");
    m.step();
    m.step();
    EXPECT_TRUE(m.indicator(kOvf));
    m.run(1000);
    EXPECT_TRUE(m.indicator(kOvf));
    EXPECT_EQ(to_text(m.rwm(4)), "80000000");
}

TEST(PisaInstructions, AddOrSubtractBySignOfWordZero) {
    auto m = machine(
        "  STO 758,1\n"
        "  STO 367,2\n"
        "  ADS 2,1,3\n"      // word 0 = +0: 758 + 367
        "  STO 1,6\n"
        "  SUB 6,0,0\n"      // word 0 = 0 - 1 = -1
        "  ADS 2,1,4\n"      // 758 - 367
        "  SET 5\n");
    m.run(1000);
    EXPECT_EQ(value(m, 3), 1125);
    EXPECT_EQ(value(m, 4), 391);
    EXPECT_EQ(m.now(), 9u + 9 + 26 + 9 + 25 + 26 + 2);
}

TEST(PisaInstructions, ModSetsOnlyTheSignBit) {
    auto m = machine(
        "  STO 391,1\n"
        "  SUB 1,0,1\n"      // -391
        "  STO 367,2\n"
        "  MOD 1,2,3\n"      // - x + = -: word 3 (0) gets 1000 in its top cell: 80000000
        "  STO 123,4\n"
        "  MOD 1,1,4\n"      // - x - = +: 00000123 stays
        "  MOD 2,2,3\n"      // + x + = +: 80000000 -> 00000000
        "  SET 5\n");
    m.step(), m.step(), m.step(), m.step();
    EXPECT_EQ(to_text(m.rwm(3)), "80000000");
    EXPECT_TRUE(m.rwm(3).negative());
    m.run(1000);
    EXPECT_EQ(value(m, 4), 123);
    EXPECT_TRUE(m.rwm(3).zero());
}

TEST(PisaInstructions, AbsMoveAndShifts) {
    auto m = machine(
        "  STO 391,1\n"
        "  SUB 1,0,2\n"      // -391
        "  ABS 2,3\n"        // 391
        "  ABS 1,4\n"        // 391
        "  MOV 2,5\n"        // -391
        "  STO 234,6\n"
        "  STO 1,7\n"
        "  SHL 7,3,7\n"      // 1000
        "  ADD 6,7,6\n"      // 1234
        "  SHL 6,3,8\n"      // 1234000
        "  SUB 6,0,9\n"      // -1234
        "  SHR 9,2,10\n"     // floor(-12.34) = -13
        "  SHR 6,1,11\n"     // 123
        "  SET 5\n");
    m.run(1000);
    EXPECT_EQ(value(m, 3), 391);
    EXPECT_EQ(value(m, 4), 391);
    EXPECT_EQ(value(m, 5), -391);
    EXPECT_EQ(value(m, 8), 1'234'000);
    EXPECT_EQ(to_text(m.rwm(10)), "99999987");
    EXPECT_EQ(value(m, 11), 123);
    EXPECT_FALSE(m.indicator(kOvf));
    // STO x3 = 27, SUB x2 = 50, ABS x2 = 36, MOV 17, SHL x2 + SHR x2 = 72, ADD 25, SET 2
    EXPECT_EQ(m.now(), 27u + 50 + 36 + 17 + 72 + 25 + 2);
}

TEST(PisaInstructions, AbsOfTheMostNegativeWordOverflows) {
    auto m = machine(
        "  STO 5,1\n"
        "  SHL 1,7,1\n"
        "  RST 4\n"
        "  ABS 1,2\n"
        "  SET 5\n");
    m.run(1000);
    EXPECT_TRUE(m.indicator(kOvf));
    EXPECT_EQ(to_text(m.rwm(2)), "50000000");
}

TEST(PisaInstructions, StoreConstantOrRomAddressAndJumpIndirect) {
    auto m = machine(
        "  STO 907,1\n"           // excess-three 1100 0011 1010: 907
        "  STO #LAB,2\n"          // raw 12 bits: 7 = 0000 0000 0111
        "  JMI 2\n"
        "  STO 1,3\n"             // skipped
        "  STO 2,3\n"             // skipped
        "  STO 3,3\n"             // skipped
        "  STO 4,3\n"             // skipped
        "LAB: STO 9,4\n"
        "  SET 5\n");
    m.run(1000);
    EXPECT_EQ(value(m, 1), 907);
    EXPECT_EQ(m.rwm(2).cell[0], 7);
    EXPECT_EQ(m.rwm(2).cell[1], 0);
    EXPECT_EQ(m.rwm(2).cell[2], 0);
    EXPECT_EQ(m.rwm(2).cell[3], 3);  // the five high digits are zeros
    EXPECT_TRUE(m.rwm(3).zero());
    EXPECT_EQ(value(m, 4), 9);
    EXPECT_EQ(m.now(), 9u + 9 + 4 + 9 + 2);
}

TEST(PisaInstructions, EveryJumpConditionTakenAndNot) {
    // Each test either jumps over a STO that marks a failure in word 20, or falls into one that
    // marks success in word 21..; a taken jump lands on the next test.
    auto m = machine(
        "  STO 5,1\n"            // +5
        "  SUB 1,0,2\n"          // -5
        "  TZE BAD,1\n"          // 5 is not zero: falls through
        "  TZE T2,0\n"           // 0 is zero: jumps
        "  JMP BAD\n"
        "T2: TPL T3,0\n"         // +0 >= 0
        "  JMP BAD\n"
        "T3: TPL T4,1\n"         // 5 >= 0
        "  JMP BAD\n"
        "T4: TPL BAD,2\n"        // -5 < 0: falls through
        "  TRS BAD,6\n"          // indicator 6 is 0
        "  SET 6\n"
        "  TRS T5,6\n"           // now 1
        "  JMP BAD\n"
        "T5: RST 6\n"
        "  TRS BAD,6\n"
        "  JMP OK\n"
        "BAD: STO 1,20\n"
        "  SET 5\n"
        "OK: STO 1,21\n"
        "  SET 5\n");
    EXPECT_EQ(m.run(1000).reason, StopReason::End);
    EXPECT_TRUE(m.rwm(20).zero());
    EXPECT_EQ(value(m, 21), 1);
}

TEST(PisaInstructions, InputFromAChannelAndTheReaderOutputToAConverter) {
    auto m = machine(
        "  IN 3,4,1\n"      // low four digits of channel 3
        "  IN 3,8,2\n"
        "  OUT 1,3,1\n"     // 321 into the low three digits of converter 1
        "  SET 2\n"         // start the reader
        "L: TRS GOT,1\n"
        "  JMP L\n"
        "GOT: IN 0,1,3\n"   // the letter
        "  IN 0,8,4\n"
        "  RST 1\n"
        "  SET 2\n"         // no more tape: EOT
        "  SET 5\n");
    m.set_input(3, {1, 2, 3, 4, 5, 6, 7, 8});  // least significant digit first (BCD)
    std::vector<std::pair<int, std::string>> outs;
    m.on_output([&](int ch, const Word& w, std::uint64_t) { outs.emplace_back(ch, to_text(w)); });
    m.reader().load({{kX, true, 12345, 8, 1}});
    EXPECT_EQ(m.run(10'000'000).reason, StopReason::End);
    EXPECT_EQ(value(m, 1), 4321);
    EXPECT_EQ(to_text(m.rwm(2)), "87654321");
    ASSERT_EQ(outs.size(), 1u);
    EXPECT_EQ(outs[0], std::make_pair(1, std::string("00000321")));
    EXPECT_EQ(value(m, 3), 3);                       // X
    EXPECT_EQ(to_text(m.rwm(4)), "90123453");        // sign 9, digits 012345, letter 3
    EXPECT_TRUE(m.indicator(kEot));
    EXPECT_FALSE(m.indicator(kRdr));
    // IN 4 digits: 1 + 2x4 + 4 = 13; IN 8: 17; OUT 3: 7: SET RUN begins at t = 37, so the flag
    // rises 8 characters of 33 333 steps later, at 266 701. The loop's TRS turns start at 39 + 4k;
    // the first at or after 266 701 is k = 66 666 (266 703), taken (2), then IN 1: 1 + 2 + 7 = 10,
    // IN 8: 17, RST 2, SET 2, SET 2.
    EXPECT_EQ(m.now(), 266'703u + 2 + 10 + 17 + 2 + 2 + 2);
}

TEST(PisaInstructions, TheClockIndicatorEverySixMilliseconds) {
    auto m = machine(
        "  SET 0\n"         // t = 0: the first tick at 60 000
        "L: TRS T,0\n"
        "  JMP L\n"
        "T: RST 0\n"
        "L2: TRS T2,0\n"    // the next tick at 120 000, whatever the reset's time
        "  JMP L2\n"
        "T2: SET 5\n");
    EXPECT_EQ(m.run(1'000'000).reason, StopReason::End);
    // TRS turns start at 2 + 4k: the first at or after 60 000 is 60 002, taken -> 60 004; RST 2
    // -> 60 006; turns from 60 006 + 4k: the first at or after 120 000 is 120 002 -> 120 004, SET.
    EXPECT_EQ(m.now(), 120'006u);

    // The same program one instruction at a time: the waiting loop's shortcut changes nothing.
    auto s = machine("  SET 0\nL: TRS T,0\n  JMP L\nT: RST 0\nL2: TRS T2,0\n  JMP L2\nT2: SET 5\n");
    while (!s.indicator(kEnd)) s.step();
    EXPECT_EQ(s.now(), m.now());
    EXPECT_EQ(s.instructions(), m.instructions());
}

TEST(PisaInstructions, FetchBeyondTheFittedRomFaults) {
    auto m = machine("  JMP 100\n");  // one package of 64 words is fitted
    auto stop = m.run(1000);
    EXPECT_EQ(stop.reason, StopReason::Fault);
    EXPECT_NE(stop.message.find("0100"), std::string::npos);
}

TEST(PisaInstructions, EncodingsOfTheSixteenCodes) {
    auto r = pisa_asm::assemble_string(
        "  ADD 1,2,3\n  SUB 1,2,3\n  ADS 1,2,3\n  MOD 1,2,3\n  ABS 1,3\n  MOV 1,3\n  SHL 1,2,3\n  SHR 1,2,3\n"
        "  STO 125,9\n  JMP 4095\n  JMI 9\n  TZE 10,9\n  TPL 10,9\n  TRS 10,63\n  SET 7\n  RST 7\n"
        "  IN 0,8,9\n  OUT 2,8,9\n");
    ASSERT_TRUE(r.ok());
    // op << 18 | A << 12 | B << 6 | C, or op << 18 | A << 12 | F
    const std::uint32_t expect[] = {
        0u << 18 | 1 << 12 | 2 << 6 | 3,  1u << 18 | 1 << 12 | 2 << 6 | 3, 2u << 18 | 1 << 12 | 2 << 6 | 3,
        3u << 18 | 1 << 12 | 2 << 6 | 3,  4u << 18 | 1 << 12 | 3,          5u << 18 | 1 << 12 | 3,
        6u << 18 | 1 << 12 | 2 << 6 | 3,  6u << 18 | 1 << 12 | (32 + 2) << 6 | 3,
        7u << 18 | 9 << 12 | 0x458,       8u << 18 | 4095,                 9u << 18 | 9 << 12,
        10u << 18 | 9 << 12 | 10,         11u << 18 | 9 << 12 | 10,        12u << 18 | 63 << 12 | 10,
        13u << 18 | 7 << 12 | 1,          13u << 18 | 7 << 12 | 0,
        14u << 18 | 9 << 12 | 0 << 6 | 8, 15u << 18 | 9 << 12 | 2 << 6 | 8};
    ASSERT_EQ(r.rom.size(), std::size(expect));
    for (std::size_t i = 0; i < r.rom.size(); ++i) EXPECT_EQ(r.rom[i], expect[i]) << "word " << i;
}

}  // namespace
}  // namespace alp85::pisa
