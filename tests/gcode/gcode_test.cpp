// The G-code subset (emu/gcode): every word, units, modes, the refusals with their columns, and
// the path table's bytes. Expected steps are worked by hand at 0.05 mm a step.
#include <gtest/gtest.h>

#include <cmath>

#include "emu/gcode/gcode.h"
#include "emu/gcode/path_table.h"

namespace alp85::gcode {
namespace {

std::vector<Entry> ok(std::string_view text) {
    Parsed p = parse(text);
    EXPECT_FALSE(p.error) << p.error->line << ":" << p.error->column << ": " << p.error->message;
    return p.entries;
}

Error refused(std::string_view text) {
    Parsed p = parse(text);
    EXPECT_TRUE(p.error);
    return p.error.value_or(Error{});
}

TEST(GcodeWords, RapidAndLineInMillimetresAbsolute) {
    const auto e = ok("G00 X10 Y5\nG01 X12.5 Y5 F750\n");
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].kind, Kind::Rapid);
    EXPECT_EQ(e[0].feed, 1500);  // rapid: the firmware's fastest
    EXPECT_EQ(e[0].x, 200);      // 10 mm / 0.05
    EXPECT_EQ(e[0].y, 100);
    EXPECT_EQ(e[1].kind, Kind::Line);
    EXPECT_EQ(e[1].x, 250);
    EXPECT_EQ(e[1].feed, 750);
}

TEST(GcodeWords, InchesAndIncrementalModes) {
    // 1 in = 25.4 mm = 508 steps; F10 in/min = 254 mm/min.
    const auto e = ok("G20 G91\nG01 X1 Y0.5 F10\nX1\nG21 G90 X1\n");
    ASSERT_EQ(e.size(), 3u);
    EXPECT_EQ(e[0].x, 508);
    EXPECT_EQ(e[0].y, 254);
    EXPECT_EQ(e[0].feed, 254);
    EXPECT_EQ(e[1].x, 1016);  // incremental, modal G01
    EXPECT_EQ(e[2].x, 20);    // back to mm, absolute
    EXPECT_EQ(e[2].feed, 254);
}

TEST(GcodeWords, CommentsLineNumbersPercentAndZOnItsOwn) {
    const auto e = ok("%\nN10 (go) G00 X1 ; the rest is a comment\nn20 g01 z2 f100\n%\n");
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[0].x, 20);
    EXPECT_EQ(e[1].z, 40);
    EXPECT_EQ(e[1].x, 20);
}

TEST(GcodeArcs, CentreByIAndJChoosesCrByEq9) {
    // R = 20 mm = 400 steps: eps_A = 400 * 2^(-2C-4) <= 1 needs 2^(2C+4) >= 400, so C_R = 3
    // (eps_A = 400/1024 = 0.39 step). A whole circle is 2 pi * 8 = 50.27 segments: 50 whole ones
    // and a shorter last one.
    const auto e = ok("G00 X70 Y50\nG03 X70 Y50 I-20 J0 F750\n");
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[1].kind, Kind::ArcCcw);
    EXPECT_EQ(e[1].cr, 3);
    EXPECT_EQ(e[1].cx, 1000);
    EXPECT_EQ(e[1].cy, 1000);
    EXPECT_EQ(e[1].n, 50);
    EXPECT_DOUBLE_EQ(e[1].radius, 400);
}

TEST(GcodeArcs, QuarterCircleClockwiseByR) {
    // From (20, 30) to (10, 20) mm, R 10, clockwise short arc: centre (10, 30) mm = (200, 600).
    // R = 200 steps: 2^(2C+4) >= 200 gives C_R = 2; a quarter is (pi/2) * 4 = 6.28 segments: 6 + 1.
    const auto e = ok("G00 X20 Y30\nG02 X10 Y20 R10 F300\n");
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[1].kind, Kind::ArcCw);
    EXPECT_EQ(e[1].cx, 200);
    EXPECT_EQ(e[1].cy, 600);
    EXPECT_EQ(e[1].cr, 2);
    EXPECT_EQ(e[1].n, 6);
    // R negative: the long way round (3/4 turn), centre across the chord: (20, 20) mm; 3 pi/2 * 4
    // = 18.85 segments: 18 + 1.
    const auto l = ok("G00 X20 Y30\nG02 X10 Y20 R-10 F300\n");
    EXPECT_EQ(l[1].cx, 400);
    EXPECT_EQ(l[1].cy, 400);
    EXPECT_EQ(l[1].n, 18);
}

