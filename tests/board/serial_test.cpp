// The serial terminal on the ALP 85's SID and SOD (Machine::connect_serial), and the bit-banged
// echo program firmware/demo/echo85.asm on it. Expected times are hand calculations: a bit is
// 3 072 000 / baud T-states, and the program's bits are 24·n + 80 T-states (its header).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "board_programs.h"

namespace alp85::test {
namespace {

periph::UartFormat rate(std::uint32_t baud) {
    periph::UartFormat f;
    f.baud = baud;
    return f;
}

// Every change of SOD with its T-state, as a logic analyzer sees it.
class SodProbe final : public PinProbe {
public:
    explicit SodProbe(const Machine& m) : m_(m), level_(m.cpu().sod()) {}
    void look(std::uint64_t t) override {
        if (m_.cpu().sod() == level_) return;
        level_ = m_.cpu().sod();
        edges.push_back(t);
    }
    std::uint64_t next() const override { return periph::Part::kNever; }
    std::vector<std::uint64_t> edges;

private:
    const Machine& m_;
    bool level_;
};

TEST(SerialLine, SidFollowsTheTerminalAtEachBit) {
    Machine m;
    const std::vector<std::uint8_t> loop{0xC3, 0x00, 0x00};  // 0000H: JMP 0000H, 10 T-states
    m.load(0x0000, loop);
    m.reset();
    periph::SerialTerminal term(board::kCpuHz, rate(9600), 0);
    m.connect_serial(term);
    EXPECT_TRUE(m.cpu().sid());  // the idle line: mark
    m.serial_at('A', 0);         // 41H: start bit from 0, d0 = 1 from 320, d1 = 0 from 640
    m.run_until(310);            // instruction boundaries every 10 T-states: ends at 310
    EXPECT_FALSE(m.cpu().sid());
    m.run_until(320);
    EXPECT_TRUE(m.cpu().sid());
    m.run_until(630);
    EXPECT_TRUE(m.cpu().sid());
    m.run_until(640);
    EXPECT_FALSE(m.cpu().sid());
    m.run_until(9 * 320);  // the stop bit
    EXPECT_TRUE(m.cpu().sid());
    ASSERT_FALSE(m.input_log().empty());
    EXPECT_EQ(m.input_log().back().kind, InputKind::Serial);  // the debugger replays it
}

TEST(SerialLine, NoTerminalNoSid) {
    Machine m;
    m.serial_at('A', 0);  // ignored: nothing on SID
    m.run_until(1000);
    EXPECT_FALSE(m.cpu().sid());
}

// A snapshot taken before the characters were typed, restored on a second board with its own
// terminal, and the first board's input log from then on replayed: the same echo at the same
// T-states (what the debugger's reverse execution relies on).
TEST(SerialLine, TypedCharactersReplayFromTheInputLog) {
    const auto setup = [](Machine& m, periph::SerialTerminal& term) {
        load_image(m, std::string(ALP85_SOURCE_DIR) + "/firmware/demo/echo85.asm");
        m.reset();
        m.cpu().regs().pc = 0x0800;  // 9600 baud
        m.connect_serial(term);
    };
    const periph::UartFormat f = rate(9600);
    Machine a, b;
    periph::SerialTerminal ta(board::kCpuHz, f, f.frame_tstates(board::kCpuHz)), tb(board::kCpuHz, f, f.frame_tstates(board::kCpuHz));
    setup(a, ta);
    setup(b, tb);
    a.run_until(1000);
    const auto snapshot = a.snapshot_bytes();
    const std::size_t logged = a.input_log().size();
    for (char c : std::string("ok")) a.serial_at(static_cast<std::uint8_t>(c), a.now());
    std::vector<std::uint64_t> at_a, at_b;
    ta.on_receive([&](const periph::UartChar& c) { at_a.push_back(c.at); });
    tb.on_receive([&](const periph::UartChar& c) { at_b.push_back(c.at); });
    a.run_until(40000);  // two frames, a gap, the echo: under 4 frames and 2 gaps (25 600)
    ASSERT_EQ(std::string(ta.text().begin(), ta.text().end()), "ok");
    b.restore_bytes(snapshot);
    b.replay({a.input_log().begin() + static_cast<std::ptrdiff_t>(logged), a.input_log().end()});
    b.run_until(40000);
    EXPECT_EQ(std::string(tb.text().begin(), tb.text().end()), "ok");
    EXPECT_EQ(at_b, at_a);
}

struct Rate {
    std::uint32_t baud;
    std::uint16_t entry;      // where GO starts echo85 at this rate
    std::uint64_t bit;        // its bit time: 24·n + 80
};

class EchoProgram : public ::testing::TestWithParam<Rate> {};

TEST_P(EchoProgram, EchoesWhatItReceivesWithItsBitTime) {
    const Rate r = GetParam();
    Machine m;
    load_image(m, std::string(ALP85_SOURCE_DIR) + "/firmware/demo/echo85.asm");
    m.reset();
    m.cpu().regs().pc = r.entry;
    periph::SerialTerminal term(board::kCpuHz, rate(r.baud), rate(r.baud).frame_tstates(board::kCpuHz));
    m.connect_serial(term);
    SodProbe probe(m);
    m.add_probe(&probe);
    m.run_until(1000);  // the program sets SOD to mark and listens
    ASSERT_EQ(probe.edges.size(), 1u);
    probe.edges.clear();
    const std::string text = "U5";  // 55H and 35H
    for (char c : text) m.serial_at(static_cast<std::uint8_t>(c), m.now());
    // Two frames, the gap and the last echo: under 4 frames and 2 gaps; then a little more.
    m.run_until(m.now() + 6 * rate(r.baud).frame_tstates(board::kCpuHz));
    EXPECT_EQ(std::string(term.text().begin(), term.text().end()), text);
    EXPECT_EQ(term.errors(), 0u);
    // 'U' = 55H alternates: its echo changes SOD at each of its 10 bit boundaries, one bit time
    // apart (start bit, d0..d7, stop bit).
    ASSERT_GE(probe.edges.size(), 10u);
    for (std::size_t i = 1; i < 10; ++i) EXPECT_EQ(probe.edges[i] - probe.edges[i - 1], r.bit) << i;
}

// n = 10, 103, 1160: 24·10 + 80 = 320, 24·103 + 80 = 2552, 24·1160 + 80 = 27920.
INSTANTIATE_TEST_SUITE_P(Rates, EchoProgram,
                         ::testing::Values(Rate{9600, 0x0800, 320}, Rate{1200, 0x0810, 2552}, Rate{110, 0x0820, 27920}),
                         [](const auto& info) { return "baud" + std::to_string(info.param.baud); });

}  // namespace
}  // namespace alp85::test
