// The Signals pane without a window (emu/gui/signals_pane.h): its cursors on a port A pulse train
// poked in by hand, placed by clicks at the pixels layout.h gives the edges. T-states from the
// Intel 8085AH data sheet's instruction table: MVI r 7, OUT 10 (the port changes at its I/O write
// cycle's first T-state, 7 after the OUT begins), JMP 10, LXI 10.
#include <gtest/gtest.h>

#include "emu/gui/layout.h"
#include "emu/gui/signals_pane.h"

namespace alp85::gui {
namespace {

// 0800 LXI SP,2000H / 0803 MVI A,01H / 0805 OUT 0F8H (port A output) / 0807 MVI A,01H / 0809 OUT 0F9H
// (PA0 rises) / 080B MVI A,00H / 080D OUT 0F9H (falls 10 + 7 = 17 T later) / 080F JMP 0807H (rises
// 10 + 10 + 7 = 27 T later).
const std::vector<std::uint8_t> kPulses = {0x31, 0x00, 0x20, 0x3E, 0x01, 0xD3, 0xF8, 0x3E, 0x01, 0xD3,
                                           0xF9, 0x3E, 0x00, 0xD3, 0xF9, 0xC3, 0x07, 0x08};

struct Rig {
    script::Session s{script::SessionOptions{}};
    SignalsPane p;
    Rig() {
        s.machine().load(0x0800, kPulses);
        s.machine().reset();
        s.machine().cpu().regs().pc = 0x0800;
    }
};

TEST(SignalsPane, ACursorClickedNearAnEdgeTakesItAndTheyReadTheHandCount) {
    Rig r;
    ASSERT_EQ(open_signals(r.p, r.s, {"PA0"}, 1).status, script::Session::Status::Ok);  // 1 ms = 3072 T
    EXPECT_TRUE(r.s.machine().has_probe(&r.s.signal_trace()));
    r.s.machine().run_until(r.s.machine().now() + 3000);
    const auto& edges = r.s.signal_trace().traces()[0].edges;
    ASSERT_GE(edges.size(), 20u);
    // The last rising edge and the falling edge after it, 17 T-states apart.
    std::size_t rise = edges.size() - 1;
    while (edges[rise].level != '1' || rise + 1 >= edges.size()) --rise;
    ASSERT_EQ(edges[rise + 1].t - edges[rise].t, 17u);
    const std::uint64_t now = r.s.machine().now(), span = board::tstates_from_ms(1);
    const float y = signals_row(0).centre().y;
    // 640 pixels for 3072 T: 4.8 T a pixel, and a click takes the nearest edge within 6 pixels
    // (28 T). One pixel right of the rise is 4.8 T from it and 12.2 from the fall; one pixel left of
    // the fall the other way round.
    ASSERT_TRUE(place_cursor(r.p, r.s, signals_x(edges[rise].t, now, span) + 1, y));
    ASSERT_TRUE(place_cursor(r.p, r.s, signals_x(edges[rise + 1].t, now, span) - 1, y));
    EXPECT_EQ(r.p.cursors[0], edges[rise].t);
    EXPECT_EQ(r.p.cursors[1], edges[rise + 1].t);
    // 17 T at 3.072 MHz: 17 / 3.072 = 5.5339 us.
    EXPECT_NE(cursor_readout(r.p).find("B - A = 17 T = 5.534 \u00b5s"), std::string::npos) << cursor_readout(r.p);
    // A third click moves A: 5 pixels (24 T) left of the rise is 3 T from the fall before it (the
    // low time is 27 T), the nearer edge.
    ASSERT_TRUE(place_cursor(r.p, r.s, signals_x(edges[rise].t, now, span) - 5, y));
    EXPECT_EQ(r.p.cursors[0], edges[rise - 1].t);
    EXPECT_EQ(edges[rise].t - edges[rise - 1].t, 27u);
    // A click below the one pin's row places nothing.
    EXPECT_FALSE(place_cursor(r.p, r.s, signals_x(edges[rise].t, now, span), signals_row(1).centre().y));
    close_signals(r.p, r.s);
    EXPECT_FALSE(r.s.machine().has_probe(&r.s.signal_trace()));
}

TEST(SignalsPane, AClickFarFromAnEdgeTakesTheTimeUnderThePointer) {
    Rig r;
    ASSERT_EQ(open_signals(r.p, r.s, {"PA0"}, 100).status, script::Session::Status::Ok);  // 307 200 T: 480 T a pixel
    // 0900 JMP 0900H: no port is written, PA0 has no edge to take.
    r.s.machine().load(0x0900, std::vector<std::uint8_t>{0xC3, 0x00, 0x09});
    r.s.machine().cpu().regs().pc = 0x0900;
    r.s.machine().run_until(r.s.machine().now() + 100'000);
    // A click 10 pixels left of the right end: 4800 T-states before the present time.
    const std::uint64_t now = r.s.machine().now();
    ASSERT_TRUE(place_cursor(r.p, r.s, kSignalsTraceX + kSignalsTraceW - 10, signals_row(0).centre().y));
    ASSERT_TRUE(r.p.cursors[0]);
    EXPECT_EQ(*r.p.cursors[0] + 4800, now);
}

TEST(SignalsPane, APinTheBoardLacksOrASpanOutOfRangeIsRefusedAndThePaneStaysClosed) {
    Rig r;
    EXPECT_EQ(open_signals(r.p, r.s, {"PA9"}, 10).status, script::Session::Status::Failed);
    EXPECT_EQ(open_signals(r.p, r.s, {"PA0"}, 0).status, script::Session::Status::Failed);
    EXPECT_EQ(open_signals(r.p, r.s, {"PA0"}, 1001).status, script::Session::Status::Failed);
    EXPECT_EQ(open_signals(r.p, r.s, {}, 10).status, script::Session::Status::Failed);
    EXPECT_FALSE(r.p.open);
    EXPECT_FALSE(r.s.machine().has_probe(&r.s.signal_trace()));
}

}  // namespace
}  // namespace alp85::gui
