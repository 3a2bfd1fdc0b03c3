// The board's keys from a PC, with no window system: which PC key presses which button (the one
// key map of every front end: the window maps SDL's keycodes onto it, the web page the browser's
// key names), the captions, the key map's rows, and the presses themselves. A press closes the key
// now (machine time) and opens it when released, but never sooner than kMinHold after it closed,
// so that the 8279's debounce (two scans, about 10 ms) always sees it: the script's default hold,
// 30 ms of simulated time. Presses quicker than that (several in one frame) are queued: each
// closes kMinGap after the one before opened, the script's default gap, so none is lost.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "emu/script/session.h"

namespace alp85::front {

// A board's keys as its description (through the Session) places them on the front panel. The
// functions without a Session give the default board's, the ALP 85's: its 24 matrix keys and
// RESET, VECT INTR, as docs/peripherals.md arranges them (front view):
//   RESET VECT  R    C D E F
//   REG   MEM   GO   8 9 A B
//   STEP  PREV  NEXT 4 5 6 7
//               EXEC 0 1 2 3
struct PadKey {
    Button pad = Button::Matrix;  // the board's button (its one enum, through the Session)
    periph::Key key = periph::Key::K0;  // for Matrix
    int row = 0, col = 0;
};
std::span<const PadKey> pad_keys();  // 26 buttons
std::optional<PadKey> find_pad_key(std::string_view name);  // "R", "EXEC", "RESET", "VECT", ...
// The same for the session's board (its description's keys, in its order).
std::vector<PadKey> pad_keys(const script::Session& s);
std::optional<PadKey> find_pad_key(std::string_view name, const script::Session& s);

inline constexpr std::uint64_t kMinHold = kKeyHold;
inline constexpr std::uint64_t kMinGap = kKeyGap;
inline constexpr std::uint64_t kQueueLimit = board::tstates_from_ms(2000);

// A PC key by its name ("0"-"9", "A"-"F" for the hex keys, then "Enter", "Space", "Backspace",
// "R", "G", "M", "X", "S", "Esc", "V"), the board key's name (find_pad_key), and the short label
// shown under the keycap.
struct PcKey {
    std::string_view pc, pad, label;
};
// The board key a PC key presses (case-insensitive name as above).
std::optional<PadKey> pad_key_for_pc(std::string_view pc_name);
std::optional<PadKey> pad_key_for_pc(std::string_view pc_name, const script::Session& s);
// What to press on the PC for a button, as shown under its keycap ("Enter", "7", "Esc").
std::string_view pc_key_label(const PadKey& k);
std::string_view pc_key_label(const PadKey& k, const script::Session& s);
// The caption on the keycap ("EXEC", "VECT\nINTR").
std::string_view cap_label(const PadKey& k);
std::string_view cap_label(const PadKey& k, const script::Session& s);
// The session's keypad as the window and the page draw it, all from its board's description: each
// key's stable name (what find_pad_key takes), its caption, the PC key shown under it, its place
// (in PadKey), and whether it is a function key (a hex key 0-F is not).
struct KeypadKey {
    PadKey key;
    std::string_view name, cap, pc;
    bool fn = false;
};
std::vector<KeypadKey> keypad_view(const script::Session& s);
// What the keyboard and the mouse do, as rows of (keys, action), for the key map.
struct KeyMapRow {
    std::string_view keys, action;
};
std::vector<KeyMapRow> key_map_rows(bool debug);
// The same for the session's board: its function keys' PC keys and captions from its description.
std::vector<KeyMapRow> key_map_rows(bool debug, const script::Session& s);

// A line shown under the display while the thesis firmware's feed prompt ("H=----", F in mm/min,
// D = 1500 / F) is typed with the physical motors: F 0006-1500 is accepted, but at F <= 0300
// (D >= 5) the closed loop reads the rotor's swing back as a step back and X runs away
// (docs/results.md). nullopt at every other display.
std::optional<std::string_view> feed_prompt_hint(std::string_view display, bool physical_motors);

class Presser {
public:
    // Button down / up from the mouse or the keyboard (a second down of a held key is ignored).
    // Each goes to the board through Session::key.
    void down(const PadKey& k, script::Session& s);
    void up(const PadKey& k, script::Session& s);
    bool held(const PadKey& k) const;

private:
    struct Held {
        PadKey key;
        std::uint64_t since;
    };
    std::vector<Held> held_;
    std::uint64_t free_at_ = 0;  // machine time from which the next press may close
};

}  // namespace alp85::front
