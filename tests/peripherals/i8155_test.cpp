// 8155 tests. Expected values come from the Intel 8155/8156 data sheet (register layout, timer
// modes, handshake sequence) and hand arithmetic in T-states (TIMER IN = CLK OUT, one count per
// T-state). Facts are listed with their sources in docs/peripherals.md.
#include "peripherals/i8155.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "peripherals/state_io.h"

namespace {

using alp85::periph::I8155;
using Port = I8155::Port;

constexpr std::uint8_t kStart = 0xC0;        // TM2 TM1 = 11
constexpr std::uint8_t kStop = 0x40;         // 01
constexpr std::uint8_t kStopAfterTc = 0x80;  // 10

// Count length register, high byte: M2 M1 in bits 7-6 (bits 15-14 of the 16-bit register).
constexpr std::uint8_t kSingleSquare = 0x00;
constexpr std::uint8_t kContSquare = 0x40;
constexpr std::uint8_t kSinglePulse = 0x80;
constexpr std::uint8_t kContPulse = 0xC0;

struct Edge {
    bool level;
    std::uint64_t at;
    bool operator==(const Edge&) const = default;
};

class I8155Test : public ::testing::Test {
protected:
    void SetUp() override {
        chip.reset(0);
        chip.on_timer_out([this](bool level, std::uint64_t at) { edges.push_back({level, at}); });
    }
    void load_count(std::uint16_t count, std::uint8_t mode_bits, std::uint64_t now) {
        chip.write(I8155::kTimerLow, static_cast<std::uint8_t>(count & 0xFF), now);
        chip.write(I8155::kTimerHigh, static_cast<std::uint8_t>(mode_bits | (count >> 8)), now);
    }
    std::uint16_t read_count(std::uint64_t now) {
        const std::uint8_t lo = chip.read(I8155::kTimerLow, now);
        const std::uint8_t hi = chip.read(I8155::kTimerHigh, now);
        return static_cast<std::uint16_t>(lo | (hi << 8));
    }
    // Runs the chip the way the board's scheduler does: from event to event.
    void run_to(std::uint64_t t) {
        for (std::uint64_t e = chip.next_event(); e <= t; e = chip.next_event()) chip.advance(e);
        chip.advance(t);
    }
    I8155 chip;
    std::vector<Edge> edges;
};

TEST_F(I8155Test, ResetStateIsAllInputsTimerIdle) {
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 0), 0x00);
    chip.set_port_input(Port::A, 0x5A);
    chip.set_port_input(Port::B, 0xA5);
    chip.set_port_input(Port::C, 0x15);
    EXPECT_EQ(chip.read(I8155::kPortA, 1), 0x5A);
    EXPECT_EQ(chip.read(I8155::kPortB, 1), 0xA5);
    EXPECT_EQ(chip.read(I8155::kPortC, 1), 0xC0 | 0x15);  // ALT1: PC0-5 inputs, PC6-7 absent (1)
    EXPECT_EQ(chip.port_output_mask(Port::A), 0x00);
    EXPECT_TRUE(chip.timer_out());
    EXPECT_EQ(chip.next_event(), I8155::kNever);
}

TEST_F(I8155Test, RamIsSeparateFromIoAndSurvivesReset) {
    for (int a = 0; a < 256; ++a) chip.write_memory(static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(a ^ 0x5A));
    chip.write(I8155::kCommandStatus, 0x03, 1);  // I/O write does not touch RAM
    chip.reset(2);
    for (int a = 0; a < 256; ++a) EXPECT_EQ(chip.read_memory(static_cast<std::uint8_t>(a)), a ^ 0x5A);
}

TEST_F(I8155Test, OutputPortsReadBackTheirLatches) {
    std::vector<std::pair<Port, std::uint8_t>> writes;
    chip.on_port_write([&](Port p, std::uint8_t v, std::uint64_t) { writes.emplace_back(p, v); });
    chip.set_port_input(Port::A, 0x00);
    chip.write(I8155::kCommandStatus, 0x0F, 10);  // PA out, PB out, PC ALT2 (all output)
    chip.write(I8155::kPortA, 0x81, 11);
    chip.write(I8155::kPortB, 0x42, 12);
    chip.write(I8155::kPortC, 0xFF, 13);
    EXPECT_EQ(chip.read(I8155::kPortA, 14), 0x81);  // the latch, not the pins (0x00)
    EXPECT_EQ(chip.read(I8155::kPortB, 14), 0x42);
    EXPECT_EQ(chip.read(I8155::kPortC, 14), 0xFF);  // 6-bit latch 3FH, PC6-7 read 1
    EXPECT_EQ(chip.port_output(Port::A), 0x81);
    EXPECT_EQ(chip.port_output(Port::C), 0x3F);
    ASSERT_EQ(writes.size(), 3u);
    EXPECT_EQ(writes[0], std::make_pair(Port::A, std::uint8_t{0x81}));
    EXPECT_EQ(writes[2], std::make_pair(Port::C, std::uint8_t{0x3F}));
}

