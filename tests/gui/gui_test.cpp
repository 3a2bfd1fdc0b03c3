// emu/gui without a window: the pacing clock, the keypad's geometry and presses, the toolpath's
// ideal line.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

#include "emu/board/machine.h"
#include "emu/gui/controls.h"
#include "emu/gui/debug_panes.h"
#include "emu/gui/input.h"
#include "emu/front/keys.h"
#include "emu/gui/layout.h"
#include "emu/front/pacer.h"
#include "emu/gui/tool_view.h"
#include "emu/front/toolpath.h"
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

// DAP's wait between slices: 3,072,000 T-states are 1 s of the board at 3.072 MHz; a quarter of a
// second of host time after the base, the machine is 750 ms ahead. Behind, or at max speed: no wait.
TEST(Pacer, AheadIsTheMachinesLeadOverTheHostClock) {
    Pacer p;
    const HostClock::time_point t0{};
    p.set_speed(1, 0, t0);
    EXPECT_EQ(p.ahead(3'072'000, t0 + 250ms), 750ms);
    EXPECT_EQ(p.ahead(3'072'000, t0 + 2s), 0ms);
    p.set_speed(0, 0, t0);
    EXPECT_EQ(p.ahead(3'072'000, t0), 0ms);
}

TEST(FrameClock, DeadlinesAreAbsoluteAndAnOverrunSkipsAhead) {
    const HostClock::time_point t0{};
    FrameClock c(t0);
    EXPECT_EQ(c.next(t0 + 5ms), t0 + FrameClock::kPeriod);
    EXPECT_EQ(c.next(t0 + FrameClock::kPeriod + 1ms), t0 + FrameClock::kPeriod * 2);
    EXPECT_EQ(c.next(t0 + 100ms), t0 + FrameClock::kPeriod * 6);  // frames 3-5 were missed
}

// Calm frames (no input): every second deadline of the 60 Hz grid, 30 a second; an event ends the
// wait and the grid goes on from the next sixtieth.
TEST(FrameClock, CalmFramesKeepEverySecondDeadlineAndAnEventResumesTheGrid) {
    const HostClock::time_point t0{};
    const auto p = FrameClock::kPeriod;
    FrameClock c(t0);
    EXPECT_EQ(c.next(t0 + 5ms, 2), t0 + p * 2);
    EXPECT_EQ(c.next(t0 + p * 2 + 1ms, 2), t0 + p * 4);
    EXPECT_EQ(c.next(t0 + p * 4 + 1ms, 2), t0 + p * 6);
    EXPECT_EQ(c.resume(t0 + p * 4 + 20ms), t0 + p * 6);  // 86.7 ms: the deadline after it is frame 6 (100 ms)
    EXPECT_EQ(c.next(t0 + p * 6 + 1ms), t0 + p * 7);      // at 60 a second again
    EXPECT_EQ(c.next(t0 + p * 7 + 1ms, 2), t0 + p * 8);
    EXPECT_EQ(c.next(t0 + 201ms, 2), t0 + p * 14);         // overran past frame 12 (200 ms): 13 is odd
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
    EXPECT_EQ(find_pad_key("RESET")->pad, Button::Reset);
    EXPECT_EQ(find_pad_key("VECT")->pad, Button::Vect);
    EXPECT_FALSE(key_at(kKeyX0 + kKeyW + 1, kKeyY0 + 1));  // the gap between two buttons
}

TEST(Presser, AShortClickIsHeldForTheDebounce) {
    script::Session session{script::SessionOptions{}};
    Machine& m = session.machine();
    Presser p;
    const PadKey seven = *find_pad_key("7");
    p.down(seven, session);
    p.up(seven, session);  // released at once on the host: the machine still sees 30 ms
    m.run_for(board::tstates_from_ms(29));
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::K7));
    m.run_for(board::tstates_from_ms(2));
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::K7));
}

