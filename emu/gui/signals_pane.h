// The Signals pane (docs/signals.md): a logic analyzer in the window. The pins chosen (a picker
// over every pin `record signals` names) are drawn as traces over the last N ms of machine time.
// The Session's SignalTrace records them while the machine runs, through the same probes as a VCD
// recording; when the machine stops (a breakpoint, Pause) the traces stand still. Two cursors,
// placed by clicks on the traces (an edge of the pin clicked, when one is near, else the time
// under the pointer), read the time between them in T-states and microseconds.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emu/script/session.h"

namespace alp85::gui {

struct SignalsPane {
    static constexpr int kDefaultSpanMs = 10;
    static constexpr int kMaxSpanMs = 1000;
    static constexpr float kSnapPixels = 6;  // a click this near an edge takes the edge

    bool open = false;
    std::vector<std::string> pins;  // the words traced ("PA0", "X.PULSE", "8155.PA0")
    int span_ms = kDefaultSpanMs;
    std::array<std::optional<std::uint64_t>, 2> cursors;  // A and B, T-states from power-on
    int next_cursor = 0;  // the one the next click places
    std::vector<debug::PinTap::PinName> names;  // the picker's list (read when the pane opens)
    std::string error;  // the Session's answer to the last choice that failed
};

// Opens the pane on `pins` over `span_ms` ms (1 to kMaxSpanMs): the Session traces them from now on.
// Failed (and the pane left closed) when a word names no pin or the span is out of range.
script::Session::Outcome open_signals(SignalsPane& p, script::Session& s, const std::vector<std::string>& pins, int span_ms);
// Shows the pane with nothing traced yet (the picker chooses).
void show_signals(SignalsPane& p, const script::Session& s);
// Closes it: the trace comes off the board.
void close_signals(SignalsPane& p, script::Session& s);
// Draws the pane when open (at kSignalsRect); the choices made in it go to `s`.
void draw_signals_pane(SignalsPane& p, script::Session& s);
// A click at (x, y) of the window: on a pin's row of the traces, the next cursor goes to the edge of
// that pin nearest the click within kSnapPixels, else to the T-state under the pointer. Returns
// whether the click was on the traces.
bool place_cursor(SignalsPane& p, const script::Session& s, float x, float y);
// What the cursors read: "A at T 123, B at T 3278: B - A = 3155 T = 1027.018 µs", or how to place them.
std::string cursor_readout(const SignalsPane& p);

}  // namespace alp85::gui