TEST_F(I8155Test, InputPortReadsPinsAndCallbackOverridesStoredLevels) {
    chip.write(I8155::kCommandStatus, 0x01, 0);  // PA out, PB in
    chip.set_input_callback([](Port p, std::uint64_t now) {
        return static_cast<std::uint8_t>(p == Port::B ? now & 0xFF : 0);
    });
    EXPECT_EQ(chip.read(I8155::kPortB, 0x37), 0x37);
}

TEST_F(I8155Test, PortCModesAlt1ToAlt4) {
    chip.set_port_input(Port::C, 0x2A);
    chip.write(I8155::kCommandStatus, 0x00, 0);  // ALT1: all input
    EXPECT_EQ(chip.port_c_mode(), I8155::PortCMode::Alt1);
    EXPECT_EQ(chip.port_output_mask(Port::C), 0x00);
    chip.write(I8155::kCommandStatus, 0x0C, 0);  // ALT2: all output
    EXPECT_EQ(chip.port_c_mode(), I8155::PortCMode::Alt2);
    EXPECT_EQ(chip.port_output_mask(Port::C), 0x3F);
    chip.write(I8155::kPortC, 0x38, 1);
    chip.write(I8155::kCommandStatus, 0x04, 2);  // ALT3: PC0-2 port A control, PC3-5 output
    EXPECT_EQ(chip.port_c_mode(), I8155::PortCMode::Alt3);
    EXPECT_EQ(chip.port_output_mask(Port::C), 0x3B);  // PC2 (A STB) is an input
    // PC0 A INTR = 0, PC1 A BF = 0, PC2 A STB = 1 (idle high), PC3-5 = latch 111.
    EXPECT_EQ(chip.read(I8155::kPortC, 3), 0xC0 | 0x38 | 0x04);
    chip.write(I8155::kCommandStatus, 0x08, 4);  // ALT4: PC0-2 A control, PC3-5 B control
    EXPECT_EQ(chip.port_c_mode(), I8155::PortCMode::Alt4);
    EXPECT_EQ(chip.port_output_mask(Port::C), 0x1B);
    EXPECT_EQ(chip.read(I8155::kPortC, 5), 0xC0 | 0x20 | 0x04);  // both STB idle high
}

TEST_F(I8155Test, Alt3DrivesPc3ToPc5FromTheLatch) {
    chip.write(I8155::kCommandStatus, 0x04, 0);  // ALT3
    chip.write(I8155::kPortC, 0x3F, 1);
    // PC3-5 follow the latch; PC0 (A INTR) and PC1 (A BF) are low; PC2 is the STB input.
    EXPECT_EQ(chip.port_output(Port::C), 0x38);
}

TEST_F(I8155Test, WritingAnInputPortLoadsItsLatchForLater) {
    chip.set_port_input(Port::A, 0x11);
    chip.write(I8155::kPortA, 0x77, 0);  // port A is an input: the pins are read...
    EXPECT_EQ(chip.read(I8155::kPortA, 1), 0x11);
    chip.write(I8155::kCommandStatus, 0x01, 2);  // ...until it becomes an output
    EXPECT_EQ(chip.read(I8155::kPortA, 3), 0x77);
    EXPECT_EQ(chip.port_output(Port::A), 0x77);
}

TEST_F(I8155Test, OneMillisecondTickAtTheBoardClock) {
    // 1 ms at 3.072 MHz = 3072 T-states = 0C00H: continuous square wave, TC every 3072 T.
    load_count(0x0C00, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 10);
    run_to(10 + 3 * 3072);
    const std::vector<Edge> expect{{false, 10 + 1536}, {true, 10 + 3072}, {false, 10 + 3072 + 1536},
                                   {true, 10 + 6144}, {false, 10 + 6144 + 1536}, {true, 10 + 9216}};
    EXPECT_EQ(edges, expect);
}