// Two presses of 0 and then EXEC within one frame (key down, up, down, up, down, up before the
// machine runs): each is held kKeyHold = 30 ms and the next closes kKeyGap = 30 ms after it
// opened (emu/board/key_press.h, the script's defaults), so the 8279 sees three presses: 0 over
// 0-30 ms, 0 over 60-90 ms, EXEC over 120-150 ms. Sampled in the middle of each interval.
TEST(Presser, PressesWithinOneFrameAreQueuedNotLost) {
    script::Session session{script::SessionOptions{}};
    Machine& m = session.machine();
    Presser p;
    const PadKey zero = *find_pad_key("0"), exec = *find_pad_key("EXEC");
    for (const PadKey& k : {zero, zero, exec}) {
        p.down(k, session);
        p.up(k, session);
    }
    const auto at = [&](int ms) { m.run_until(board::tstates_from_ms(ms)); };
    at(15);
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::K0));
    at(45);
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::K0));  // the gap: the first press ended
    at(75);
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::K0));   // the second, not merged into the first
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::Exec));
    at(105);
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::K0));
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::Exec));
    at(135);
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::Exec));  // not at once with the zeros
    at(165);
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::Exec));
}

// A runaway into an end stop reports it at every step: the log shows one line with a count.
TEST(ControlsLog, RepeatedEndStopMessagesCoalesce) {
    ControlsState s;
    s.add_log("script endstop.alp");
    for (int i = 0; i < 600; ++i) s.add_log(fmt::format("machine tool: the Y table reached its high end stop at {} ms", 400 + i));
    ASSERT_EQ(s.log.size(), 2u);
    EXPECT_EQ(s.log.back(), "machine tool: the Y table reached its high end stop at 400 ms (600 times, the last at 999 ms)");
    s.add_log("machine tool: the Y table reached its low end stop at 2 s");  // another message: a line of its own
    s.add_log("paused at 0B2CH");
    s.add_log("paused at 0B2CH");  // the same text without a time: counted too
    ASSERT_EQ(s.log.size(), 4u);
    EXPECT_EQ(s.log[2], "machine tool: the Y table reached its low end stop at 2 s");
    EXPECT_EQ(s.log[3], "paused at 0B2CH (2 times)");
}

// The feed prompt "H=----" (docs/thesis.md) and its digits as typed get the hint with the
// physical motors; X1's "H1=----", the Z prompt and the ideal motors do not.
TEST(Prompt, TheFeedPromptWarnsOfTheRunawayBelow300) {
    const auto hint = feed_prompt_hint("H=----  ", true);
    ASSERT_TRUE(hint);
    EXPECT_NE(hint->find("0300"), std::string_view::npos);
    EXPECT_TRUE(feed_prompt_hint("H=0750", true));
    EXPECT_FALSE(feed_prompt_hint("H1=----", true));
    EXPECT_FALSE(feed_prompt_hint("?.=----", true));
    EXPECT_FALSE(feed_prompt_hint("H=----", false));
}

// The thesis firmware's line: X1,Y1 = 100,50; X2,Y2 = 300,200 steps (16-bit little endian, 3 bytes
// apart from 1B00H).
void set_line_variables(Machine& m, Toolpath& path) {
    path.set_variables(0x1B00);
    for (auto [a, v] : {std::pair{0x1B00, 100}, {0x1B03, 50}, {0x1B06, 300}, {0x1B09, 200}}) {
        m.poke(static_cast<std::uint16_t>(a), static_cast<std::uint8_t>(v & 0xFF));
        m.poke(static_cast<std::uint16_t>(a + 1), static_cast<std::uint8_t>(v >> 8));
    }
}