TEST(GcodeArcs, ChoiceOfCrAndBound) {
    EXPECT_EQ(choose_cr(16), 1);    // 16 * 2^-6 = 0.25
    EXPECT_EQ(choose_cr(64), 1);    // 64 * 2^-6 = 1
    EXPECT_EQ(choose_cr(65), 2);
    EXPECT_EQ(choose_cr(256), 2);   // 256 * 2^-8 = 1
    EXPECT_EQ(choose_cr(4000), 4);  // 2^12 = 4096 >= 4000 > 2^10
    EXPECT_DOUBLE_EQ(eps_a(3, 400), 400.0 / 1024);
}

TEST(GcodeErrors, EachWithItsLineAndColumn) {
    struct Case {
        const char* text;
        int line, column;
        const char* starts;
    } cases[] = {
        {"G00 X1\nG04 P1\n", 2, 1, "G4 is not in the subset"},
        {"G00 X1 M30\n", 1, 8, "'M' is not in the subset"},
        {"G01 X1\n", 1, 1, "no feedrate (F)"},
        {"X1\n", 1, 1, "a move with no motion mode"},
        {"G01 X1 F1600\n", 1, 8, "feedrate 1600 mm/min is outside"},
        {"G00 X-1\n", 1, 5, "X -1.000 mm is outside the table's travel (0 to 1500 mm)"},
        {"G00 Y201\n", 1, 5, "Y 201.000 mm is outside the table's travel (0 to 200 mm)"},
        {"G00 X1 Z1\n", 1, 8, "Z moves on its own"},
        {"G00 X1 I1\n", 1, 8, "I, J and R belong to arcs"},
        {"G00 X10 Y10\nG02 X20 Y10 F100\n", 2, 5, "an arc needs its centre"},
        {"G00 X10 Y10\nG02 X20 Y10 I5 R5 F100\n", 2, 16, "an arc takes I and J or R"},
        {"G00 X10 Y10\nG02 X20 Y10 R4 F100\n", 2, 13, "no arc of radius 4.000 mm"},
        {"G00 X10 Y10\nG03 X30 Y10 I5 F100\n", 2, 13, "the end point is not on the arc"},
        {"G00 X10 Y10\nG03 X10 Y10 I-9.9 F100\n", 2, 13, "the arc leaves the table's travel on X"},
        {"G00 X1 X2\n", 1, 8, "'X' twice"},
        {"G00 N5 X1\n", 1, 5, "a line number (N) must open"},
        {"G00 X1 (open\n", 1, 8, "comment not closed"},
        {"G00 X1 #\n", 1, 8, "unexpected character '#'"},
        {"G00 X\n", 1, 5, "'X' needs a number"},
        {"G00 G01 X1\n", 1, 5, "two motion words"},
    };
    for (const Case& c : cases) {
        const Error e = refused(c.text);
        EXPECT_EQ(e.line, c.line) << c.text;
        EXPECT_EQ(e.column, c.column) << c.text;
        EXPECT_EQ(e.message.rfind(c.starts, 0), 0u) << c.text << " gave: " << e.message;
    }
}

