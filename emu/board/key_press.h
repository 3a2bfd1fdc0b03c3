// Pressing a key as a user does: down now, up after the hold, then the gap before the next one.
// The one definition the script session and the monitor tests share.
#pragma once

#include <cstdint>
#include <optional>

#include "emu/board/board_map.h"
#include "emu/board/machine.h"

namespace alp85 {

inline constexpr std::uint64_t kKeyHold = board::tstates_from_ms(30);  // 92160 T-states
inline constexpr std::uint64_t kKeyGap = board::tstates_from_ms(30);

// The keypad's matrix keys, and the two keys outside it (RESET IN, VECT INTR = RST 7.5): the one
// enum of the board's buttons, for the script's keys (KeyRef), the window's and the page's keypad (PadKey).
enum class Button : std::uint8_t { Matrix, Reset, Vect };

// The one place a key's level is scheduled: a keypad matrix key, RESET or VECT INTR, pressed
// (`down`) or released at machine time `at`.
inline void schedule_key(Machine& m, Button button, periph::Key key, bool down, std::uint64_t at) {
    switch (button) {
        case Button::Matrix: m.key_at(key, down, at); break;
        case Button::Reset: m.reset_key_at(down, at); break;
        case Button::Vect: m.vect_intr_at(down, at); break;
    }
}

// Schedules a press of `button` (for Matrix: `key`) at `at` (default: the machine's present time)
// and its release `hold` later; returns when the gap after it ends (at + hold + gap): run the
// machine until then, or schedule the next press there.
inline std::uint64_t schedule_press(Machine& m, Button button, periph::Key key, std::uint64_t hold = kKeyHold,
                                    std::uint64_t gap = kKeyGap, std::optional<std::uint64_t> at = {}) {
    const std::uint64_t t = at.value_or(m.now());
    schedule_key(m, button, key, true, t);
    schedule_key(m, button, key, false, t + hold);
    return t + hold + gap;
}

// schedule_press, then run until the gap has passed (or the observer stops the run).
inline Machine::RunEnd press_button(Machine& m, Button button, periph::Key key, std::uint64_t hold = kKeyHold,
                                  std::uint64_t gap = kKeyGap) {
    return m.run_until(schedule_press(m, button, key, hold, gap));
}

}  // namespace alp85