TEST(Toolpath, TheIdealLineStartsWhereTheTableStoodWhenTheMoveBegan) {
    script::Session session{script::SessionOptions{}};
    Machine& m = session.machine();
    Toolpath path;
    set_line_variables(m, path);
    debug::ToolSample s;
    s.t = 0;
    path.observe(s, session);
    s.t = Toolpath::kIdle + 10;
    s.axes[0].commanded = 1;  // the first step after a pause: the move began at 0,0
    s.axes[0].mm = 0.05;
    path.observe(s, session);
    const auto line = path.ideal(session);
    ASSERT_TRUE(line);
    EXPECT_TRUE(line->started);
    EXPECT_DOUBLE_EQ(line->from.x, 0);
    EXPECT_DOUBLE_EQ(line->to.x, 10);
    EXPECT_DOUBLE_EQ(line->to.y, 7.5);
    EXPECT_DOUBLE_EQ(line->origin.x, -5);
    EXPECT_DOUBLE_EQ(line->origin.y, -2.5);
    const Bounds w = path.workpiece(session);
    EXPECT_DOUBLE_EQ(w.x1, 35);
    EXPECT_EQ(path.points().size(), 2u);
}

// A path cleared (a reset or a new workpiece at the feed prompt, then EXEC at once): the first step comes
// well within kIdle of the first sample, and still begins the move; the line stays where the move
// began while the table goes on.
TEST(Toolpath, AMoveBegunRightAfterAClearStartsWhereTheTableStood) {
    script::Session session{script::SessionOptions{}};
    Machine& m = session.machine();
    Toolpath path;
    set_line_variables(m, path);
    for (int round = 0; round < 2; ++round) {  // and again after a second clear
        path.clear();
        const std::int64_t at = 40 * round;  // where the table stands: 0, then 40 steps (2 mm)
        debug::ToolSample s;
        s.t = Toolpath::kIdle * 10 * static_cast<std::uint64_t>(round);
        s.axes[0].commanded = at;
        path.observe(s, session);
        for (int step = 1; step <= 3; ++step) {  // steps 3 ms apart, far less than kIdle
            s.t += board::tstates_from_ms(3);
            s.axes[0].commanded = at + step;
            path.observe(s, session);
            const auto line = path.ideal(session);
            ASSERT_TRUE(line);
            EXPECT_TRUE(line->started);
            EXPECT_DOUBLE_EQ(line->from.x, 0.05 * static_cast<double>(at));
            EXPECT_DOUBLE_EQ(line->to.x, 0.05 * static_cast<double>(at) + 10);  // (300 - 100) steps
            EXPECT_DOUBLE_EQ(line->to.y, 7.5);                                   // (200 - 50) steps
        }
    }
}

// A snapshot taken at Bitti (the thesis line X1,Y1 = 0,0 to X2,Y2 = 200,150 steps, done): the table
// stands at 10, 7.5 mm. The line it ran is not known after the restore, and the one from where the
// table stands, (10, 7.5) to (20, 15), was never commanded: no line until the next move begins, and
// the workpiece where the finished move puts it: X2, Y2 steps before where the table stands.
TEST(Toolpath, ARestoredSnapshotDrawsNoLineUntilTheNextMoveBegins) {
    script::Session session{script::SessionOptions{}};
    Machine& m = session.machine();
    Toolpath path;
    path.set_variables(0x1B00);
    for (auto [a, v] : {std::pair{0x1B00, 0}, {0x1B03, 0}, {0x1B06, 200}, {0x1B09, 150}}) {
        m.poke(static_cast<std::uint16_t>(a), static_cast<std::uint8_t>(v & 0xFF));
        m.poke(static_cast<std::uint16_t>(a + 1), static_cast<std::uint8_t>(v >> 8));
    }
    ASSERT_TRUE(path.ideal(session));  // the line as a reset leaves it: from where the table stands
    path.restored();
    EXPECT_FALSE(path.ideal(session));
    // This machine's sequencers stand at 0 steps: the finished move began 200, 150 steps before.
    const Bounds w = path.workpiece(session);
    EXPECT_DOUBLE_EQ(w.x0, -200 * 0.05);
    EXPECT_DOUBLE_EQ(w.y0, -150 * 0.05);
    debug::ToolSample s;
    s.t = 1000;
    s.axes[0].commanded = 200, s.axes[1].commanded = 150;  // where Bitti left the table
    path.observe(s, session);
    EXPECT_FALSE(path.ideal(session));
    // The middle of a move restored: steps 3 ms apart, never kIdle standing: still no line.
    for (int step = 1; step <= 20; ++step) {
        s.t += board::tstates_from_ms(3);
        s.axes[0].commanded = 200 + step;
        path.observe(s, session);
        EXPECT_FALSE(path.ideal(session)) << "step " << step;
    }
    // The table stands for kIdle, then the next move begins: its line starts where the table stood.
    s.t += Toolpath::kIdle;
    s.axes[0].commanded = 221;
    path.observe(s, session);
    const auto line = path.ideal(session);
    ASSERT_TRUE(line);
    EXPECT_TRUE(line->started);
    EXPECT_DOUBLE_EQ(line->from.x, 220 * 0.05);
    EXPECT_DOUBLE_EQ(line->from.y, 150 * 0.05);
    EXPECT_DOUBLE_EQ(line->to.x, 220 * 0.05 + 10);   // (200 - 0) steps
    EXPECT_DOUBLE_EQ(line->to.y, 150 * 0.05 + 7.5);  // (150 - 0) steps
}