TEST_F(I8155Test, StrobedInputHandshakeOnPortA) {
    std::vector<std::pair<Port, bool>> intr;
    chip.on_intr([&](Port p, bool level, std::uint64_t) { intr.emplace_back(p, level); });
    chip.write(I8155::kCommandStatus, 0x14, 0);  // PA input, ALT3, INTE A
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 1), I8155::kStInteA);
    chip.set_port_input(Port::A, 0x3C);
    chip.set_stb(Port::A, false, 10);  // STB falling: data latched, BF set
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 11), I8155::kStInteA | I8155::kStBfA);
    chip.set_port_input(Port::A, 0x00);  // the pins change after the strobe
    chip.set_stb(Port::A, true, 12);     // STB rising: INTR
    EXPECT_TRUE(chip.intr(Port::A));
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 13), I8155::kStInteA | I8155::kStBfA | I8155::kStIntrA);
    EXPECT_EQ(chip.read(I8155::kPortC, 13) & 0x07, 0x01 | 0x02 | 0x04);  // INTR, BF, STB high
    EXPECT_EQ(chip.read(I8155::kPortA, 14), 0x3C);  // the latched byte; RD clears INTR and BF
    EXPECT_FALSE(chip.intr(Port::A));
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 15), I8155::kStInteA);
    ASSERT_EQ(intr.size(), 2u);
    EXPECT_EQ(intr[0], std::make_pair(Port::A, true));
    EXPECT_EQ(intr[1], std::make_pair(Port::A, false));
}

TEST_F(I8155Test, InterruptEnableGatesIntr) {
    chip.write(I8155::kCommandStatus, 0x04, 0);  // ALT3, INTE A off
    chip.set_stb(Port::A, false, 1);
    chip.set_stb(Port::A, true, 2);
    EXPECT_FALSE(chip.intr(Port::A));
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 3), I8155::kStBfA);
    chip.write(I8155::kCommandStatus, 0x14, 4);  // enabling INTE exposes the pending request
    EXPECT_TRUE(chip.intr(Port::A));
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 5), I8155::kStBfA | I8155::kStInteA | I8155::kStIntrA);
}

TEST_F(I8155Test, StrobedOutputHandshakeOnPortB) {
    chip.write(I8155::kCommandStatus, 0x2A, 0);  // PB output, ALT4, INTE B
    chip.write(I8155::kPortB, 0x99, 1);          // WR: INTR reset, BF set
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 2), I8155::kStInteB | I8155::kStBfB);
    EXPECT_EQ(chip.port_output(Port::C) & 0x18, 0x10);  // PC4 = B BF high, PC3 = B INTR low
    chip.set_stb(Port::B, false, 3);  // peripheral acknowledges: BF reset
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 4), I8155::kStInteB);
    chip.set_stb(Port::B, true, 5);  // STB rising: INTR (buffer empty, send more)
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 6), I8155::kStInteB | I8155::kStIntrB);
    EXPECT_EQ(chip.read(I8155::kPortC, 6) & 0x38, 0x08 | 0x20);  // B INTR, B STB high
    chip.write(I8155::kPortB, 0x11, 7);
    EXPECT_FALSE(chip.intr(Port::B));
}

TEST_F(I8155Test, StrobedInputOnPortBAndOutputOnPortA) {
    chip.write(I8155::kCommandStatus, 0x39, 0);  // PA out, PB in, ALT4, INTE A and B
    // Port B strobed input (PC5 = B STB).
    chip.set_port_input(Port::B, 0xC3);
    chip.set_stb(Port::B, false, 1);
    chip.set_stb(Port::B, true, 2);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 3),
              I8155::kStInteA | I8155::kStInteB | I8155::kStBfB | I8155::kStIntrB);
    EXPECT_EQ(chip.read(I8155::kPortB, 4), 0xC3);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 5), I8155::kStInteA | I8155::kStInteB);
    // Port A strobed output (PC2 = A STB).
    chip.write(I8155::kPortA, 0x5A, 6);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 7), I8155::kStInteA | I8155::kStInteB | I8155::kStBfA);
    chip.set_stb(Port::A, false, 8);
    chip.set_stb(Port::A, true, 9);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 10), I8155::kStInteA | I8155::kStInteB | I8155::kStIntrA);
    EXPECT_EQ(chip.port_output(Port::A), 0x5A);
}

