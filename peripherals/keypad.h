// A keypad as a key matrix on the 8279's scan and return lines (board level). Where each key sits
// is the board's (its description places the keys, Keypad::place); a keypad not placed by a board
// has the ALP 85's matrix, which layout() lists.
//
// The real ALP 85 matrix is not documented; this is a design in the manner of Intel's SDK-85:
// SL0-2 are decoded (74LS138-style, active low) into eight row lines; rows 0 and 1 carry the hex
// keys 0-F on RL0-7, row 2 the function keys. SHIFT and CNTL are grounded on the board, so a key's
// 8279 FIFO code is simply row * 8 + return line (hex keys 00H-0FH, function keys 10H-17H).
// RESET and VECT INTR are not in the matrix: the board wires them to the CPU's RESET IN and RST 7.5.
// The full layout is in docs/peripherals.md.
//
// Not emulated: contact bounce (the 8279's debounce sees clean make/break), ghosting between three
// or more closed keys, SL3 (the decoder is enabled for all sixteen scan values).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "peripherals/part.h"

namespace alp85::periph {

enum class Key : std::uint8_t {
    K0, K1, K2, K3, K4, K5, K6, K7, K8, K9, KA, KB, KC, KD, KE, KF,
    Exec,  // terminal key: ends an entry, executes (SDK-85 "EXEC")
    Next,  // terminal key: next field / next address (SDK-85 "NEXT")
    Go,    // run from an address
    Mem,   // examine/substitute memory
    Reg,   // examine registers
    Step,  // single step
    Prev,  // previous field / address
    R,     // monitor command key ("R", then a command number)
};

struct KeyInfo {
    Key key;
    std::string_view name;   // stable name for scripts and front ends
    std::string_view label;  // what the keycap says
    std::uint8_t row;        // scan line (SL0-2 value)
    std::uint8_t column;     // return line RL0-7
    std::uint8_t code() const { return static_cast<std::uint8_t>(row * 8 + column); }  // FIFO code
};

class Keypad final : public Part {
public:
    // Part: keys are contacts, with no reset and no clock of their own; the keypad only follows
    // the machine's time so that a snapshot can check it.
    std::string_view name() const override { return "keypad"; }
    void describe(Description& d) const override;
    std::string_view tag() const override { return "KEYS"; }
    std::uint8_t state_version() const override { return 2; }
    void reset(std::uint64_t) override {}
    void advance(std::uint64_t now) override { now_ = now; }
    std::uint64_t now() const override { return now_; }
    void save_state(StateWriter& w) const override { w(now_), w(closed_); }
    void load_state(StateReader& r) override;

    static constexpr std::size_t kKeyCount = 24;

    static std::span<const KeyInfo, kKeyCount> layout();
    static const KeyInfo& info(Key key);
    static std::optional<Key> find(std::string_view name);  // by name, case-insensitive
    static std::optional<Key> from_code(std::uint8_t fifo_code);  // ignores the CNTL/SHIFT bits

    void press(Key key) { set(key, true); }
    void release(Key key) { set(key, false); }
    void set(Key key, bool down);  // a key this board lacks: ignored
    void release_all() { closed_.fill(0); }
    bool is_pressed(Key key) const;

    // The board's matrix: none of the keys (clear), then each key on its scan line and return line.
    void clear_places();
    void place(Key key, std::uint8_t row, std::uint8_t column);
    bool has(Key key) const { return place_[static_cast<std::size_t>(key)] != kNowhere; }

    // RL0-7 levels for the given SL0-3 value: a closed key on the selected row pulls its line low.
    std::uint8_t return_lines(std::uint8_t scan_lines) const;

private:
    static constexpr std::uint8_t kNowhere = 0xFF;
    static std::array<std::uint8_t, kKeyCount> layout_places();

    std::array<std::uint8_t, kKeyCount> place_ = layout_places();  // row * 8 + column, or kNowhere
    std::array<std::uint8_t, 8> closed_{};  // per row: bit n = key on RL n is down
    std::uint64_t now_ = 0;
};

}  // namespace alp85::periph
