// Excess-three words: the digit adder, complements and shifts of the serial arithmetic unit.
#include "emu/pisa/word.h"

#include <fmt/format.h>

namespace alp85::pisa {

bool Word::zero() const {
    for (auto c : cell)
        if (c != kXs3Zero) return false;
    return true;
}

bool Word::valid() const {
    for (auto c : cell)
        if (c < 3 || c > 12) return false;
    return true;
}

Word from_int(std::int64_t v) {
    constexpr std::int64_t kMod = 100'000'000;
    std::int64_t u = ((v % kMod) + kMod) % kMod;
    Word w;
    for (auto& c : w.cell) {
        c = static_cast<std::uint8_t>(u % 10 + 3);
        u /= 10;
    }
    return w;
}

std::optional<std::int64_t> to_int(const Word& w) {
    if (!w.valid()) return std::nullopt;
    std::int64_t u = 0;
    for (int i = 7; i >= 0; --i) u = u * 10 + (w.cell[static_cast<std::size_t>(i)] - 3);
    return w.negative() ? u - 100'000'000 : u;
}

std::string to_text(const Word& w) {
    std::string s;
    for (int i = 7; i >= 0; --i) {
        auto c = w.cell[static_cast<std::size_t>(i)];
        if (c >= 3 && c <= 12) s += static_cast<char>('0' + c - 3);
        else s += fmt::format("[{:X}]", c);
    }
    return s;
}

std::uint8_t xs3_digit_add(std::uint8_t a, std::uint8_t b, bool carry_in, bool& carry_out) {
    unsigned s = (a & 15u) + (b & 15u) + (carry_in ? 1u : 0u);
    carry_out = s > 15;
    // Excess-three correction: with a carry the sum lost 6 of its excess (add 3), without one it
    // carries a double excess (subtract 3, i.e. add 13 modulo 16).
    return static_cast<std::uint8_t>((carry_out ? s + 3 : s + 13) & 15u);
}

namespace {

AddResult add_with(const Word& a, const Word& b, bool carry) {
    AddResult r;
    for (std::size_t i = 0; i < 8; ++i) r.sum.cell[i] = xs3_digit_add(a.cell[i], b.cell[i], carry, carry);
    r.carry = carry;
    r.overflow = a.negative() == b.negative() && r.sum.negative() != a.negative();
    return r;
}

}  // namespace

AddResult add(const Word& a, const Word& b) { return add_with(a, b, false); }

AddResult sub(const Word& b, const Word& a) { return add_with(b, nines_complement(a), true); }

Word nines_complement(const Word& w) {
    Word r;
    for (std::size_t i = 0; i < 8; ++i) r.cell[i] = static_cast<std::uint8_t>(~w.cell[i] & 15u);
    return r;
}

Word shift_left(const Word& w, unsigned n, bool& overflow) {
    n = n > 8 ? 8 : n;
    Word r;
    for (std::size_t i = n; i < 8; ++i) r.cell[i] = w.cell[i - n];
    std::uint8_t sign_digit = w.negative() ? kXs3Nine : kXs3Zero;
    overflow = false;
    for (std::size_t i = 8 - n; i < 8; ++i)
        if (w.cell[i] != sign_digit) overflow = true;
    if (r.negative() != w.negative()) overflow = true;
    return r;
}

Word shift_right(const Word& w, unsigned n) {
    n = n > 8 ? 8 : n;
    Word r;
    std::uint8_t fill = w.negative() ? kXs3Nine : kXs3Zero;
    for (std::size_t i = 0; i < 8; ++i) r.cell[i] = i + n < 8 ? w.cell[i + n] : fill;
    return r;
}

}  // namespace alp85::pisa
