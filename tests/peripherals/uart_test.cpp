// The UART framing of the serial line on SID/SOD (peripherals/uart.h) and the terminal part.
// Expected times are hand calculations at the ALP 85's 3.072 MHz: a bit is 3 072 000 / baud
// T-states (9600: 320, 1200: 2560, 110: 27 927.27), bit k of a frame starts at
// floor(k * 3 072 000 / baud) after the start edge and is sampled at floor((2k + 1) * 3 072 000 /
// (2 * baud)).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "peripherals/serial_terminal.h"
#include "peripherals/uart.h"

namespace alp85::periph {
namespace {

constexpr std::uint64_t kClock = 3'072'000;
using Edges = std::vector<std::pair<bool, std::uint64_t>>;

UartFormat format(std::string_view text) {
    std::string why;
    const auto f = parse_uart_format(text, why);
    EXPECT_TRUE(f) << why;
    return f.value_or(UartFormat{});
}

Edges transmit(UartTransmitter& tx, std::uint64_t until) {
    Edges edges;
    tx.advance(until, [&](bool level, std::uint64_t t) { edges.emplace_back(level, t); });
    return edges;
}

std::vector<UartChar> receive(UartReceiver& rx, const Edges& edges, std::uint64_t until) {
    std::vector<UartChar> got;
    const auto sink = [&](const UartChar& c) { got.push_back(c); };
    for (const auto& [level, t] : edges) rx.edge(level, t, sink);
    rx.advance(until, sink);
    return got;
}

TEST(UartFormat, ParsesBaudAndFrame) {
    const UartFormat a = format("9600");
    EXPECT_EQ(a.baud, 9600u);
    EXPECT_EQ(a.data_bits, 8);
    EXPECT_EQ(a.parity, Parity::None);
    EXPECT_EQ(a.stop_bits, 1);
    EXPECT_EQ(a.text(), "9600,8N1");
    const UartFormat b = format("110,7e2");
    EXPECT_EQ(b.baud, 110u);
    EXPECT_EQ(b.data_bits, 7);
    EXPECT_EQ(b.parity, Parity::Even);
    EXPECT_EQ(b.stop_bits, 2);
    EXPECT_EQ(format("1200,5O1").parity, Parity::Odd);
}

TEST(UartFormat, RefusesBadRatesAndFrames) {
    for (const char* bad : {"", "0", "49", "115201", "9600x", "-9600", "96 00", ",8N1", "9600,", "9600,9N1", "9600,4N1",
                            "9600,8X1", "9600,8N3", "9600,8N1,", "9600,8N10"}) {
        std::string why;
        EXPECT_FALSE(parse_uart_format(bad, why)) << bad;
        EXPECT_FALSE(why.empty()) << bad;
    }
    std::string why;
    parse_uart_format("9600,8X1", why);
    EXPECT_EQ(why, "bad frame '8X1' (data bits 5-8, parity N, E or O, stop bits 1 or 2, e.g. 8N1 or 7E1)");
    parse_uart_format("96k", why);
    EXPECT_EQ(why, "bad baud rate '96k' (a whole number from 50 to 115200, e.g. 9600)");
}

TEST(UartFormat, FrameTimes) {
    // 8N1: start + 8 + stop = 10 bits; 9600 baud: 10 * 320 = 3200 T-states.
    EXPECT_EQ(format("9600").frame_tstates(kClock), 3200u);
    // 1200 7E2: 1 + 7 + 1 + 2 = 11 bits, 11 * 2560 = 28160.
    EXPECT_EQ(format("1200,7E2").frame_tstates(kClock), 28160u);
    // 110 8N1: 10 * 27 927.27 = 279 272.7, whole T-states: 279 272.
    EXPECT_EQ(format("110").frame_tstates(kClock), 279272u);
}

TEST(UartFormat, ParityCountsTheDataBitsOnes) {
    const UartFormat even = format("9600,7E1"), odd = format("9600,7O1");
    EXPECT_FALSE(even.parity_bit('A'));  // 41H = 100 0001: two ones, already even
    EXPECT_TRUE(even.parity_bit('C'));   // 43H = 100 0011: three ones
    EXPECT_TRUE(odd.parity_bit('A'));
    EXPECT_FALSE(odd.parity_bit('C'));
    EXPECT_FALSE(even.parity_bit(0xC1));  // 7 data bits: bit 7 is not sent, 41H's two ones count
}

TEST(UartTransmitter, SendsAFrameAt9600) {
    UartTransmitter tx(kClock, format("9600"), 0);
    tx.send('A', 1000);  // 41H: d0 = 1, d6 = 1, the others 0
    EXPECT_EQ(tx.next_event(), 1000u);
    const Edges want{{false, 1000},           // start bit
                     {true, 1000 + 320},      // d0
                     {false, 1000 + 2 * 320}, // d1 (d2-d5 stay 0)
                     {true, 1000 + 7 * 320},  // d6
                     {false, 1000 + 8 * 320}, // d7
                     {true, 1000 + 9 * 320}}; // stop bit
    EXPECT_EQ(transmit(tx, 1000 + 10 * 320), want);
    EXPECT_FALSE(tx.busy());
    EXPECT_TRUE(tx.level());
}

TEST(UartTransmitter, KeepsTheAverageAt110Baud) {
    // 55H alternates: a change at every boundary, k * 3 072 000 / 110 rounded down.
    UartTransmitter tx(kClock, format("110"), 0);
    tx.send(0x55, 0);
    const Edges want{{false, 0},      {true, 27927},   {false, 55854},  {true, 83781},  {false, 111709},
                     {true, 139636},  {false, 167563}, {true, 195490},  {false, 223418}, {true, 251345}};
    EXPECT_EQ(transmit(tx, 279272), want);
}

TEST(UartTransmitter, ParityAndTwoStopBits) {
    // 7E2, 'C' (43H = 100 0011, three ones: parity 1): start, 1 1 0 0 0 0 1, parity 1, stop stop.
    UartTransmitter tx(kClock, format("1200,7E2"), 0);
    tx.send('C', 0);
    const Edges want{{false, 0}, {true, 2560}, {false, 3 * 2560}, {true, 7 * 2560}};
    EXPECT_EQ(transmit(tx, 11 * 2560), want);
    EXPECT_FALSE(tx.busy());
}

TEST(UartTransmitter, LeavesTheGapBetweenCharacters) {
    // Two characters typed at once, a gap of one frame (3200): the second starts at 3200 + 3200.
    UartTransmitter tx(kClock, format("9600"), 3200);
    tx.send(0xFF, 0);  // start bit only: 0 at 0, 1 at 320
    tx.send(0xFF, 0);
    const Edges want{{false, 0}, {true, 320}, {false, 6400}, {true, 6720}};
    EXPECT_EQ(transmit(tx, 20000), want);
    // A third typed long after the gap starts when typed.
    tx.send(0xFF, 50000);
    EXPECT_EQ(tx.next_event(), 50000u);
}

TEST(UartReceiver, SamplesInTheMiddleOfEachBit) {
    // 'A' from a start edge at 1000; the stop bit (k = 9) is sampled at 1000 + 19 * 160 = 4040.
    UartReceiver rx(kClock, format("9600"));
    const Edges line{{false, 1000}, {true, 1320}, {false, 1640}, {true, 3240}, {false, 3560}, {true, 3880}};
    const auto got = receive(rx, line, 5000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].value, 'A');
    EXPECT_EQ(got[0].at, 4040u);
    EXPECT_EQ(got[0].error, UartChar::Error::None);
}

TEST(UartReceiver, TakesNothingBeforeTheStopBitsMiddle) {
    UartReceiver rx(kClock, format("9600"));
    const Edges line{{false, 1000}, {true, 1320}, {false, 1640}, {true, 3240}, {false, 3560}, {true, 3880}};
    EXPECT_TRUE(receive(rx, line, 4040).empty());  // samples before 4040 only
    std::vector<UartChar> got;
    rx.advance(4041, [&](const UartChar& c) { got.push_back(c); });
    EXPECT_EQ(got.size(), 1u);
}

TEST(UartReceiver, ASampleAtAnEdgeSeesTheNewLevel) {
    // Start at 0; d0's middle is at 480. A rise exactly there makes d0 = 1; one T-state later, 0.
    for (const auto& [rise, want] : {std::pair<std::uint64_t, std::uint8_t>{480, 0xFF}, {481, 0xFE}}) {
        UartReceiver rx(kClock, format("9600"));
        const auto got = receive(rx, {{false, 0}, {true, rise}}, 4000);
        ASSERT_EQ(got.size(), 1u);
        EXPECT_EQ(got[0].value, want) << rise;
    }
}

TEST(UartReceiver, AShortPulseIsAGlitch) {
    // Low for 100 T-states (less than the 160 to the start bit's middle): nothing; a frame after it
    // is taken.
    UartReceiver rx(kClock, format("9600"));
    const auto got = receive(rx, {{false, 0}, {true, 100}, {false, 1000}, {true, 1320}}, 5000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].value, 0xFF);  // d0..d7 all 1 after 1320
    EXPECT_EQ(got[0].at, 1000u + 19 * 160);
}

