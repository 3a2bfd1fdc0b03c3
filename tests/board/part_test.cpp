// A part added in one place: a toy LED latch on port 00H with a heartbeat clock. It shows that the
// machine advances, resets and saves any periph::Part without knowing what it is.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>

#include "emu/board/machine.h"
#include "emu/program/image_loader.h"
#include "peripherals/part.h"
#include "tests/board/led_latch.h"

namespace alp85::test {
namespace {

// MVI A,55H (7 T) / OUT 00H (10 T: its I/O write cycle starts at T-state 7 + 7 = 14) / JMP $ (10 T).
const std::vector<std::uint8_t> kProgram = {0x3E, 0x55, 0xD3, 0x00, 0xC3, 0x04, 0x08};

struct Board {
    Machine m;
    LedLatch leds;
    Board() {
        m.attach(leds, &leds, 0x00, 0x00);  // the one place the part is added
        m.load(0x0800, kProgram);
        m.cpu().regs().pc = 0x0800;
    }
};

TEST(Parts, AToyPartAdvancesWithTheMachine) {
    Board b;
    EXPECT_EQ(b.m.find_part("leds"), &b.leds);
    b.m.run_until(10'000);
    const std::uint64_t t = b.m.now();
    EXPECT_EQ(b.leds.s.value, 0x55);
    EXPECT_EQ(b.leds.s.now, t);                 // caught up with the CPU
    EXPECT_EQ(b.leds.s.lit, (t - 14) * 4);      // 55H lights four LEDs from the OUT's write cycle on
    EXPECT_EQ(b.leds.s.beats, t / 1000);
}

TEST(Parts, TheSchedulerStopsAtAPartsEvent) {
    Board b;
    std::vector<std::uint64_t> seen;
    // The condition is checked after every batch; batches end at the part's heartbeats, so the
    // machine is seen within one instruction (at most 10 T-states: JMP) after each beat.
    b.m.run_until(5'000, [&] {
        seen.push_back(b.m.now());
        return false;
    });
    for (std::uint64_t beat = 1000; beat < 5000; beat += 1000) {
        const bool near = std::any_of(seen.begin(), seen.end(), [&](std::uint64_t t) { return t >= beat && t < beat + 10; });
        EXPECT_TRUE(near) << "no stop near " << beat;
    }
}

TEST(Parts, AToyPartResetsWithTheMachine) {
    Board b;
    b.m.run_until(1'000);
    ASSERT_EQ(b.leds.s.value, 0x55);
    b.m.reset();
    EXPECT_EQ(b.leds.s.value, 0x00);
}

TEST(Parts, AToyPartSurvivesSnapshotRestoreContinueBitForBit) {
    Board a;
    a.m.run_until(2'345);
    const std::vector<std::uint8_t> snap = a.m.snapshot_bytes();
    a.m.run_until(50'000);

    Board b;
    b.m.run_until(777);  // somewhere else entirely
    b.m.restore_bytes(snap);
    b.m.run_until(50'000);
    EXPECT_EQ(b.m.now(), a.m.now());
    EXPECT_EQ(b.leds.s.lit, a.leds.s.lit);
    EXPECT_EQ(b.leds.s.beats, a.leds.s.beats);
    EXPECT_EQ(b.m.snapshot_bytes(), a.m.snapshot_bytes());
}

TEST(Parts, AMachineWithoutThePartRefusesItsSnapshot) {
    Board a;
    a.m.run_until(1'000);
    Machine plain;
    const auto before = plain.snapshot_bytes();
    try {
        plain.restore_bytes(a.m.snapshot_bytes());
        FAIL() << "a machine without LEDs accepted their snapshot";
    } catch (const SnapshotError& e) {
        EXPECT_NE(std::string(e.what()).find("LEDS"), std::string::npos) << e.what();
    }
    EXPECT_EQ(plain.snapshot_bytes(), before);
}

// The toy describes itself: its latch as OUT 00H wrote it (55H: LEDs 0, 2, 4, 6 lit) and its
// heartbeats (one per 1000 T-states), read without changing it.
TEST(Parts, AToyPartDescribesItsTwoRegisters) {
    Board b;
    b.m.run_until(10'000);
    const std::vector<std::uint8_t> before = b.m.snapshot_bytes();
    periph::Description d;
    d.now = b.m.now();
    b.leds.describe(d);
    ASSERT_EQ(d.fields.size(), 2u);
    EXPECT_EQ(d.fields[0].name, "latch");
    EXPECT_EQ(d.fields[0].shown_value(), "55H: 4 lit");
    EXPECT_EQ(d.find_watch("LATCH"), &d.fields[0]);
    EXPECT_EQ(d.fields[1].name, "heartbeats");
    EXPECT_EQ(d.fields[1].value, static_cast<std::int64_t>(b.m.now() / 1000));
    EXPECT_EQ(b.m.snapshot_bytes(), before);
}

TEST(Parts, TwoPartsWithOneTagAreRefused) {
    Board b;
    LedLatch other;
    EXPECT_THROW(b.m.attach(other), std::invalid_argument);
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

// The machine tool is a part like the others: stopped in the middle of a move (physical motors,
// rotors ringing), saved, restored into another board and run on, it ends exactly where the
// uninterrupted run does, bit for bit (scripts/machine/axes.asm drives each axis both ways).
TEST(Parts, TheMachineToolMidMoveSurvivesSnapshotRestoreContinueBitForBit) {
    const std::string program = std::string(ALP85_SOURCE_DIR) + "/scripts/machine/axes.asm";
    Machine a;
    load_image(a, program);
    a.reset();
    a.run_until(board::tstates_from_ms(41.3));  // X half-way out, between two steps
    ASSERT_FALSE(a.tool().settled(periph::MachineTool::Axis::X));
    const std::vector<std::uint8_t> snap = a.snapshot_bytes();
    a.run_until(board::tstates_from_ms(300));

    Machine b;
    load_image(b, program);
    b.restore_bytes(snap);
    b.run_until(board::tstates_from_ms(300));
    for (int i = 0; i < 3; ++i) {
        const auto axis = static_cast<periph::MachineTool::Axis>(i);
        EXPECT_EQ(b.tool().table_mm(axis), a.tool().table_mm(axis));  // exactly: the same doubles
        EXPECT_EQ(b.tool().transducer_count(axis), a.tool().transducer_count(axis));
    }
    EXPECT_EQ(b.snapshot_bytes(), a.snapshot_bytes());
}

}  // namespace
}  // namespace alp85::test
