// The ROM program (firmware/pisa/interp.pasm) on tapes of lines in every quadrant, full circles,
// arcs both ways and a contour: every 6 ms output against the exact geometry the test itself
// works out from the moves it punched (not from the tape parser or the program).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "asm/pisa_asm.h"
#include "emu/pisa/run.h"

namespace alp85::pisa {
namespace {

struct Move {
    int g = 1;                 // 0 rapid, 1 line, 2 CW, 3 CCW
    std::int64_t x = 0, y = 0; // end point, um
    std::int64_t i = 0, j = 0; // arcs: centre from the start
    int f = 600;               // mm/min (rapid: 1500)
};

const pisa_asm::Result& program() {
    static pisa_asm::Result r = pisa_asm::assemble_file(PISA_FIRMWARE);
    return r;
}

int indicator(const char* name) {
    const auto* s = program().out.find_symbol(name);
    EXPECT_NE(s, nullptr) << name;
    return s ? s->value : 0;
}

std::string punch(const std::vector<Move>& moves) {
    std::string t = "%\n";
    int n = 10;
    for (const auto& m : moves) {
        t += fmt::format("N{:03d} G{:02d} X{:+07d} Y{:+07d}", n, m.g, m.x, m.y);
        if (m.g >= 2) t += fmt::format(" I{:+07d} J{:+07d}", m.i, m.j);
        if (m.g != 0) t += fmt::format(" F{:04d}", m.f);
        t += "\n";
        n += 10;
    }
    return t + "%\n";
}

struct Checked {
    double worst_path_um = 0;       // largest distance of an output from its element
    double worst_bound_um = 0;      // the method's bound there
    std::size_t outputs = 0;        // 6 ms outputs while moving
    double path_mm = 0;
    RunResult run;
};

// Runs the moves and checks every output; returns the figures for the docs.
Checked run_and_check(const std::vector<Move>& moves) {
    Checked c;
    auto parsed = parse_tape(punch(moves));
    EXPECT_FALSE(parsed.error) << (parsed.error ? parsed.error->message : "");
    if (parsed.error) return c;
    RunParams p;
    const auto* wait = program().out.find_symbol("WAIT");
    p.idle_first = wait->value;
    p.idle_last = static_cast<std::uint16_t>(wait->value + 1);
    c.run = run_tape(program().rom, parsed.tape, p);
    const RunResult& r = c.run;
    EXPECT_EQ(r.stop.reason, StopReason::End) << r.stop.message;
    EXPECT_FALSE(r.indicators[static_cast<std::size_t>(indicator("LATE"))]) << "a period's work overran 6 ms";
    EXPECT_FALSE(r.indicators[static_cast<std::size_t>(indicator("STALL"))]) << "the motion waited for the tape";
    EXPECT_FALSE(r.indicators[kOvf]) << "arithmetic overflow";

    // The outputs: skip those at program zero before the motion starts.
    std::vector<std::pair<std::int64_t, std::int64_t>> out;
    for (std::size_t k = 0; k < r.output_samples; ++k) out.emplace_back(r.samples[k].cmd_x_um, r.samples[k].cmd_y_um);
    std::size_t first = 0;
    while (first < out.size() && out[first] == std::make_pair(std::int64_t{0}, std::int64_t{0})) ++first;
    EXPECT_GT(first, 0u);
    double px = 0, py = 0;  // the previous output
    std::int64_t sx = 0, sy = 0;  // the element's start
    std::size_t k = 0;
    for (std::size_t o = first; o < out.size(); ++o) {
        double x = static_cast<double>(out[o].first), y = static_cast<double>(out[o].second);
        if (k == moves.size()) {
            // After the last element: only its end point, once more at most.
            EXPECT_EQ(out[o], std::make_pair(moves.back().x, moves.back().y));
            continue;
        }
        const Move& m = moves[k];
        ++c.outputs;
        double dist = 0, bound = 0;
        if (m.g <= 1) {
            // Distance to the segment; the decision rule keeps |E| <= (A+B)/2, i.e. (A+B)/(2L).
            double ax = static_cast<double>(m.x - sx), ay = static_cast<double>(m.y - sy);
            double len = std::hypot(ax, ay);
            double t = ((x - static_cast<double>(sx)) * ax + (y - static_cast<double>(sy)) * ay) / (len * len);
            EXPECT_GE(t, -1e-9);
            EXPECT_LE(t, 1 + 1e-9);
            dist = std::abs((x - static_cast<double>(sx)) * ay - (y - static_cast<double>(sy)) * ax) / len;
            bound = (std::abs(ax) + std::abs(ay)) / (2 * len);
        } else {
            // Radial distance; the axial search keeps |x^2+y^2-R^2| <= 2(R+1)+1, so |r-R| <= 1+1.5/R,
            // and the last few um (a line within 4 um of the end) add at most 2/R more.
            double cx = static_cast<double>(sx + m.i), cy = static_cast<double>(sy + m.j);
            double radius = std::hypot(static_cast<double>(m.i), static_cast<double>(m.j));
            dist = std::abs(std::hypot(x - cx, y - cy) - radius);
            bound = 1 + 4 / radius;
        }
        c.worst_path_um = std::max(c.worst_path_um, dist);
        c.worst_bound_um = std::max(c.worst_bound_um, bound);
        EXPECT_LE(dist, bound + 1e-9) << fmt::format("element {} output {} at ({}, {})", k, o, x, y);
        // Feedrate: each 6 ms chord is F/10 um within half a um; the last of an element ends on
        // its end point and may be shorter.
        double chord = std::hypot(x - px, y - py);
        double ds = (m.g == 0 ? 1500 : m.f) / 10.0;
        c.path_mm += chord / 1000;
        bool at_end = out[o] == std::make_pair(m.x, m.y);  // a full circle's start is never an output of it
        EXPECT_LT(chord, ds + 0.5 + 1e-9) << fmt::format("element {} output {}", k, o);
        if (!at_end) {
            EXPECT_GE(chord, ds - 0.5 - 1e-9) << fmt::format("element {} output {}", k, o);
        }
        px = x, py = y;
        if (at_end) {
            sx = m.x, sy = m.y;
            ++k;
        }
    }
    EXPECT_EQ(k, moves.size()) << "every end point is an output, exactly";
    EXPECT_EQ(out.back(), std::make_pair(moves.back().x, moves.back().y));
    return c;
}

TEST(PisaProgram, LinesInEveryQuadrantAndAlongTheAxes) {
    std::vector<Move> m;
    const std::int64_t pts[][2] = {{30000, 20000}, {-25000, 35000}, {-40000, -15000}, {10000, -45000},
                                   {50000, 0},     {0, 30000},      {-20000, 0},      {0, -20000},
                                   {-12345, 6789}};
    for (auto& p : pts) {
        m.push_back({1, p[0], p[1], 0, 0, 600});
        m.push_back({1, 0, 0, 0, 0, 600});
    }
    auto c = run_and_check(m);
    EXPECT_LE(c.worst_path_um, 0.7072);  // (A+B)/2L <= 1/sqrt(2)
}

TEST(PisaProgram, FastestAndSlowestFeedrates) {
    run_and_check({{1, 60000, 45000, 0, 0, 1500}, {0, 0, 0}, {1, 300, -400, 0, 0, 10}});
}

TEST(PisaProgram, FullCirclesBothWays) {
    run_and_check({{3, 0, 0, 20000, 0, 600}, {2, 0, 0, 0, -15000, 1000}});  // the arcs' fastest
}

TEST(PisaProgram, ArcsBothWaysIncludingEndsOffTheLattice) {
    // A CCW quarter, a CW three-quarter, and a 30 degree CCW arc whose end is rounded to 1 um.
    const double a = 30 * 3.14159265358979323846 / 180;
    // centre (45000, 20000), start at 180 degrees, end at 210: (45000 - 25000 cos 30, 20000 - 12500)
    std::int64_t ex = 45000 - static_cast<std::int64_t>(std::lround(25000 * std::cos(a)));
    std::int64_t ey = 20000 - 12500;
    run_and_check({{3, 20000, 20000, 0, 20000, 600},
                   {2, 20000 + 30000, 20000 - 30000, 30000, 0, 750},
                   {1, 20000, 20000, 0, 0, 600},
                   {3, ex, ey, 25000, 0, 500}});
}

TEST(PisaProgram, ContourOfLinesAndArcs) {
    // A slot with rounded ends, a full circle inside, a rapid back.
    auto c = run_and_check({{0, 10000, 0},
                            {1, 60000, 0, 0, 0, 800},
                            {3, 60000, 30000, 0, 15000, 800},
                            {1, 10000, 30000, 0, 0, 800},
                            {3, 10000, 0, 0, -15000, 800},
                            {1, 35000, 5000, 0, 0, 400},
                            {2, 35000, 5000, 0, 10000, 700},
                            {2, 45000, 15000, 0, 10000, 700},
                            {0, 0, 0}});
    EXPECT_GT(c.outputs, 1000u);
}

TEST(PisaProgram, AnElementShorterThanTheNextBlocksReadingStallsAndSaysSo) {
    // 30 um at 600 mm/min is one period; the next block (29 characters at 300/s) takes 97 ms.
    auto parsed = parse_tape(punch({{1, 30, 0, 0, 0, 600}, {1, 20030, 0, 0, 0, 600}}));
    ASSERT_FALSE(parsed.error);
    auto r = run_tape(program().rom, parsed.tape);
    EXPECT_EQ(r.stop.reason, StopReason::End);
    EXPECT_TRUE(r.indicators[static_cast<std::size_t>(indicator("STALL"))]);
}

// The guard against a program that never ends is sized from the tape, by hand here.
TEST(PisaRun, TheGuardIsTwiceTheTapesOwnTimeAndAMinute) {
    // 60 mm at 600 mm/min: 6 s, 60 000 000 digit steps of 100 ns. On tape N G X Y F and the end of
    // block are 4 + 3 + 8 + 8 + 5 + 1 = 29 characters, 29 x 33 333 steps (300 characters/s) = 966 657.
    // Guard: 2 x 60 966 657 + 600 000 000 (a minute) = 721 933 314.
    auto line = parse_tape("N010 G01 X60.0 Y0 F600\n");
    ASSERT_FALSE(line.error);
    EXPECT_EQ(tape_steps(line.tape), 60'966'657u);
    EXPECT_EQ(guard_steps(line.tape), 721'933'314u);
    // A full circle of R 20 mm at 750 mm/min: 2 pi 20 mm x 60 / 750 = 10.0530965 s, 100 530 965
    // steps; N G X Y I J F and the end: 45 characters, 1 499 985 steps.
    auto circle = parse_tape("N010 G03 X0 Y0 I-20.0 J0 F750\n");
    ASSERT_FALSE(circle.error);
    EXPECT_NEAR(static_cast<double>(tape_steps(circle.tape)), 102'030'950.0, 1.0);
    // A run with a guard of its own stops there.
    RunParams p;
    p.max_steps = 1'000'000;  // 0.1 s
    const RunResult r = run_tape(program().rom, line.tape, p);
    EXPECT_EQ(r.stop.reason, StopReason::StepLimit);
    EXPECT_EQ(r.max_steps, 1'000'000u);
}

TEST(PisaRun, ALongValidTapeRunsToItsEnd) {
    // 101 mm at F10 (the slowest feed: 1 um a 6 ms period) is 101 000 periods, 606 s: beyond the
    // fixed 10 minutes the run used to stop at, within every limit of the tape.
    auto parsed = parse_tape("N010 G01 X101.0 Y0 F10\n");
    ASSERT_FALSE(parsed.error);
    const RunResult r = run_tape(program().rom, parsed.tape);
    EXPECT_EQ(r.stop.reason, StopReason::End) << r.stop.message;
    EXPECT_GE(r.steps, 6'060'000'000u);
    EXPECT_LT(r.steps, r.max_steps);
    ASSERT_GT(r.output_samples, 0u);
    EXPECT_EQ(r.samples[r.output_samples - 1].cmd_x_um, 101'000);
}

}  // namespace
}  // namespace alp85::pisa