TEST(UartReceiver, ReportsFramingErrorsAndBreaks) {
    UartReceiver rx(kClock, format("9600"));
    // The line falls at 0 and stays at space: a break, taken at the stop bit's middle (3040).
    auto got = receive(rx, {{false, 0}}, 10000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].error, UartChar::Error::Framing);
    EXPECT_TRUE(got[0].is_break());
    EXPECT_EQ(got[0].at, 3040u);
    // Still at space: no new frame until the line rises and falls again.
    rx.advance(100000, [&](const UartChar& c) { got.push_back(c); });
    EXPECT_EQ(got.size(), 1u);
    // 80H sent, but the line rises only at 9.75 bits (3120), after the stop bit's middle.
    UartReceiver rx2(kClock, format("9600"));
    got = receive(rx2, {{false, 0}, {true, 8 * 320}, {false, 9 * 320}, {true, 3120}}, 10000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].error, UartChar::Error::Framing);
    EXPECT_EQ(got[0].value, 0x80);
    EXPECT_FALSE(got[0].is_break());
}

TEST(UartReceiver, ChecksParity) {
    // 7E1 'C': 1 1 0 0 0 0 1, parity 1 (three ones). Sent with parity 0 instead: a parity error.
    const UartFormat f = format("1200,7E1");
    UartReceiver good(kClock, f), bad(kClock, f);
    const Edges right{{false, 0}, {true, 2560}, {false, 3 * 2560}, {true, 7 * 2560}};
    const Edges wrong{{false, 0}, {true, 2560}, {false, 3 * 2560}, {true, 7 * 2560}, {false, 8 * 2560}, {true, 9 * 2560}};
    auto got = receive(good, right, 30000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].value, 'C');
    EXPECT_EQ(got[0].error, UartChar::Error::None);
    got = receive(bad, wrong, 30000);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].value, 'C');
    EXPECT_EQ(got[0].error, UartChar::Error::Parity);
}

