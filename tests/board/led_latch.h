// A toy part for the tests: eight LEDs latched by OUT, with a heartbeat clock. It is added to a
// machine in one line (Machine::attach) and describes itself (two registers: the latch and the
// heartbeat count), so every debugger front end shows it without knowing what it is
// (tests/board/part_test.cpp, tests/dap/part_view_test.cpp, tests/gui).
#pragma once

#include <algorithm>
#include <bit>
#include <string>

#include "emu/core/bus.h"
#include "peripherals/part.h"

namespace alp85::test {

// Eight LEDs latched by OUT 00H; it integrates how long the LEDs were lit (T-states x lit LEDs)
// and ticks a heartbeat every 1000 T-states (an event the scheduler must stop at).
class LedLatch final : public periph::Part, public IoDevice {
public:
    struct State {
        std::uint8_t value = 0;
        std::uint64_t lit = 0;    // LED-T-states
        std::uint64_t beats = 0;  // heartbeats seen
        std::uint64_t now = 0;
        template <class S, class Io>
        static void fields(S& s, Io& io) { io(s.value), io(s.lit), io(s.beats), io(s.now); }
    };
    static constexpr std::uint64_t kBeat = 1000;

    std::string_view name() const override { return "leds"; }
    std::string_view tag() const override { return "LEDS"; }
    std::uint8_t state_version() const override { return 1; }
    void reset(std::uint64_t) override { s.value = 0; }
    void advance(std::uint64_t now) override {
        s.lit += (now - s.now) * static_cast<unsigned>(std::popcount(s.value));
        s.beats = now / kBeat;
        s.now = now;
    }
    std::uint64_t next_event() const override { return (s.now / kBeat + 1) * kBeat; }
    std::uint64_t now() const override { return s.now; }
    void save_state(StateWriter& w) const override { State::fields(s, w); }
    void load_state(StateReader& r) override {
        State n;
        State::fields(n, r);
        r.expect_end();
        s = n;
    }
    void describe(periph::Description& d) const override {
        d.title = "LED latch (a toy part)";
        d.add(periph::Field::hex("latch", s.value, 8, std::to_string(std::popcount(s.value)) + " lit")).watched_as("latch");
        d.add(periph::Field::decimal("heartbeats", static_cast<std::int64_t>(std::max(d.now, s.now) / kBeat))).watched_as("beats");
    }
    std::uint8_t in(std::uint8_t, std::uint64_t) override { return s.value; }
    void out(std::uint8_t, std::uint8_t v, std::uint64_t t) override {
        advance(t);
        s.value = v;
    }

    State s;
};

}  // namespace alp85::test
