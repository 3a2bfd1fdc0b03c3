// The linear transducer and its direction discrimination (thesis §3.2.4.1, Table 3.3): photocell
// sequences, the direction latch, counting one increment per scale line, and back-and-forth chatter.
// Positions are chosen by hand from the pitch (0.05 mm) and offset (0.025 mm).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "peripherals/transducer.h"

namespace alp85::test {
namespace {

using periph::Transducer;
constexpr double kP = 0.05;

// The centre of quadrature state q (q = 0 starts at the line x = 0.025 mm).
double centre(int q) { return 0.025 + (q + 0.5) * kP / 4; }

std::pair<bool, bool> cells(const Transducer::State& s) {
    return {Transducer::photocell_a(s), Transducer::photocell_b(s)};
}

TEST(Transducer, PhotocellsFollowTable33Forward) {
    Transducer tr;
    Transducer::State s;
    tr.init(s, centre(0));
    std::vector<std::pair<bool, bool>> seen{cells(s)};
    for (int q = 1; q <= 4; ++q) {
        tr.update(s, centre(q));
        seen.push_back(cells(s));
        EXPECT_TRUE(tr.outputs(s).direction);
    }
    // both lit, then A dark while B lit, both dark, A lit B dark, both lit.
    const std::vector<std::pair<bool, bool>> want{{1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}};
    EXPECT_EQ(seen, want);
}

TEST(Transducer, BackwardRunsTheSequenceInReverseAndLatchesDirection) {
    Transducer tr;
    Transducer::State s;
    tr.init(s, centre(0));
    tr.update(s, centre(-1));
    EXPECT_EQ(cells(s), (std::pair<bool, bool>{1, 0}));
    EXPECT_FALSE(tr.outputs(s).direction);
    tr.update(s, centre(-2));
    EXPECT_EQ(cells(s), (std::pair<bool, bool>{0, 0}));
    tr.update(s, centre(-1));  // turns round: direction flips at the next transition
    EXPECT_TRUE(tr.outputs(s).direction);
}

TEST(Transducer, OneIncrementPerLineAtTheMiddleOfEachStep) {
    Transducer tr;
    Transducer::State s;
    tr.init(s, 0.0);  // the table on step 0, half a pitch before the line at 0.025 mm
    const bool c0 = tr.outputs(s).count;
    tr.update(s, 0.0249);
    EXPECT_EQ(s.count, 0);
    tr.update(s, 0.0251);  // across the line
    EXPECT_EQ(s.count, 1);
    EXPECT_NE(tr.outputs(s).count, c0);
    for (int k = 2; k <= 10; ++k) tr.update(s, k * kP);  // steps 2..10, one line each
    EXPECT_EQ(s.count, 10);
    EXPECT_EQ(tr.outputs(s).count, c0);  // ten toggles
    tr.update(s, 3 * kP);                 // seven steps back at once: the logic walks every state
    EXPECT_EQ(s.count, 3);
    EXPECT_FALSE(tr.outputs(s).direction);
}

TEST(Transducer, ChatterAcrossALineGivesEdgesBackAndForthAndNetZero) {
    Transducer tr;
    Transducer::State s;
    tr.init(s, 0.0);
    const bool c0 = tr.outputs(s).count;
    int toggles = 0;
    bool last = c0;
    for (int k = 0; k < 7; ++k) {
        for (double x : {0.030, 0.020}) {  // overshoot past the line and back
            tr.update(s, x);
            const auto o = tr.outputs(s);
            if (o.count != last) ++toggles, last = o.count;
            EXPECT_EQ(o.direction, x > 0.025);
        }
    }
    EXPECT_EQ(toggles, 14);
    EXPECT_EQ(s.count, 0);
    EXPECT_EQ(tr.outputs(s).count, c0);
}

TEST(Transducer, DirectionPolarityIsAParameter) {
    Transducer tr({0.05, 0.025, false});
    Transducer::State s;
    tr.init(s, 0.0);
    tr.update(s, 0.05);
    EXPECT_FALSE(tr.outputs(s).direction);  // + move reads low
    tr.update(s, 0.0);
    EXPECT_TRUE(tr.outputs(s).direction);
}

TEST(Transducer, PitchAndOffsetAreParameters) {
    Transducer tr({0.1, 0.0, true});  // lines every 0.1 mm, on the step positions
    Transducer::State s;
    tr.init(s, 0.01);
    tr.update(s, 0.31);
    EXPECT_EQ(s.count, 3);  // lines at 0.1, 0.2, 0.3
}

}  // namespace
}  // namespace alp85::test