TEST(Uart, EveryCharacterRoundTripsAtEveryFrame) {
    for (const char* text : {"110", "1200,7E2", "9600,8O1", "9600,5N2", "115200"}) {
        const UartFormat f = format(text);
        UartTransmitter tx(kClock, f, 0);
        UartReceiver rx(kClock, f);
        const unsigned values = 1u << f.data_bits;
        for (unsigned v = 0; v < values; ++v) tx.send(static_cast<std::uint8_t>(v), 0);
        std::vector<UartChar> got;
        const auto sink = [&](const UartChar& c) { got.push_back(c); };
        tx.advance(values * f.frame_tstates(kClock) + 1, [&](bool level, std::uint64_t t) { rx.edge(level, t, sink); });
        rx.advance(values * f.frame_tstates(kClock) + 1, sink);
        ASSERT_EQ(got.size(), values) << text;
        for (unsigned v = 0; v < values; ++v) {
            EXPECT_EQ(got[v].value, v) << text;
            EXPECT_EQ(got[v].error, UartChar::Error::None) << text;
        }
    }
}

TEST(SerialTerminal, SnapshotInTheMiddleOfAFrameGoesOnTheSame) {
    SerialTerminal a(kClock, format("1200"), 0);
    Edges ea, eb;
    a.on_txd([&](bool level, std::uint64_t t) { ea.emplace_back(level, t); });
    a.type('Z', 0);
    a.type('!', 0);
    a.sod(false, 100);  // a frame coming in from SOD too: start at 100, then 0FFH
    a.sod(true, 100 + 2560);
    a.advance(5 * 2560);
    std::vector<std::uint8_t> state;
    a.save(state);
    SerialTerminal b(kClock, format("1200"), 0);
    b.load(state);
    b.on_txd([&](bool level, std::uint64_t t) { eb.emplace_back(level, t); });
    std::vector<UartChar> from_a, from_b;
    a.on_receive([&](const UartChar& c) { from_a.push_back(c); });
    b.on_receive([&](const UartChar& c) { from_b.push_back(c); });
    const std::size_t before = ea.size();
    a.advance(30 * 2560);
    b.advance(30 * 2560);
    EXPECT_EQ(Edges(ea.begin() + static_cast<std::ptrdiff_t>(before), ea.end()), eb);
    ASSERT_EQ(from_b.size(), 1u);
    EXPECT_EQ(from_b[0].value, 0xFF);
    EXPECT_EQ(from_a.size(), 1u);
    EXPECT_EQ(b.text(), std::vector<std::uint8_t>{0xFF});
}

TEST(SerialTerminal, RefusesAFrameBeyondItsBits) {
    SerialTerminal a(kClock, format("9600"), 0);
    a.type('x', 0);
    a.advance(5 * 320);
    std::vector<std::uint8_t> state;
    a.save(state);
    // The transmitter's bit index: after the header (3), the queue (4-byte length + 1), head (4),
    // sending (1) and start (8).
    state[3 + 5 + 4 + 1 + 8] = 99;
    SerialTerminal b(kClock, format("9600"), 0);
    EXPECT_THROW(b.load(state), SnapshotError);
    EXPECT_TRUE(b.text().empty());
}

}  // namespace
}  // namespace alp85::periph
