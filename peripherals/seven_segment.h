// The ALP 85's eight seven-segment digits (board level), read from the 8279's display outputs.
//
// Wiring (inferred from the thesis's segment codes: 76H = H, 6EH = y, 78H = t, 7FH = B/8):
// bit0 = a, bit1 = b, bit2 = c, bit3 = d, bit4 = e, bit5 = f, bit6 = g, bit7 = dp, active high.
//
//      a
//    f   b
//      g
//    e   c
//      d   dp
//
// Not emulated: brightness, ghosting and flicker of the multiplexed scan (the picture is steady).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace alp85::periph {

class I8279;

namespace seven_segment {

constexpr std::uint8_t kA = 0x01, kB = 0x02, kC = 0x04, kD = 0x08, kE = 0x10, kF = 0x20, kG = 0x40, kDP = 0x80;
constexpr unsigned kDigits = 8;
constexpr unsigned kArtLines = 7;

// The character a segment pattern shows (dp ignored): ' ' for blank, '?' when no glyph matches.
char to_char(std::uint8_t segments);
// The pattern for a character, if it has a glyph (digits, A-F, and the letters the table knows).
std::optional<std::uint8_t> from_char(char c);
// One character per digit, a '.' after a digit whose dp is lit.
std::string to_text(std::span<const std::uint8_t> digits);
// Seven lines of ASCII art; each digit is 6 columns wide plus a space.
std::array<std::string, kArtLines> to_art(std::span<const std::uint8_t> digits);
// The eight digits as the board shows them: 8279 display positions 0-7, leftmost first.
std::array<std::uint8_t, kDigits> read_digits(const I8279& kdc);

}  // namespace seven_segment
}  // namespace alp85::periph
