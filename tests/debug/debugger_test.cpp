// The debugging API: stops as values, events, source lines of addresses and addresses of lines,
// and the input log replaying a run exactly. Addresses are counted by hand from
// tests/board/programs/hello.asm (ORG 0040H; instruction lengths from the 8085 data sheet).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "emu/debug/debugger.h"
#include "emu/program/image_loader.h"

namespace alp85::test {
namespace {

using debug::Debugger;
using debug::Event;
using debug::StopReason;
using debug::WatchKind;
using debug::WatchSpec;

std::string program(const char* name) { return std::string(ALP85_BOARD_PROGRAMS) + "/" + name; }
std::uint64_t ms(double v) { return board::tstates_from_ms(v); }

struct Rig {
    Machine m;
    Debugger d{m};
    std::vector<Event> events;
    Rig() {
        const LoadedImage img = load_image(m, program("hello.asm"));
        d.program().add_assembly(*img.assembly);
        m.reset();
        d.listen([this](const Event& e) { events.push_back(e); });
    }
};

// 0040 LXI SP (3), XRA A (1), 3 x STA (3), then MVI/OUT pairs (2+2) x 3, WAITDU: IN (2), ANI (2),
// JNZ (3), MVI (2), OUT (2), LXI H (3), MVI B (2): SHOW (line 34) is at 0069H, OUT KDATA (35) 006AH.
TEST(Debugger, SourceLinesOfAddressesAndAddressesOfLines) {
    Rig r;
    const auto show = r.d.program().line_of(0x0069);
    ASSERT_TRUE(show);
    EXPECT_EQ(show->line, 34);
    EXPECT_TRUE(show->file.ends_with("hello.asm"));
    EXPECT_EQ(r.d.program().line_of(0x006A)->line, 35);
    EXPECT_EQ(r.d.program().line_of(0x006B)->line, 35);  // OUT's second byte
    EXPECT_EQ(r.d.program().addresses_of("hello.asm", 34), std::vector<std::uint16_t>{0x0069});
    EXPECT_EQ(r.d.program().addresses_of("programs/hello.asm", 35), std::vector<std::uint16_t>{0x006A});
    EXPECT_TRUE(r.d.program().addresses_of("hello.asm", 57).empty());  // an empty line
    EXPECT_FALSE(r.d.program().line_of(0x0700));                       // nothing assembled there
}

TEST(Debugger, ALineWithoutCodeBindsToTheNextLineWithCode) {
    Rig r;
    const Debugger::Location loc = r.d.locate_line("hello.asm", 57);  // blank, before KEYINT (58)
    ASSERT_TRUE(loc.error.empty()) << loc.error;
    ASSERT_TRUE(loc.bound);
    EXPECT_EQ(loc.bound->line, 58);
    EXPECT_EQ(loc.addresses, std::vector<std::uint16_t>{*r.d.program().value_of("KEYINT")});
    EXPECT_FALSE(r.d.locate_line("hello.asm", 500).error.empty());
    EXPECT_FALSE(r.d.locate_line("other.asm", 1).error.empty());
}

TEST(Debugger, ABreakpointStopIsAValueAndAnEvent) {
    Rig r;
    const int n = r.d.add_breakpoint_at(0x0069).number;
    const debug::Stop s = r.d.run_until(ms(5), {}, {"x.alp", 3});
    EXPECT_EQ(s.reason, StopReason::Breakpoint);
    EXPECT_EQ(s.pc, 0x0069);
    ASSERT_TRUE(s.line);
    EXPECT_EQ(s.line->line, 34);
    ASSERT_EQ(r.events.size(), 1u);
    EXPECT_EQ(r.events[0].kind, Event::Kind::Stopped);
    EXPECT_EQ(r.events[0].stop.pc, 0x0069);
    EXPECT_EQ(r.events[0].origin.line, 3);
    // A run that simply reaches its deadline is no event.
    r.d.remove(n);
    EXPECT_EQ(r.d.run_until(r.m.now() + 1000).reason, StopReason::Deadline);
    EXPECT_EQ(r.events.size(), 1u);
}

TEST(Debugger, AWatchpointNamesTheAddress) {
    Rig r;
    WatchSpec w;  // any access of DONE: the first is STA DONE at 004AH
    w.kind = WatchKind::Access;
    w.what = "DONE";
    w.first = w.last = 0x1002;
    r.d.add_watchpoint(w);
    const debug::Stop s = r.d.run_until(ms(5));
    EXPECT_EQ(s.reason, StopReason::Watchpoint);
    EXPECT_EQ(s.data, std::optional<std::uint16_t>{0x1002});
    EXPECT_EQ(s.pc, 0x004D);  // after the STA
}

TEST(Debugger, TheInputLogReplaysARunExactly) {
    Rig a;
    // Two keys (codes 05H and 0CH) pressed 30 ms each at fixed times.
    a.m.key_at(periph::Key::K5, true, ms(20));
    a.m.key_at(periph::Key::K5, false, ms(50));
    a.m.key_at(periph::Key::KC, true, ms(80));
    a.m.key_at(periph::Key::KC, false, ms(110));
    a.d.run_until(ms(150));
    const std::vector<InputEvent> log = a.d.input_log();
    ASSERT_EQ(log.size(), 4u);
    EXPECT_EQ(log[0].at, ms(20));
    EXPECT_EQ(log[3].at, ms(110));
    EXPECT_EQ(a.m.peek(0x1002), 0x55);  // both keys arrived (hello.asm's DONE)

    Rig b;
    b.m.replay(log);
    b.d.run_until(ms(150));
    EXPECT_EQ(b.m.now(), a.m.now());
    EXPECT_EQ(b.m.snapshot_bytes(), a.m.snapshot_bytes());
    EXPECT_EQ(b.d.input_log().size(), 4u);
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

// The memory cap of reverse execution: a program that calls and then resets SP inside the call,
// over and over, deepens the counted call depth by one each pass (CALL pushes, LXI SP is no
// return) and never comes back. One pass is CALL 18 + LXI 10 + JMP 10 = 38 T-states (8085 data
// sheet), so 3.9 M T-states inside one snapshot interval are 102 631 passes: more call depths
// than reverse-next keeps for one interval (65 536). It stops, says so, and leaves the machine
// where it was.
TEST(Debugger, ReverseNextStopsAtTheDepthCapAndSaysSo) {
    const std::filesystem::path src = std::filesystem::temp_directory_path() / "alp85_depth_cap.asm";
    {
        std::ofstream f(src);
        f << "        ORG     0\n        LXI     SP,20F0H\nLOOP:   CALL    SUB\nSUB:    LXI     SP,20F0H\n"
             "        JMP     LOOP\n        END\n";
    }
    Machine m;
    Debugger d{m};
    const LoadedImage img = load_image(m, src);
    std::filesystem::remove(src);
    d.program().add_assembly(*img.assembly);
    m.reset();
    d.set_history(true, 4'000'000);  // one snapshot, at 0, for the whole run
    d.run_for(3'900'000);
    const std::vector<std::uint8_t> before = m.snapshot_bytes();
    const debug::Stop s = d.reverse_next();
    EXPECT_EQ(s.reason, StopReason::Error);
    EXPECT_NE(s.message.find("memory cap"), std::string::npos) << s.message;
    EXPECT_EQ(m.snapshot_bytes(), before);
}

}  // namespace
}  // namespace alp85::test