// The window on a 1366x768 laptop: the largest size that leaves room for a title bar and a panel,
// with the 1280x800 layout's proportions: 708 = 768 - 60 rows, 708 / 800 = 0.885, 0.885 * 1280 = 1133.
TEST(Window, TheFirstSizeFitsA1366x768Screen) {
    const Size s = initial_window_size(0, 1366, 768);
    EXPECT_EQ(s.w, 1133);
    EXPECT_EQ(s.h, 708);
    EXPECT_LE(s.w, 1366);
    EXPECT_LE(s.h + 60, 768);
    const Size big = initial_window_size(0, 2560, 1440);  // never larger than 1:1 unless asked
    EXPECT_EQ(big.w, kWindowWidth);
    EXPECT_EQ(big.h, kWindowHeight);
    const Size hidpi = initial_window_size(2, 0, 0);
    EXPECT_EQ(hidpi.w, 2 * kWindowWidth);
    EXPECT_EQ(hidpi.h, 2 * kWindowHeight);
}

// --scale 2 on a 1366x768 screen: brought down to the largest that fits, as without --scale:
// min((1366 - 40) / 1280, (768 - 60) / 800) = 0.885 -> 1133 x 708.
TEST(Window, AScaleTooLargeForTheScreenIsFitted) {
    const Size s = initial_window_size(2, 1366, 768);
    EXPECT_EQ(s.w, 1133);
    EXPECT_EQ(s.h, 708);
    const Size fits = initial_window_size(2, 2600, 1700);  // 2560 + 40 and 1600 + 60 fit: as asked
    EXPECT_EQ(fits.w, 2 * kWindowWidth);
    EXPECT_EQ(fits.h, 2 * kWindowHeight);
}

// The table view's Y labels sit 14 px above their grid line; one that would reach into the title's
// band (the top 20 px of kTableRect, y 8..28) is not drawn: a line at y 40 would put its label at
// 26, over the title; one at 42 at 28, just below it.
TEST(TableView, NoGridLabelOverTheTitle) {
    EXPECT_FALSE(grid_label_y(kTableRect.y + 32));
    ASSERT_TRUE(grid_label_y(kTableRect.y + 34));
    EXPECT_FLOAT_EQ(*grid_label_y(kTableRect.y + 34), kTableRect.y + 20);
    EXPECT_FLOAT_EQ(*grid_label_y(300), 286);
}

