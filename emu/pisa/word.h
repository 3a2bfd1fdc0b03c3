// A word of the Pisa interpolator: eight decimal digits in excess-three code, one 4-bit cell each,
// integers with negatives in ten's complement (paper §2.1). Cell 0 is the least significant digit.
//
// The sign is the top bit of cell 7 (MOD stores "the result in the sign bit of L3"): in excess-three
// that bit is 1 exactly for the digits 5..9, so the sign bit and the ten's-complement rule (a word
// is negative when its first digit is 5 or more) agree. Range -50 000 000 ... +49 999 999 (µm).
//
// Arithmetic is serial, one digit at a time through a 4-bit binary adder with the excess-three
// correction (a carry out: add 3; none: subtract 3). Nine's complement is the bitwise inverse
// (excess-three is self-complementing), so B - A = B + ~A + 1. Cells holding codes that are not
// excess-three (0-2, 13-15: a ROM address put there by STO) go through the same adder, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace alp85::pisa {

inline constexpr std::uint8_t kXs3Zero = 3;  // 0011
inline constexpr std::uint8_t kXs3Nine = 12; // 1100

struct Word {
    std::array<std::uint8_t, 8> cell{kXs3Zero, kXs3Zero, kXs3Zero, kXs3Zero,
                                     kXs3Zero, kXs3Zero, kXs3Zero, kXs3Zero};
    bool operator==(const Word&) const = default;

    bool negative() const { return (cell[7] & 8u) != 0; }
    bool zero() const;  // every cell is excess-three 0
    bool valid() const; // every cell is an excess-three digit
};

// Ten's complement from an integer (wrapped modulo 10^8), and back (nullopt if a cell is not a digit).
Word from_int(std::int64_t v);
std::optional<std::int64_t> to_int(const Word& w);
// "12345678" (digits, most significant first; a cell that is not a digit shows as its hex code
// in brackets) - for listings, traces and test messages.
std::string to_text(const Word& w);

struct AddResult {
    Word sum;
    bool carry = false;     // out of the top digit
    bool overflow = false;  // ten's-complement overflow: the operands' signs agree, the sum's differs
};

// One excess-three digit: s = a + b + carry through the 4-bit adder, corrected.
std::uint8_t xs3_digit_add(std::uint8_t a, std::uint8_t b, bool carry_in, bool& carry_out);
AddResult add(const Word& a, const Word& b);
AddResult sub(const Word& b, const Word& a);  // b - a = b + ~a + 1
Word nines_complement(const Word& w);

// Digit shifts. Left: zeros come in at the bottom; overflow when a digit shifted out is not the
// sign digit (0 or 9) or the sign changes. Right: the sign digit comes in at the top (division by
// 10^n rounded towards minus infinity). n may be 0..8 (8: every digit).
Word shift_left(const Word& w, unsigned n, bool& overflow);
Word shift_right(const Word& w, unsigned n);

}  // namespace alp85::pisa
