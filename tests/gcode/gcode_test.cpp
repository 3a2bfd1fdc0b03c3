// The G-code subset (emu/gcode): every word, units, modes, the refusals with their columns, and
// the path table's bytes. Expected steps are worked by hand at 0.05 mm a step.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

// G91: the increments add up exactly and the point is rounded to a step once, as under G90; so an
// incremental program gives the table of the absolute program through the same points.
std::string repeat(const std::string& block, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += block;
    return s;
}

void expect_same_table(const std::vector<Entry>& a, const std::vector<Entry>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].kind, b[i].kind) << i;
        EXPECT_EQ(a[i].feed, b[i].feed) << i;
        EXPECT_EQ(a[i].x, b[i].x) << i;
        EXPECT_EQ(a[i].y, b[i].y) << i;
        EXPECT_EQ(a[i].z, b[i].z) << i;
        EXPECT_EQ(a[i].cx, b[i].cx) << i;
        EXPECT_EQ(a[i].cy, b[i].cy) << i;
        EXPECT_EQ(a[i].n, b[i].n) << i;
    }
}

TEST(GcodeIncremental, TenSmallStepsEndWhereTheAbsoluteProgramEnds) {
    // From X10, ten X0.03: X10.30 = 206 steps (not 10 x round(0.6) = 10 more, 210). The points
    // 10.03 ... 10.30 mm are 200.6, 201.2, 201.8, 202.4, 203.0, 203.6, 204.2, 204.8, 205.4, 206.0
    // steps: rounded, 201 202 203 204 205 206 are new (the others stand still), so 1 + 6 entries.
    const auto inc = ok("G21 G90 G01 X10 F100\nG91\n" + repeat("X0.03\n", 10));
    std::string abs = "G21 G90 G01 X10 F100\n";
    for (int k = 1; k <= 10; ++k) abs += "X" + std::to_string(10 + 0.03 * k).substr(0, 5) + "\n";
    const auto absolute = ok(abs);
    ASSERT_EQ(inc.size(), 7u);
    EXPECT_EQ(inc.back().x, 206);
    expect_same_table(inc, absolute);
}

TEST(GcodeIncremental, StepsBelowHalfAStepStillAddUp) {
    // Thirty X0.024 (0.48 step each, nothing alone): 0.72 mm = 14.4 steps, 14. The rounded
    // points 0.48k go 0, 1, 1, 2, ... 14: fourteen entries of one step.
    const auto inc = ok("G01 F200 G91\n" + repeat("X0.024\n", 30));
    std::string abs = "G01 F200 G90\n";
    for (int k = 1; k <= 30; ++k) abs += "X" + std::to_string(0.024 * k).substr(0, 5) + "\n";
    ASSERT_EQ(inc.size(), 14u);
    EXPECT_EQ(inc.back().x, 14);
    expect_same_table(inc, ok(abs));
    // In inches: ten X0.001 = 0.254 mm = 5.08 steps, 5 (one step each alone, 0.508, would be 10).
    const auto inch = ok("G20 G91 G01 F10\n" + repeat("X0.001\n", 10));
    ASSERT_FALSE(inch.empty());
    EXPECT_EQ(inch.back().x, 5);
}

TEST(GcodeIncremental, MixedWithAbsoluteArcsAndZAsTheAbsoluteProgram) {
    // The same contour twice: G91 blocks among G90 ones (arcs by I J, which are relative to the
    // start either way; Z on its own), and every point written out absolutely.
    const auto inc = ok("G21 G90 G00 X20.01 Y30.02\n"
                        "G91 G02 X-10 Y-10 I-10 J0 F300\n"  // to (10.01, 20.02)
                        "G90 G01 X40.004\n"
                        "G91 Y0.013\nY0.013\nY0.013\n"      // 20.033, 20.046, 20.059
                        "Z2.02\nZ-0.01\n"                   // 2.02, 2.01
                        "G03 X-10 Y10 I0 J10\n"             // to (30.004, 30.059), centre (40.004, 30.059)
                        "G90 X30.004 Y10.059 R-10\n");
    const auto abs = ok("G21 G90 G00 X20.01 Y30.02\n"
                        "G02 X10.01 Y20.02 I-10 J0 F300\n"
                        "G01 X40.004\n"
                        "Y20.033\nY20.046\nY20.059\n"
                        "Z2.02\nZ2.01\n"
                        "G03 X30.004 Y30.059 I0 J10\n"
                        "X30.004 Y10.059 R-10\n");
    expect_same_table(inc, abs);
    // (40.004, 20.059) mm is (800.08, 401.18) steps: (800, 401); the arc's centre (40.004,
    // 30.059) mm is (800, 601).
    ASSERT_GE(inc.size(), 6u);
    EXPECT_EQ(inc[5].kind, Kind::ArcCcw);
    EXPECT_EQ(inc[5].cx, 800);
    EXPECT_EQ(inc[5].cy, 601);
}

TEST(GcodeWords, FeedIsRoundedToWholeMmPerMinuteThenChecked) {
    // The table holds whole mm/min and the firmware takes 6 to 1500: F5.9 is 6 (inside), F0.236
    // in/min is 5.9944 mm/min, 6; F1500.4 is 1500. F5.4 (5) and F1500.6 (1501) are outside, and the
    // refusal says which whole number is.
    EXPECT_EQ(ok("G01 X1 F5.9\n").at(0).feed, 6);
    EXPECT_EQ(ok("G20 G01 X0.1 F0.236\n").at(0).feed, 6);
    EXPECT_EQ(ok("G01 X1 F1500.4\n").at(0).feed, 1500);
    EXPECT_EQ(ok("G01 X1 F6\n").at(0).feed, 6);
    const Error low = refused("G01 X1 F5.4\n");
    EXPECT_EQ(low.message, "feedrate 5.4 mm/min, 5 to the whole mm/min, is outside the firmware's 6 to 1500 mm/min");
    EXPECT_EQ(low.column, 8);
    EXPECT_EQ(refused("G01 X1 F1500.6\n").message,
              "feedrate 1500.6 mm/min, 1501 to the whole mm/min, is outside the firmware's 6 to 1500 mm/min");
    EXPECT_EQ(refused("G01 X1 F5\n").message, "feedrate 5 mm/min is outside the firmware's 6 to 1500 mm/min");
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
