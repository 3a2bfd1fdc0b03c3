// emu/gui without a window: the pacing clock, the keypad's geometry and presses, the toolpath's
// ideal line.
#include <gtest/gtest.h>

#include <algorithm>

#include "emu/board/machine.h"
#include "emu/gui/debug_panes.h"
#include "emu/gui/input.h"
#include "emu/gui/layout.h"
#include "emu/gui/pacer.h"
#include "emu/gui/toolpath.h"
#include "tests/board/led_latch.h"

namespace alp85::gui {
namespace {

using namespace std::chrono_literals;

TEST(Pacer, RealTimeIsAbsoluteSoItDoesNotDrift) {
    Pacer p;
    const HostClock::time_point t0{};
    p.set_speed(1, 1000, t0);
    // A thousand frames of 16.666667 ms: the target is the base plus exactly 3.072 MHz x elapsed.
    std::uint64_t now = 1000;
    for (int i = 1; i <= 1000; ++i) now = p.target(now, t0 + FrameClock::kPeriod * i);
    const double elapsed = std::chrono::duration<double>(FrameClock::kPeriod * 1000).count();
    EXPECT_EQ(now, 1000 + static_cast<std::uint64_t>(elapsed * 3.072e6));
}

TEST(Pacer, SpeedsScaleTheRateAndAFallenBehindMachineIsRebased) {
    Pacer p;
    const HostClock::time_point t0{};
    p.set_speed(0.1, 0, t0);
    EXPECT_EQ(p.target(300000, t0 + 1s), 307200u);
    p.set_speed(100, 0, t0);
    // Two seconds behind is more than kMaxLag: the target is kMaxLag ahead of the machine.
    EXPECT_EQ(p.target(0, t0 + 2s), static_cast<std::uint64_t>(0.25 * 307.2e6));
    p.set_speed(0, 0, t0);
    EXPECT_TRUE(p.max_speed());
}

TEST(FrameClock, DeadlinesAreAbsoluteAndAnOverrunSkipsAhead) {
    const HostClock::time_point t0{};
    FrameClock c(t0);
    EXPECT_EQ(c.next(t0 + 5ms), t0 + FrameClock::kPeriod);
    EXPECT_EQ(c.next(t0 + FrameClock::kPeriod + 1ms), t0 + FrameClock::kPeriod * 2);
    EXPECT_EQ(c.next(t0 + 100ms), t0 + FrameClock::kPeriod * 6);  // frames 3-5 were missed
}

TEST(Layout, EveryButtonIsFoundAtItsCentreAndTheyDoNotOverlap) {
    EXPECT_EQ(pad_keys().size(), 26u);
    for (const PadKey& k : pad_keys()) {
        const Vec2 c = key_rect(k).centre();
        const auto hit = key_at(c.x, c.y);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->row, k.row);
        EXPECT_EQ(hit->col, k.col);
    }
    EXPECT_EQ(find_pad_key("exec")->key, periph::Key::Exec);
    EXPECT_EQ(find_pad_key("RESET")->pad, Pad::Reset);
    EXPECT_EQ(find_pad_key("VECT")->pad, Pad::Vect);
    EXPECT_FALSE(key_at(kKeyX0 + kKeyW + 1, kKeyY0 + 1));  // the gap between two buttons
}

TEST(Presser, AShortClickIsHeldForTheDebounce) {
    Machine m;
    Presser p;
    const PadKey seven = *find_pad_key("7");
    p.down(seven, m);
    p.up(seven, m);  // released at once on the host: the machine still sees 30 ms
    m.run_for(board::tstates_from_ms(29));
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::K7));
    m.run_for(board::tstates_from_ms(2));
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::K7));
}

TEST(Toolpath, TheIdealLineStartsWhereTheTableStoodWhenTheMoveBegan) {
    Machine m;
    Toolpath path;
    path.set_variables(0x1B00);
    // X1,Y1 = 100,50; X2,Y2 = 300,200 (16-bit little endian, 3 bytes apart).
    for (auto [a, v] : {std::pair{0x1B00, 100}, {0x1B03, 50}, {0x1B06, 300}, {0x1B09, 200}}) {
        m.poke(static_cast<std::uint16_t>(a), static_cast<std::uint8_t>(v & 0xFF));
        m.poke(static_cast<std::uint16_t>(a + 1), static_cast<std::uint8_t>(v >> 8));
    }
    debug::ToolSample s;
    s.t = 0;
    path.observe(s, m);
    s.t = Toolpath::kIdle + 10;
    s.axes[0].commanded = 1;  // the first step after a pause: the move began at 0,0
    s.axes[0].mm = 0.05;
    path.observe(s, m);
    const auto line = path.ideal(m);
    ASSERT_TRUE(line);
    EXPECT_TRUE(line->started);
    EXPECT_DOUBLE_EQ(line->from.x, 0);
    EXPECT_DOUBLE_EQ(line->to.x, 10);
    EXPECT_DOUBLE_EQ(line->to.y, 7.5);
    EXPECT_DOUBLE_EQ(line->origin.x, -5);
    EXPECT_DOUBLE_EQ(line->origin.y, -2.5);
    const Bounds w = path.workpiece(m);
    EXPECT_DOUBLE_EQ(w.x1, 35);
    EXPECT_EQ(path.points().size(), 2u);
}

// The chip pane has a tab per part that describes itself: a toy part attached in one line gets
// one, listing its two registers as `info leds` renders them, with no GUI code of its own.
TEST(PartPane, AToyPartAddedInOneLineHasItsTab) {
    test::LedLatch leds;  // outlives the machine it is attached to
    script::DebugShell shell{script::SessionOptions{}};
    shell.debugger().machine().attach(leds, &leds, 0x00, 0x00);
    const auto panes = part_panes(shell);
    const auto tab = std::find_if(panes.begin(), panes.end(), [](const DebugPanes::PartPane& p) { return p.name == "leds"; });
    ASSERT_NE(tab, panes.end());
    ASSERT_EQ(tab->lines.size(), 3u);
    EXPECT_EQ(tab->lines[0], "LED latch (a toy part)");
    EXPECT_EQ(tab->lines[1], "  latch       00H: 0 lit");
    EXPECT_EQ(tab->lines[2], "  heartbeats  0");
    for (const char* board_part : {"8155", "8279", "machine tool"})
        EXPECT_TRUE(std::any_of(panes.begin(), panes.end(), [&](const DebugPanes::PartPane& p) { return p.name == board_part; }));
}

}  // namespace
}  // namespace alp85::gui