// A resized window: the picture keeps its proportions, centred; a point maps there and back.
TEST(Window, ThePictureIsScaledIntoAnyWindowAndPointsMapBack) {
    const Fit wide = fit_to(2000, 800);  // 800 rows: scale 1, centred with 360 columns each side
    EXPECT_FLOAT_EQ(wide.scale, 1.0f);
    EXPECT_FLOAT_EQ(wide.ox, 360.0f);
    EXPECT_FLOAT_EQ(wide.oy, 0.0f);
    const Fit twice = fit_to(2560, 1600);
    EXPECT_FLOAT_EQ(twice.scale, 2.0f);
    EXPECT_TRUE(fit_to(kWindowWidth, kWindowHeight).identity());
    const Fit small = fit_to(640, 600);  // width-bound: 0.5, 100 rows above and below
    EXPECT_FLOAT_EQ(small.scale, 0.5f);
    EXPECT_FLOAT_EQ(small.oy, 100.0f);
    const Vec2 c = key_rect(*find_pad_key("EXEC")).centre();
    const Vec2 w = to_window(small, c.x, c.y);
    EXPECT_FLOAT_EQ(w.x, c.x / 2);
    EXPECT_FLOAT_EQ(w.y, c.y / 2 + 100);
    const Vec2 back = to_logical(small, w.x, w.y);
    EXPECT_FLOAT_EQ(back.x, c.x);
    EXPECT_FLOAT_EQ(back.y, c.y);
    const auto k = key_at(back.x, back.y);
    ASSERT_TRUE(k);
    EXPECT_EQ(k->key, periph::Key::Exec);
}

// Zoom about the pointer keeps the millimetre under it; a drag moves the view by the drag;
// framing fits the given bounds.
TEST(TableCameraTest, ZoomKeepsThePointUnderThePointerAndPanFollowsTheDrag) {
    Bounds b = Bounds::none();
    b.add(0, 0);
    b.add(40, 30);
    const TableView fitted = TableView::fit(b);
    TableCamera cam;
    const float px = kTableRect.x + 100, py = kTableRect.y + 80;
    const auto [mx, my] = cam.apply(fitted).to_mm(px, py);
    cam.zoom_at(fitted, px, py, 4);
    const TableView z = cam.apply(fitted);
    EXPECT_DOUBLE_EQ(z.scale, 4 * fitted.scale);
    const auto [mx2, my2] = z.to_mm(px, py);
    EXPECT_NEAR(mx2, mx, 1e-9);
    EXPECT_NEAR(my2, my, 1e-9);
    // a drag of 40 px right and 20 px down: the point under the pointer moves with it
    const auto [ax, ay] = z.to_mm(px, py);
    cam.pan(fitted, 40, 20);
    const auto [bx, by] = cam.apply(fitted).to_mm(px + 40, py + 20);
    EXPECT_NEAR(bx, ax, 1e-9);
    EXPECT_NEAR(by, ay, 1e-9);
    // Home frames the path: a 2 mm square fills the view
    Bounds path = Bounds::none();
    path.add(10, 10);
    path.add(12, 12);
    cam.frame(path);
    const TableView f = cam.apply(fitted);
    EXPECT_DOUBLE_EQ(f.scale, TableView::fit(path).scale);
    EXPECT_DOUBLE_EQ(f.cx, 11);
    cam.reset();
    EXPECT_DOUBLE_EQ(cam.apply(fitted).scale, fitted.scale);
}

// F1 and ? open the key map, and it names every key of the pad's PC keys.
TEST(KeyMap, F1OrQuestionMarkAndEveryPadKeyListed) {
    SDL_Keysym f1{};
    f1.sym = SDLK_F1;
    EXPECT_TRUE(is_key_map_key(f1));
    SDL_Keysym q{};
    q.sym = SDLK_SLASH;
    q.mod = KMOD_LSHIFT;
    EXPECT_TRUE(is_key_map_key(q));
    q.mod = KMOD_NONE;
    EXPECT_FALSE(is_key_map_key(q));
    std::string all;
    for (const KeyMapRow& r : key_map_rows(false)) all += std::string(r.keys) + " " + std::string(r.action) + "\n";
    for (const char* name : {"EXEC", "NEXT", "PREV", "GO", "SUBST MEM", "EXAM REG", "SINGLE STEP", "RESET", "VECT INTR", "zoom", "pan",
                             "frame the toolpath"})
        EXPECT_NE(all.find(name), std::string::npos) << name;
}

