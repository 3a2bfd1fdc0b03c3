#include "peripherals/seven_segment.h"

#include "peripherals/i8279.h"

namespace alp85::periph::seven_segment {

namespace {
struct Glyph {
    std::uint8_t segments;
    char c;
};
// The first glyph for a character is the one from_char() gives; later ones are variants.
constexpr Glyph kGlyphs[] = {
    {0x3F, '0'}, {0x06, '1'}, {0x5B, '2'}, {0x4F, '3'}, {0x66, '4'}, {0x6D, '5'}, {0x7D, '6'},
    {0x07, '7'}, {0x7F, '8'}, {0x6F, '9'}, {0x77, 'A'}, {0x7C, 'b'}, {0x39, 'C'}, {0x5E, 'd'},
    {0x79, 'E'}, {0x71, 'F'}, {0x3D, 'G'}, {0x76, 'H'}, {0x74, 'h'}, {0x04, 'i'}, {0x30, 'I'},
    {0x1E, 'J'}, {0x38, 'L'}, {0x54, 'n'}, {0x5C, 'o'}, {0x73, 'P'}, {0x50, 'r'}, {0x78, 't'},
    {0x3E, 'U'}, {0x1C, 'u'}, {0x6E, 'y'}, {0x58, 'c'}, {0x40, '-'}, {0x08, '_'}, {0x48, '='},
    {0x00, ' '}, {0x27, '7'}, {0x67, '9'}, {0x7D, 'G'},
};
}  // namespace

char to_char(std::uint8_t segments) {
    const auto s = static_cast<std::uint8_t>(segments & 0x7F);
    for (const auto& g : kGlyphs) {
        if (g.segments == s) return g.c;
    }
    return '?';
}

std::optional<std::uint8_t> from_char(char c) {
    for (const auto& g : kGlyphs) {
        if (g.c == c) return g.segments;
    }
    // Letters with only one case in the table.
    const char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    const char upper = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
    for (const auto& g : kGlyphs) {
        if (g.c == lower || g.c == upper) return g.segments;
    }
    return std::nullopt;
}

std::string to_text(std::span<const std::uint8_t> digits) {
    std::string out;
    for (auto d : digits) {
        out += to_char(d);
        if (d & kDP) out += '.';
    }
    return out;
}

std::array<std::string, kArtLines> to_art(std::span<const std::uint8_t> digits) {
    std::array<std::string, kArtLines> art;
    for (auto d : digits) {
        auto on = [d](std::uint8_t seg) { return (d & seg) != 0; };
        const std::string horiz_a = on(kA) ? " ---  " : "      ";
        const std::string horiz_g = on(kG) ? " ---  " : "      ";
        const std::string horiz_d = on(kD) ? " --- " : "     ";
        std::string upper = {on(kF) ? '|' : ' ', ' ', ' ', ' ', on(kB) ? '|' : ' ', ' '};
        std::string lower = {on(kE) ? '|' : ' ', ' ', ' ', ' ', on(kC) ? '|' : ' ', ' '};
        art[0] += horiz_a + ' ';
        art[1] += upper + ' ';
        art[2] += upper + ' ';
        art[3] += horiz_g + ' ';
        art[4] += lower + ' ';
        art[5] += lower + ' ';
        art[6] += horiz_d + (on(kDP) ? '.' : ' ') + ' ';
    }
    return art;
}

std::array<std::uint8_t, kDigits> read_digits(const I8279& kdc) {
    std::array<std::uint8_t, kDigits> out{};
    for (unsigned i = 0; i < kDigits; ++i) out[i] = kdc.digit_output(i);
    return out;
}

}  // namespace alp85::periph::seven_segment