TEST_F(I8155Test, NopTimerCommandLeavesTheCounterRunning) {
    load_count(10, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    chip.write(I8155::kCommandStatus, 0x01, 3);  // TM = 00: only the port bits change
    EXPECT_TRUE(chip.state().running);
    EXPECT_EQ(chip.next_event(), 5u);
}

TEST_F(I8155Test, ContinuousSquareWaveEvenCount) {
    // N = 10 started at T = 1000: high for N/2 = 5 clocks, low for 5, TC every 10 clocks.
    load_count(10, kContSquare, 990);
    chip.write(I8155::kCommandStatus, kStart, 1000);
    EXPECT_EQ(chip.next_event(), 1005u);
    run_to(1030);
    const std::vector<Edge> expect{{false, 1005}, {true, 1010}, {false, 1015}, {true, 1020}, {false, 1025}, {true, 1030}};
    EXPECT_EQ(edges, expect);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 1030) & I8155::kStTimer, I8155::kStTimer);
}

TEST_F(I8155Test, OddCountSquareWaveHasTheLargerHalfFirst) {
    // N = 9: high (9 + 1) / 2 = 5 clocks, low (9 - 1) / 2 = 4 clocks.
    load_count(9, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 100);
    run_to(118);
    const std::vector<Edge> expect{{false, 105}, {true, 109}, {false, 114}, {true, 118}};
    EXPECT_EQ(edges, expect);
}

TEST_F(I8155Test, MinimumCountTwoSquareWave) {
    load_count(2, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    run_to(4);
    const std::vector<Edge> expect{{false, 1}, {true, 2}, {false, 3}, {true, 4}};
    EXPECT_EQ(edges, expect);
}

TEST_F(I8155Test, SingleSquareWaveStopsAtTerminalCount) {
    load_count(6, kSingleSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 50);
    run_to(1000);
    const std::vector<Edge> expect{{false, 53}, {true, 56}};
    EXPECT_EQ(edges, expect);
    EXPECT_EQ(chip.next_event(), I8155::kNever);
    EXPECT_FALSE(chip.state().running);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 1000), I8155::kStTimer);
}

TEST_F(I8155Test, SinglePulseIsOneClockLowAtTerminalCount) {
    load_count(4, kSinglePulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 20);
    EXPECT_EQ(chip.next_event(), 24u);  // TC after 4 TIMER IN pulses
    run_to(100);
    const std::vector<Edge> expect{{false, 24}, {true, 25}};
    EXPECT_EQ(edges, expect);
    EXPECT_EQ(chip.next_event(), I8155::kNever);
}

TEST_F(I8155Test, ContinuousPulsesEveryCount) {
    load_count(5, kContPulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    run_to(15);
    const std::vector<Edge> expect{{false, 5}, {true, 6}, {false, 10}, {true, 11}, {false, 15}};
    EXPECT_EQ(edges, expect);
}

TEST_F(I8155Test, TimerFlagLatchesUntilStatusRead) {
    load_count(100, kContPulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 99) & I8155::kStTimer, 0);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 100) & I8155::kStTimer, I8155::kStTimer);  // TC at 100
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 101) & I8155::kStTimer, 0);  // cleared by the read
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 350) & I8155::kStTimer, I8155::kStTimer);  // TCs 200, 300
}

TEST_F(I8155Test, CountAndModeReadWhileRunning) {
    // Pulse mode counts down by one: N = 100 started at 0, read at T = 30 -> 70, mode 11.
    load_count(100, kContPulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    EXPECT_EQ(read_count(30), 0xC000 | 70);
    // Square wave counts down by two; bit 0 = 1 in the first half. N = 10, 2 clocks in:
    // 3 clocks left of the 5-clock first half -> (3 << 1) | 1 = 7; the data sheet's recipe
    // (7 >> 1 = 3, carry set so add N/2 = 5) gives the 8 clocks left of the count.
    load_count(10, kContSquare, 100);
    chip.write(I8155::kCommandStatus, kStop, 100);
    chip.write(I8155::kCommandStatus, kStart, 200);
    EXPECT_EQ(read_count(202), 0x4000 | 7);
    // Second half, 7 clocks in: 3 clocks left, bit 0 = 0 -> 6.
    EXPECT_EQ(read_count(207), 0x4000 | 6);
}

TEST_F(I8155Test, CountRegisterReadsAsWrittenBeforeTheFirstStart) {
    load_count(0x1234, kSinglePulse, 0);
    EXPECT_EQ(read_count(1), 0x9234);
}

TEST_F(I8155Test, StopFreezesTheCounter) {
    load_count(100, kSinglePulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    chip.write(I8155::kCommandStatus, kStop, 40);
    EXPECT_EQ(read_count(1000), 0x8000 | 60);
    EXPECT_EQ(chip.next_event(), I8155::kNever);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 1000) & I8155::kStTimer, 0);
}