// Labels fit where they are drawn, in ImGui's default font (the one the window uses): the table's
// title inside the table view, and the axis panel's headers within the panel's width.
TEST(Labels, TheTableTitleAndTheAxisHeadersAreNotClipped) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = {static_cast<float>(kWindowWidth), static_cast<float>(kWindowHeight)};
    ImGui::NewFrame();
    EXPECT_LE(ImGui::CalcTextSize(kTableTitle).x + 6, kTableRect.w);
    float headers = 0;
    for (const char* hd : kAxisHeaders) headers += ImGui::CalcTextSize(hd).x + 2 * ImGui::GetStyle().CellPadding.x + 1;
    EXPECT_LE(headers, kAxesRect.w - 2 * ImGui::GetStyle().WindowPadding.x);
    ImGui::EndFrame();
    ImGui::DestroyContext();
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

// No part's text is cut off at the chip pane's edge (the 8155's "command 01H: port A out, port B
// in, ..." ran past it): each part's lines, drawn as its tab draws them in a pane of the chip
// pane's size and scrollbars, are no wider than the pane (nothing to scroll to sideways). The layout is the same
// at 1366x768: the window scales it.
TEST(DebugPanes, NoPartTextIsCutOff) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = {static_cast<float>(kWindowWidth), static_cast<float>(kWindowHeight)};
    script::DebugShell shell{script::SessionOptions{}};
    const auto parts = part_panes(shell);
    ASSERT_GE(parts.size(), 4u);
    for (const DebugPanes::PartPane& part : parts) {
        float scroll_x = -1;
        for (int i = 0; i < 3; ++i) {  // the content's size is known from the frame after
            io.DeltaTime = 1.0f / 60;
            ImGui::NewFrame();
            ImGui::SetNextWindowSize({kChipsRect.w, kChipsRect.h});
            ImGui::Begin(("pane " + part.name).c_str(), nullptr, ImGuiWindowFlags_HorizontalScrollbar | ImGuiWindowFlags_AlwaysVerticalScrollbar);
            draw_part_lines(part);
            scroll_x = ImGui::GetScrollMaxX();
            ImGui::End();
            ImGui::EndFrame();
        }
        EXPECT_EQ(scroll_x, 0) << part.name;
    }
    ImGui::DestroyContext();
}

// The Parts and Watch panes keep the size a user drags them to (ImGui::SetWindowSize is what a
// drag on an edge does); the other panes stay in their rects.
TEST(DebugPanes, PartsAndWatchAreResizable) {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    io.DisplaySize = {static_cast<float>(kWindowWidth), static_cast<float>(kWindowHeight)};
    script::DebugShell shell{script::SessionOptions{}};
    DebugPanes panes;
    const auto frame = [&](const std::function<void()>& after) {
        io.DeltaTime = 1.0f / 60;
        ImGui::NewFrame();
        draw_debug_panes(panes, shell, false);
        after();
        ImGui::EndFrame();
    };
    frame([] {
        ImGui::SetWindowSize("Parts", {400, 300});
        ImGui::SetWindowSize("Watch", {500, 200});
        ImGui::SetWindowSize("Registers", {400, 300});
    });
    const auto size_of = [](const char* name) {
        ImGui::Begin(name);  // appends to the pane drawn this frame
        const ImVec2 s = ImGui::GetWindowSize();
        ImGui::End();
        return s;
    };
    ImVec2 parts, watch, regs;
    frame([&] { parts = size_of("Parts"), watch = size_of("Watch"), regs = size_of("Registers"); });
    EXPECT_FLOAT_EQ(parts.x, 400);
    EXPECT_FLOAT_EQ(parts.y, 300);
    EXPECT_FLOAT_EQ(watch.x, 500);
    EXPECT_FLOAT_EQ(watch.y, 200);
    EXPECT_FLOAT_EQ(regs.x, kRegistersRect.w);  // fixed
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace alp85::gui