TEST(PathTable, BytesAndHex) {
    Entry e;
    e.kind = Kind::ArcCcw;
    e.cr = 3;
    e.feed = 750;   // 02EEH
    e.x = 1400;     // 0578H
    e.y = 1000;     // 03E8H
    e.cx = 1000;
    e.cy = 1000;
    e.n = 50;
    const auto b = table_bytes({{e}});
    ASSERT_EQ(b.size(), 32u);  // the entry and the path's End
    const std::uint8_t want[16] = {4, 3, 0xEE, 0x02, 0x78, 0x05, 0xE8, 0x03, 0, 0, 0xE8, 0x03, 0xE8, 0x03, 50, 0};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(b[i], want[i]) << i;
    for (int i = 16; i < 32; ++i) EXPECT_EQ(b[i], 0) << i;
    // One record: 02 bytes at 3800H, checksum = -(02+38+00+00+AB+CD) mod 256 = 0x4E.
    EXPECT_EQ(intel_hex(0x3800, {0xAB, 0xCD}), ":02380000ABCD4E\n:00000001FF\n");
    EXPECT_EQ(kTableBase, 0x3DD0);  // after the master program's 3000H-3DCFH
    EXPECT_EQ(kTableSize / kEntrySize, 35u);  // scripts/master/sampling/octants: 35 entries
    EXPECT_EQ(kTableBase + kTableSize, 0x4000);
}

// The sampling method's table (docs/contours.md "Sampling"): headers where the tool must stop, the
// feed as steps a 2 ms sample and the group's length to its stop, by hand.
TEST(GcodeSampling, DirectivesChooseTheMethodAndTheRamp) {
    const Parsed p = parse("(METHOD SAMPLING)\n( ramp off )\nG01 X1 F750\n");
    ASSERT_FALSE(p.error);
    ASSERT_TRUE(p.method && p.ramp);
    EXPECT_EQ(*p.method, Method::Sampling);
    EXPECT_FALSE(*p.ramp);
    EXPECT_FALSE(parse("(a comment)\nG01 X1 F750\n").method);
    const Parsed bad = parse("G21\n  (METHOD FAST)\n");
    ASSERT_TRUE(bad.error);
    EXPECT_EQ(bad.error->line, 2);
    EXPECT_EQ(bad.error->column, 3);
    EXPECT_TRUE(parse("(RAMP SLOW)\n").error);
}

TEST(GcodeSampling, HeadersAtStopsWithFeedAndLength) {
    // A line of 300 x 400 steps (500 long) at 750 mm/min, then on at the same heading (no stop),
    // then back (a reversal: a stop), then a Z move (a stop).
    const Parsed p = parse("G21 G90\nG01 X15 Y20 F750\nX30 Y40\nX15 Y20\nZ5\n");
    ASSERT_FALSE(p.error);
    const auto s = sampling_path(p.entries, true);
    ASSERT_EQ(s.size(), 7u);
    EXPECT_EQ(s[0].kind, Kind::Sample);
    EXPECT_EQ(s[0].cr, 1);  // the ramp
    EXPECT_EQ(s[0].feed, 32768);  // 750 mm/min = 250 steps/s = 0.5 step a sample
    // 1000 steps, less 1000/32 + 4: 964.75 steps in 16.16 (the margin covers the 16-entry C_x table)
    const double l0 = s[0].y + s[0].x / 65536.0;
    EXPECT_NEAR(l0, 1000 - 1000 / 32.0 - 4, 1.0 / 65536);
    EXPECT_EQ(s[1].kind, Kind::Line);
    EXPECT_EQ(s[2].kind, Kind::Line);
    EXPECT_EQ(s[3].kind, Kind::Sample);  // the reversal
    EXPECT_NEAR(s[3].y + s[3].x / 65536.0, 500 - 500 / 32.0 - 4, 1.0 / 65536);
    EXPECT_EQ(s[4].kind, Kind::Line);
    EXPECT_EQ(s[5].kind, Kind::Sample);  // before the Z move
    EXPECT_EQ(s[6].z, 100);
    EXPECT_EQ(sampling_path(p.entries, false)[0].cr, 0);
    // 1500 mm/min is one step a sample, kept to FFFFH
    EXPECT_EQ(sampling_path(parse("G01 X1 F1500\n").entries, true)[0].feed, 0xFFFF);
}

}  // namespace
}  // namespace alp85::gcode
