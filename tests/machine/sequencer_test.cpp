// The sequencer of thesis Figure 3.10: full step, two phases on, both directions, one step per
// active edge of PULSE with DIRECTION sampled at that edge. Expected patterns from the Gray
// sequence AB -> /A B -> /A /B -> A /B (sequencer.h), written out by hand.
#include <gtest/gtest.h>

#include <bitset>
#include <vector>

#include "peripherals/sequencer.h"

namespace alp85::test {
namespace {

using periph::Sequencer;
constexpr std::uint8_t kAB = 0b1010, kAbarB = 0b0110, kAbarBbar = 0b0101, kABbar = 0b1001;

std::vector<std::uint8_t> run(Sequencer& seq, Sequencer::State& s, const std::vector<bool>& dirs) {
    std::vector<std::uint8_t> out;
    for (bool d : dirs) {
        seq.set_inputs(s, false, d);
        seq.set_inputs(s, true, d);
        out.push_back(Sequencer::phases(s));
    }
    return out;
}

TEST(Sequencer, PositiveOrder) {
    Sequencer seq;
    Sequencer::State s;
    EXPECT_EQ(Sequencer::phases(s), kAB);
    EXPECT_EQ(run(seq, s, {true, true, true, true, true}),
              (std::vector<std::uint8_t>{kAbarB, kAbarBbar, kABbar, kAB, kAbarB}));
    EXPECT_EQ(s.count, 5);
}

TEST(Sequencer, NegativeOrder) {
    Sequencer seq;
    Sequencer::State s;
    EXPECT_EQ(run(seq, s, {false, false, false, false, false}),
              (std::vector<std::uint8_t>{kABbar, kAbarBbar, kAbarB, kAB, kABbar}));
    EXPECT_EQ(s.count, -5);
}

TEST(Sequencer, Reversal) {
    Sequencer seq;
    Sequencer::State s;
    EXPECT_EQ(run(seq, s, {true, true, false, false, false, true}),
              (std::vector<std::uint8_t>{kAbarB, kAbarBbar, kAbarB, kAB, kABbar, kAB}));
    EXPECT_EQ(s.count, 0);
}

TEST(Sequencer, TwoPhasesOnOneFlipFlopPerStep) {
    for (int k = 0; k < 4; ++k) {
        const std::uint8_t p = Sequencer::kPattern[k], q = Sequencer::kPattern[(k + 1) & 3];
        EXPECT_EQ(((p >> 3) & 1) + ((p >> 2) & 1), 1) << k;  // A xor /A
        EXPECT_EQ(((p >> 1) & 1) + (p & 1), 1) << k;         // B xor /B
        EXPECT_EQ(std::bitset<4>(p ^ q).count(), 2u) << k;   // one flip-flop toggles: two outputs change
    }
}

TEST(Sequencer, StepsOnRisingEdgeOnlyWithDirectionAtTheEdge) {
    Sequencer seq;
    Sequencer::State s;
    EXPECT_EQ(seq.set_inputs(s, false, true), 0);
    EXPECT_EQ(seq.set_inputs(s, true, true), 1);    // rising edge: a step
    EXPECT_EQ(seq.set_inputs(s, true, true), 0);    // level, no edge
    EXPECT_EQ(seq.set_inputs(s, true, false), 0);   // direction changes while high: no step
    EXPECT_EQ(seq.set_inputs(s, false, false), 0);  // falling edge: no step
    EXPECT_EQ(seq.set_inputs(s, true, false), -1);  // rising with direction low: back
    EXPECT_EQ(s.count, 0);
}

TEST(Sequencer, FallingEdgeAndDirectionPolarityAreParameters) {
    Sequencer seq({Sequencer::Edge::Falling, false});
    Sequencer::State s;
    EXPECT_EQ(seq.set_inputs(s, true, true), 0);
    EXPECT_EQ(seq.set_inputs(s, false, true), -1);  // falling edge, DIRECTION high = negative
    EXPECT_EQ(seq.set_inputs(s, true, false), 0);
    EXPECT_EQ(seq.set_inputs(s, false, false), 1);
}

}  // namespace
}  // namespace alp85::test
