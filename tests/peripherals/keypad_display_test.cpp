// Keypad matrix and seven-segment display tests. Expected codes come from the layout documented
// in docs/peripherals.md and from the thesis's segment codes (76H = H, 6EH = y, 78H = t, 7FH = 8/B,
// 04H = i), with the wiring bit0 = a ... bit6 = g, bit7 = dp.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "peripherals/i8279.h"
#include "peripherals/keypad.h"
#include "peripherals/seven_segment.h"
#include "peripherals/state_io.h"

namespace {

using alp85::periph::I8279;
using alp85::periph::Key;
using alp85::periph::Keypad;
namespace seg = alp85::periph::seven_segment;

TEST(Keypad, HexKeysCarryTheirValueAsCode) {
    for (unsigned v = 0; v < 16; ++v) {
        const Key k = static_cast<Key>(v);
        EXPECT_EQ(Keypad::info(k).code(), v);
        EXPECT_EQ(Keypad::info(k).row, v / 8);
        EXPECT_EQ(Keypad::info(k).column, v % 8);
    }
}

TEST(Keypad, FunctionKeysOnRowTwo) {
    EXPECT_EQ(Keypad::info(Key::Exec).code(), 0x10);
    EXPECT_EQ(Keypad::info(Key::Next).code(), 0x11);
    EXPECT_EQ(Keypad::info(Key::Go).code(), 0x12);
    EXPECT_EQ(Keypad::info(Key::Mem).code(), 0x13);
    EXPECT_EQ(Keypad::info(Key::Reg).code(), 0x14);
    EXPECT_EQ(Keypad::info(Key::Step).code(), 0x15);
    EXPECT_EQ(Keypad::info(Key::Prev).code(), 0x16);
    EXPECT_EQ(Keypad::info(Key::R).code(), 0x17);
}

TEST(Keypad, NamesAndCodesAreUniqueAndFindable) {
    std::set<std::string> names;
    std::set<unsigned> codes;
    for (const auto& k : Keypad::layout()) {
        names.insert(std::string(k.name));
        codes.insert(k.code());
        EXPECT_EQ(Keypad::find(k.name), k.key);
        EXPECT_EQ(Keypad::from_code(k.code()), k.key);
        EXPECT_EQ(&Keypad::info(k.key), &k);
    }
    EXPECT_EQ(names.size(), Keypad::kKeyCount);
    EXPECT_EQ(codes.size(), Keypad::kKeyCount);
    EXPECT_EQ(Keypad::find("exec"), Key::Exec);
    EXPECT_EQ(Keypad::find("RESET"), std::nullopt);  // wired to the CPU, not the matrix
    EXPECT_EQ(Keypad::from_code(0xC0 | 0x17), Key::R);  // CNTL/SHIFT bits ignored
    EXPECT_EQ(Keypad::from_code(0x18), std::nullopt);
}

TEST(Keypad, ReturnLinesAreActiveLowOnTheSelectedRow) {
    Keypad pad;
    pad.press(Key::KA);  // row 1, RL2
    pad.press(Key::R);   // row 2, RL7
    EXPECT_EQ(pad.return_lines(0), 0xFF);
    EXPECT_EQ(pad.return_lines(1), 0xFB);
    EXPECT_EQ(pad.return_lines(2), 0x7F);
    EXPECT_EQ(pad.return_lines(9), 0xFB);  // SL3 does not take part in the decoding
    pad.release(Key::KA);
    EXPECT_EQ(pad.return_lines(1), 0xFF);
    EXPECT_TRUE(pad.is_pressed(Key::R));
    pad.release_all();
    EXPECT_FALSE(pad.is_pressed(Key::R));
}

TEST(Keypad, SnapshotRoundTripAndRejection) {
    Keypad pad;
    pad.press(Key::Step);
    std::vector<std::uint8_t> blob;
    pad.save(blob);
    Keypad copy;
    copy.load(blob);
    EXPECT_TRUE(copy.is_pressed(Key::Step));
    blob.back() = 0x01;  // row 7: no keys there
    EXPECT_THROW(copy.load(blob), alp85::SnapshotError);
}

TEST(Keypad, KeyThroughThe8279GivesItsCode) {
    Keypad pad;
    I8279 kdc;
    kdc.set_return_lines_source([&](std::uint8_t sl) { return pad.return_lines(sl); });
    kdc.reset(0);
    kdc.set_shift(false, 0);  // grounded on the board
    kdc.set_cntl_stb(false, 0);
    pad.press(Key::R);
    kdc.inputs_changed(1000);
    // Row 2 is sampled at digit 2 (2 * 1984 = 3968 T); entered two scans later at digit 18.
    kdc.advance(18 * 1984);
    EXPECT_TRUE(kdc.irq());
    EXPECT_EQ(kdc.read(0, 18 * 1984), 0x17);
}

TEST(SevenSegment, ThesisCodesReadRight) {
    EXPECT_EQ(seg::to_char(0x76), 'H');
    EXPECT_EQ(seg::to_char(0x6E), 'y');
    EXPECT_EQ(seg::to_char(0x78), 't');
    EXPECT_EQ(seg::to_char(0x7F), '8');  // the thesis's "B" of "Bitti"
    EXPECT_EQ(seg::to_char(0x04), 'i');
    const std::uint8_t bitti[] = {0x00, 0x00, 0x7F, 0x04, 0x78, 0x78, 0x04, 0x00};
    EXPECT_EQ(seg::to_text(bitti), "  8itti ");
}

TEST(SevenSegment, HexDigitsAndSymbols) {
    // a=01 b=02 c=04 d=08 e=10 f=20 g=40: 0 = abcdef = 3F, 1 = bc = 06, ..., F = aefg = 71.
    const std::uint8_t hex[] = {0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07,
                                0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71};
    EXPECT_EQ(seg::to_text(hex), "0123456789AbCdEF");
    EXPECT_EQ(seg::to_char(0x40), '-');
    EXPECT_EQ(seg::to_char(0x08), '_');
    EXPECT_EQ(seg::to_char(0x00), ' ');
    EXPECT_EQ(seg::to_char(0x38), 'L');
    EXPECT_EQ(seg::to_char(0x73), 'P');
    EXPECT_EQ(seg::to_char(0x50), 'r');
    EXPECT_EQ(seg::to_char(0x5C), 'o');
    EXPECT_EQ(seg::to_char(0x1C), 'u');
    EXPECT_EQ(seg::to_char(0x49), '?');  // a, d, g: no glyph
    for (char c : std::string("0123456789AbCdEFHLPrtyiou-_ ")) {
        const auto p = seg::from_char(c);
        ASSERT_TRUE(p.has_value()) << c;
        EXPECT_EQ(seg::to_char(*p), c);
    }
    EXPECT_EQ(seg::from_char('B'), 0x7C);  // B/b share the b glyph
    EXPECT_EQ(seg::from_char('#'), std::nullopt);
}

TEST(SevenSegment, DecimalPointReadsAsDot) {
    const std::uint8_t digits[] = {0x76, 0x86, 0x48};  // H, 1 with dp, =
    EXPECT_EQ(seg::to_text(digits), "H1.=");
    const std::uint8_t dp_only[] = {0x80};
    EXPECT_EQ(seg::to_text(dp_only), " .");
}

TEST(SevenSegment, AsciiArtIsSevenLines) {
    const std::uint8_t digits[] = {0xFF, 0x06};  // 8 with dp, then 1
    const auto art = seg::to_art(digits);
    ASSERT_EQ(art.size(), 7u);
    // Each digit is 6 columns (segments in columns 0-4, dp in column 5) plus a space: 14 columns.
    EXPECT_EQ(art[0], " ---          ");
    EXPECT_EQ(art[1], "|   |      |  ");
    EXPECT_EQ(art[2], "|   |      |  ");
    EXPECT_EQ(art[3], " ---          ");
    EXPECT_EQ(art[4], "|   |      |  ");
    EXPECT_EQ(art[5], "|   |      |  ");
    EXPECT_EQ(art[6], " --- .        ");
}

TEST(SevenSegment, ReadDigitsFollowsThe8279) {
    I8279 kdc;
    kdc.reset(0);
    kdc.write(1, 0x00, 0);  // 8-digit left entry
    kdc.write(1, 0x90, 0);
    const std::uint8_t h1[] = {0x76, 0x06, 0x48, 0x40, 0x40, 0x40, 0x40, 0x00};
    for (auto c : h1) kdc.write(0, c, 1);
    const auto d = seg::read_digits(kdc);
    EXPECT_EQ(seg::to_text(d), "H1=---- ");
    kdc.write(1, 0xA3, 2);  // blank both nibbles
    EXPECT_EQ(seg::to_text(seg::read_digits(kdc)), "        ");
}

}  // namespace
