// The Signals pane's trace (emu/debug/signal_trace.h) and the probes it shares with `record
// signals` (emu/debug/pin_tap.h). The program is poked in by hand; its T-states are counted from the
// Intel 8085AH data sheet's instruction table: MVI r 7, OUT 10 (opcode fetch 4, memory read 3, I/O
// write 3: the port changes at the first T-state of the write cycle, 7 after the OUT begins), JMP 10,
// LXI 10.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "emu/debug/signal_record.h"
#include "emu/debug/signal_trace.h"

namespace alp85::test {
namespace {

using debug::SignalTrace;

constexpr std::uint16_t kOrg = 0x0800;

// 0800 LXI SP,2000H        10 T
// 0803 MVI A,01H            7    8155 command: port A output
// 0805 OUT 0F8H            10    PA0 goes from z (input after RESET) to 0, at 17 + 7 = 24
// 0807 MVI A,01H            7    LOOP
// 0809 OUT 0F9H            10    PA0 rises at 27 + 7 = 34 + 7 = 41
// 080B MVI A,00H            7
// 080D OUT 0F9H            10    PA0 falls at 44 + 7 + 7 = 58: high 10 + 7 = 17 T
// 080F JMP 0807H           10    the next rise at 61 + 10 + 7 + 7 = 85: low 10 + 10 + 7 = 27 T
const std::vector<std::uint8_t> kPulses = {0x31, 0x00, 0x20, 0x3E, 0x01, 0xD3, 0xF8, 0x3E, 0x01, 0xD3,
                                           0xF9, 0x3E, 0x00, 0xD3, 0xF9, 0xC3, 0x07, 0x08};
constexpr std::uint64_t kHigh = 17, kLow = 27, kFirstEdge = 24, kFirstRise = 41;

struct Rig {
    Machine m{[] {
        Machine::Options o;
        o.machine_tool = false;
        return o;
    }()};
    std::uint64_t t0 = 0;
    Rig() {
        m.load(kOrg, kPulses);
        m.reset();
        m.cpu().regs().pc = kOrg;
        t0 = m.now();
    }
    void run_to(std::uint64_t t) { m.run_until(t); }
};

TEST(SignalTrace, PortAPulsesAreTheProgramsHandCount) {
    Rig r;
    SignalTrace tr;
    tr.start(r.m, {"PA0"}, 100'000);
    ASSERT_EQ(tr.traces().size(), 1u);
    EXPECT_EQ(tr.traces()[0].pin.scope, "8155");
    EXPECT_EQ(tr.traces()[0].pin.name, "PA0");
    EXPECT_EQ(tr.traces()[0].level_before, 'z');
    r.run_to(r.t0 + 2000);
    const auto& e = tr.traces()[0].edges;
    ASSERT_GE(e.size(), 40u);
    EXPECT_EQ(e[0].t, r.t0 + kFirstEdge);
    EXPECT_EQ(e[0].level, '0');
    EXPECT_EQ(e[1].t, r.t0 + kFirstRise);
    for (std::size_t i = 1; i + 1 < e.size(); ++i) {
        EXPECT_EQ(e[i].level, i % 2 ? '1' : '0') << i;
        EXPECT_EQ(e[i + 1].t - e[i].t, e[i].level == '1' ? kHigh : kLow) << i;
    }
    // Levels between the edges, and the edge nearest a time.
    EXPECT_EQ(tr.level_at(0, r.t0), 'z');
    EXPECT_EQ(tr.level_at(0, r.t0 + kFirstRise - 1), '0');
    EXPECT_EQ(tr.level_at(0, r.t0 + kFirstRise), '1');
    EXPECT_EQ(tr.level_at(0, r.t0 + kFirstRise + kHigh), '0');
    EXPECT_EQ(tr.edge_near(0, r.t0 + kFirstRise + 3, 5), r.t0 + kFirstRise);
    EXPECT_EQ(tr.edge_near(0, r.t0 + kFirstRise + kHigh - 2, 5), r.t0 + kFirstRise + kHigh);
    EXPECT_FALSE(tr.edge_near(0, r.t0 + kFirstRise + 8, 5));  // 8 after the rise, 9 before the fall
}

TEST(SignalTrace, KeepsOnlyItsSpan) {
    Rig r;
    SignalTrace all, tr;
    all.start(r.m, {"PA0"}, 100'000);
    tr.start(r.m, {"8155.PA0"}, 440);  // ten periods of 44 T
    r.run_to(r.t0 + 5000);
    const auto kept_of = [&](std::uint64_t span) {
        std::size_t n = 0;
        for (const auto& e : all.traces()[0].edges) n += e.t + span >= all.latest();
        return n;
    };
    const auto& t = tr.traces()[0];
    ASSERT_FALSE(t.edges.empty());
    EXPECT_EQ(tr.latest(), all.latest());
    EXPECT_EQ(t.edges.size(), kept_of(440));
    EXPECT_GE(t.edges.size(), 20u);  // two edges a period
    EXPECT_LE(t.edges.size(), 21u);
    EXPECT_EQ(t.edges.front().t, all.traces()[0].edges[all.traces()[0].edges.size() - t.edges.size()].t);
    // the level before the first edge kept is the one the edge before it left
    EXPECT_NE(t.level_before, t.edges.front().level);
    tr.set_span(88);
    EXPECT_EQ(tr.traces()[0].edges.size(), kept_of(88));
    EXPECT_GE(tr.traces()[0].edges.size(), 4u);
}

TEST(SignalTrace, StandsStillWhileTheMachineStandsAndForgetsATimelineTakenBack) {
    Rig r;
    SignalTrace tr;
    tr.start(r.m, {"PA0"}, 100'000);
    r.run_to(r.t0 + 1000);
    const std::vector<std::uint8_t> snap = r.m.snapshot_bytes();
    const std::uint64_t t1 = r.m.now();
    r.run_to(r.t0 + 3000);
    const std::deque<SignalTrace::Edge> first = tr.traces()[0].edges;
    r.m.restore_bytes(snap);
    ASSERT_EQ(r.m.now(), t1);
    EXPECT_EQ(tr.traces()[0].edges.size(), first.size());  // nothing looked at while the machine stands
    r.run_to(t1 + 100);  // two periods: the edges of the first timeline after t1 are gone at the first look
    ASSERT_FALSE(tr.traces()[0].edges.empty());
    for (const auto& e : tr.traces()[0].edges) EXPECT_LE(e.t, t1 + 100);
    EXPECT_LT(tr.traces()[0].edges.size(), first.size());
    r.run_to(r.t0 + 3000);  // the same timeline again: the same edges, none twice
    const auto& again = tr.traces()[0].edges;
    ASSERT_EQ(again.size(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(again[i].t, first[i].t) << i;
        EXPECT_EQ(again[i].level, first[i].level) << i;
    }
}

TEST(SignalTrace, ARecordingAndATraceLookAtOnceAndNeitherStaysOnTheBoard) {
    const auto dir = std::filesystem::temp_directory_path() / "alp85_signal_trace_test";
    std::filesystem::create_directories(dir);
    Rig r;
    SignalTrace tr;
    debug::SignalRecorder rec;
    EXPECT_FALSE(r.m.has_probe(&tr));
    tr.start(r.m, {"PA0"}, 100'000);
    rec.start(r.m, dir / "both.vcd", {"PA0"});
    EXPECT_TRUE(r.m.has_probe(&tr));
    EXPECT_TRUE(r.m.has_probe(&rec));
    r.run_to(r.t0 + 2000);
    const std::size_t edges = tr.traces()[0].edges.size();
    rec.stop();
    EXPECT_EQ(rec.changes(), edges);  // the same pin seen by both from the same T-state
    EXPECT_FALSE(r.m.has_probe(&rec));
    EXPECT_TRUE(r.m.has_probe(&tr));
    tr.stop();
    EXPECT_FALSE(r.m.has_probe(&tr));
    EXPECT_TRUE(tr.traces().empty());
    std::filesystem::remove_all(dir);
}

TEST(SignalTrace, ANameThatIsNoPinIsRefusedAndTheOpenTraceKept) {
    Rig r;
    SignalTrace tr;
    tr.start(r.m, {"PA0"}, 1000);
    EXPECT_THROW(tr.start(r.m, {"PA9"}, 1000), std::runtime_error);
    EXPECT_TRUE(tr.open());
    ASSERT_EQ(tr.traces().size(), 1u);
    EXPECT_EQ(tr.traces()[0].pin.name, "PA0");
}

TEST(SignalTrace, TheCursorsReadTStatesAndMicroseconds) {
    // 3.072 MHz: 3155 T = 3155 / 3.072 us = 1027.0182 us (the thesis's pulse at D = 1, 3070 + 85);
    // 3072 T = 1 ms exactly; 1 T = 0.32552 us.
    EXPECT_EQ(debug::interval_text(1000, 4155), "3155 T = 1027.018 \u00b5s");
    EXPECT_EQ(debug::interval_text(0, 3072), "3072 T = 1000.000 \u00b5s");
    EXPECT_EQ(debug::interval_text(5, 6), "1 T = 0.326 \u00b5s");
    EXPECT_EQ(debug::interval_text(4155, 1000), "-3155 T = -1027.018 \u00b5s");
}

}  // namespace
}  // namespace alp85::test