TEST_F(I8155Test, StopWhenIdleIsANop) {
    chip.write(I8155::kCommandStatus, kStop, 0);
    chip.write(I8155::kCommandStatus, kStopAfterTc, 0);
    EXPECT_FALSE(chip.state().running);
    EXPECT_EQ(chip.next_event(), I8155::kNever);
}

TEST_F(I8155Test, StopAfterTcEndsAContinuousMode) {
    load_count(10, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    chip.write(I8155::kCommandStatus, kStopAfterTc, 12);  // during the second period
    run_to(100);
    const std::vector<Edge> expect{{false, 5}, {true, 10}, {false, 15}, {true, 20}};
    EXPECT_EQ(edges, expect);
    EXPECT_FALSE(chip.state().running);
}

TEST_F(I8155Test, StartWhileRunningTakesEffectAtTerminalCount) {
    load_count(10, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    load_count(4, kContPulse, 3);  // a new count and mode, loaded while counting...
    EXPECT_EQ(read_count(3), 0x4000 | ((2 << 1) | 1));  // ...do not change the running count
    chip.write(I8155::kCommandStatus, kStart, 3);  // ...until the present TC (T = 10)
    run_to(18);
    // Square wave to TC at 10, then pulses at 10 + 4 = 14 and 18.
    const std::vector<Edge> expect{{false, 5}, {true, 10}, {false, 14}, {true, 15}, {false, 18}};
    EXPECT_EQ(edges, expect);
}

TEST_F(I8155Test, StartClearsTheTimerFlag) {
    load_count(4, kContPulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    chip.advance(9);  // TCs at 4 and 8 latched the flag
    EXPECT_EQ(chip.peek_status() & I8155::kStTimer, I8155::kStTimer);
    chip.write(I8155::kCommandStatus, kStart, 9);  // "starting a new count" resets it
    EXPECT_EQ(chip.peek_status() & I8155::kStTimer, 0);
}

TEST_F(I8155Test, StartReloadsTheCountLengthAfterStop) {
    load_count(50, kContPulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    chip.write(I8155::kCommandStatus, kStop, 20);
    chip.write(I8155::kCommandStatus, kStart, 100);  // reload: the next TC is 50 clocks later
    EXPECT_EQ(chip.next_event(), 150u);
}

TEST_F(I8155Test, LongCatchUpWithoutListenerIsExact) {
    I8155 quiet;
    quiet.reset(0);
    quiet.write(I8155::kTimerLow, 10, 0);
    quiet.write(I8155::kTimerHigh, kContSquare, 0);
    quiet.write(I8155::kCommandStatus, kStart, 0);
    // 10^12 + 3 T-states: 10^11 whole periods, then 3 clocks into the high half:
    // 2 clocks left of it -> (2 << 1) | 1 = 5; TIMER OUT high; TIMER flag set.
    const std::uint64_t t = 1'000'000'000'003ull;
    quiet.advance(t);
    EXPECT_TRUE(quiet.timer_out());
    EXPECT_EQ(quiet.peek_counter(t), 0x4000 | 5);
    EXPECT_EQ(quiet.next_event(), t + 2);  // falls at 10^12 + 5
    EXPECT_EQ(quiet.read(I8155::kCommandStatus, t), I8155::kStTimer);
}

TEST_F(I8155Test, ResetStopsTheTimerAndClearsTheCommand) {
    load_count(10, kContSquare, 0);
    chip.write(I8155::kCommandStatus, 0xFF & ~0x0C, 0);  // START, ports out, INTE A/B
    run_to(7);                                           // TIMER OUT low
    chip.reset(8);
    EXPECT_TRUE(chip.timer_out());
    EXPECT_EQ(chip.next_event(), I8155::kNever);
    EXPECT_EQ(chip.read(I8155::kCommandStatus, 9), 0x00);
    EXPECT_EQ(chip.port_output_mask(Port::A), 0x00);
    EXPECT_EQ(read_count(9), 0x4000 | 10);  // the count length register is kept
}

TEST_F(I8155Test, SnapshotRoundTripContinuesIdentically) {
    load_count(7, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart | 0x01, 0);
    chip.write(I8155::kPortA, 0xA7, 1);
    chip.write_memory(0x20, 0x55);
    run_to(9);
    std::vector<std::uint8_t> blob;
    chip.save(blob);
    I8155 copy;
    copy.load(blob);
    std::vector<Edge> copy_edges;
    copy.on_timer_out([&](bool level, std::uint64_t at) { copy_edges.push_back({level, at}); });
    edges.clear();
    run_to(30);
    for (std::uint64_t e = copy.next_event(); e <= 30; e = copy.next_event()) copy.advance(e);
    EXPECT_EQ(copy_edges, edges);
    EXPECT_EQ(copy.read_memory(0x20), 0x55);
    EXPECT_EQ(copy.port_output(Port::A), 0xA7);
}

TEST_F(I8155Test, LoadRejectsBadSnapshots) {
    std::vector<std::uint8_t> blob;
    chip.save(blob);
    I8155 other;
    std::vector<std::uint8_t> truncated(blob.begin(), blob.end() - 1);
    EXPECT_THROW(other.load(truncated), alp85::SnapshotError);
    std::vector<std::uint8_t> wrong = blob;
    wrong[0] = 'X';
    EXPECT_THROW(other.load(wrong), alp85::SnapshotError);
    std::vector<std::uint8_t> extra = blob;
    extra.push_back(0);
    EXPECT_THROW(other.load(extra), alp85::SnapshotError);
}

TEST_F(I8155Test, LoadRejectsATimerPeriodInTheFuture) {
    load_count(7, kContSquare, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    run_to(9);
    std::vector<std::uint8_t> blob;
    chip.save(blob);
    I8155 ok;
    ASSERT_NO_THROW(ok.load(blob));
    // The state ends with period_start (u64), pending_start, stop_after_tc, held_value (u16),
    // timer_out, pulse_end (u64) and now (u64): period_start is 29 bytes from the end.
    const std::size_t at = blob.size() - 29;
    EXPECT_EQ(blob[at], 7);  // the second period started at 7 (count 7)
    blob[at] = 200;          // a period starting after `now` (9)
    I8155 other;
    EXPECT_THROW(other.load(blob), alp85::SnapshotError);
}

}  // namespace

namespace alp85::periph {
namespace {

// Issue #11, 9 (docs/peripherals.md, "Read-back in the pulse modes"): the same count N = 10, two
// TIMER IN pulses in, read back in both kinds of mode. Both say 8 pulses remain: the pulse modes
// as the number itself, the square-wave modes encoded (3 pulses left of the 5-pulse first half,
// bit 0 set: (3 << 1) | 1 = 7; the data sheet's recipe: 7 >> 1 = 3, carry set, + 10 / 2 = 8).
TEST_F(I8155Test, PulseModeReadBackIsTheRemainingCountNotTheSquareWaveEncoding) {
    const auto recipe = [](std::uint16_t v, unsigned n) { return (v & 0x3FFFu) / 2u + ((v & 1u) ? n / 2u : 0u); };
    load_count(10, kContPulse, 0);
    chip.write(I8155::kCommandStatus, kStart, 0);
    const std::uint16_t pulse = read_count(2);
    EXPECT_EQ(pulse, 0xC000 | 8);
    chip.write(I8155::kCommandStatus, kStop, 5);
    load_count(10, kContSquare, 100);
    chip.write(I8155::kCommandStatus, kStart, 100);
    const std::uint16_t square = read_count(102);
    EXPECT_EQ(square, 0x4000 | 7);
    EXPECT_EQ(recipe(square, 10), 8u);
    EXPECT_EQ(pulse & 0x3FFF, 8);  // not 7: the pulse modes count by ones here
}

}  // namespace
}  // namespace alp85::periph
