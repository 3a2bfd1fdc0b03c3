// Excess-three words worked by hand: digit d is the cell d + 3; ten's complement negatives.
#include <gtest/gtest.h>

#include "emu/pisa/word.h"

namespace alp85::pisa {
namespace {

using Cells = std::array<std::uint8_t, 8>;  // least significant digit first

TEST(PisaWord, CellsAreDigitsPlusThree) {
    EXPECT_EQ(from_int(1234).cell, (Cells{7, 6, 5, 4, 3, 3, 3, 3}));
    EXPECT_EQ(from_int(0).cell, (Cells{3, 3, 3, 3, 3, 3, 3, 3}));
    // -2 is 99999998: 8 -> 1011, 9 -> 1100; the top cell's high bit is the sign.
    Word m2 = from_int(-2);
    EXPECT_EQ(m2.cell, (Cells{11, 12, 12, 12, 12, 12, 12, 12}));
    EXPECT_TRUE(m2.negative());
    EXPECT_EQ(to_int(m2), -2);
    EXPECT_EQ(to_text(m2), "99999998");
    EXPECT_FALSE(from_int(49'999'999).negative());  // first digit 4: 0111
    EXPECT_TRUE(from_int(-50'000'000).negative());  // first digit 5: 1000
}

TEST(PisaWord, DigitAdderWithTheExcessThreeCorrection) {
    bool c = false;
    // 7 + 5: 1010 + 1000 = 10010, a carry: 0010 + 0011 = 0101 = 2, carry 1.
    EXPECT_EQ(xs3_digit_add(10, 8, false, c), 5);
    EXPECT_TRUE(c);
    // 3 + 4: 0110 + 0111 = 1101, no carry: 1101 - 0011 = 1010 = 7.
    EXPECT_EQ(xs3_digit_add(6, 7, false, c), 10);
    EXPECT_FALSE(c);
    // 9 + 9 + 1: 1100 + 1100 + 1 = 11001, carry: 1001 + 0011 = 1100 = 9.
    EXPECT_EQ(xs3_digit_add(12, 12, true, c), 12);
    EXPECT_TRUE(c);
    // 0 + 0: 0110, no carry: 0011 = 0.
    EXPECT_EQ(xs3_digit_add(3, 3, false, c), 3);
    EXPECT_FALSE(c);
}

TEST(PisaWord, CarriesRunAcrossDigits) {
    // 00009999 + 00000001: each 9 + carry gives 10000 = 0 carry 1, up to digit 4.
    auto r = add(from_int(9999), from_int(1));
    EXPECT_EQ(r.sum.cell, (Cells{3, 3, 3, 3, 4, 3, 3, 3}));
    EXPECT_FALSE(r.overflow);
    // 758 + 367: 8+7 = 15 (5, carry), 5+6+1 = 12 (2, carry), 7+3+1 = 11 (1, carry), 0+0+1 = 1.
    EXPECT_EQ(to_int(add(from_int(758), from_int(367)).sum), 1125);
    // 99999999 + 1 = (1)00000000: -1 + 1 = 0 with a carry out and no overflow.
    r = add(from_int(-1), from_int(1));
    EXPECT_TRUE(r.sum.zero());
    EXPECT_TRUE(r.carry);
    EXPECT_FALSE(r.overflow);
}

TEST(PisaWord, SubtractionByTheNinesComplementAndAnInitialCarry) {
    // 1234 -> 8765 in each digit: the bitwise inverse of 0100 0101 0110 0111 is 1011 1010 1001 1000.
    EXPECT_EQ(nines_complement(from_int(1234)).cell, (Cells{8, 9, 10, 11, 12, 12, 12, 12}));
    // 3 - 5: 0110 + ~1000 (0111) + 1 = 1110, no carry: 1011 = 8; the other digits 0 + 9 = 9 with
    // no carry: 99999998 = -2.
    auto r = sub(from_int(3), from_int(5));
    EXPECT_EQ(r.sum.cell, (Cells{11, 12, 12, 12, 12, 12, 12, 12}));
    EXPECT_EQ(to_int(r.sum), -2);
    // 367 - 758 = -391: 99999609.
    EXPECT_EQ(to_text(sub(from_int(367), from_int(758)).sum), "99999609");
    // -100 - -250 = 150.
    EXPECT_EQ(to_int(sub(from_int(-100), from_int(-250)).sum), 150);
}

TEST(PisaWord, OverflowWhenTheSignsAgreeAndTheSumsDoesNot) {
    EXPECT_TRUE(add(from_int(49'999'999), from_int(1)).overflow);     // 50000000 reads negative
    EXPECT_TRUE(sub(from_int(-50'000'000), from_int(1)).overflow);    // 49999999 reads positive
    EXPECT_FALSE(add(from_int(49'999'998), from_int(1)).overflow);
    EXPECT_FALSE(add(from_int(-50'000'000), from_int(49'999'999)).overflow);
}

TEST(PisaWord, ShiftsByPowersOfTen) {
    bool ovf = false;
    EXPECT_EQ(to_int(shift_left(from_int(12), 2, ovf)), 1200);
    EXPECT_FALSE(ovf);
    EXPECT_EQ(to_int(shift_left(from_int(-3), 1, ovf)), -30);  // 99999997 -> 99999970: a 9 left
    EXPECT_FALSE(ovf);
    shift_left(from_int(5'000'000), 1, ovf);  // 05000000 -> 50000000: the sign changes
    EXPECT_TRUE(ovf);
    shift_left(from_int(10'000'000), 1, ovf);  // a 1 is shifted out
    EXPECT_TRUE(ovf);
    // Right: the sign digit comes in, so negatives round towards minus infinity.
    EXPECT_EQ(to_int(shift_right(from_int(1234), 1)), 123);
    EXPECT_EQ(to_text(shift_right(from_int(-1234), 1)), "99999876");  // -124
    EXPECT_EQ(to_int(shift_right(from_int(-1234), 2)), -13);
    EXPECT_EQ(to_int(shift_right(from_int(-1), 8)), -1);
    EXPECT_EQ(to_int(shift_right(from_int(49'999'999), 8)), 0);
}

TEST(PisaWord, CellsThatAreNotDigits) {
    Word w;
    w.cell[0] = 0xC, w.cell[1] = 0xB, w.cell[2] = 0;  // 12 bits of a ROM address
    EXPECT_FALSE(to_int(w).has_value());
    EXPECT_EQ(to_text(w), "00000[0]89");
}

}  // namespace
}  // namespace alp85::pisa
