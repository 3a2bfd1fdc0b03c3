// Helpers for the monitor tests: a board with the monitor ROM (the build's embedded copy), keys
// pressed as a user would (held 30 ms, 30 ms apart), and the monitor's documented RAM layout
// (docs/monitor.md, firmware/monitor/monitor.inc).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>

#include "emu/program/image_loader.h"
#include "emu/board/key_press.h"
#include "emu/board/machine.h"
#include "monitor_embed.h"

namespace alp85::test {

using periph::Key;

// docs/monitor.md, "RAM".
inline constexpr std::uint16_t kSaveC = 0x20B0, kSaveB = 0x20B1, kSaveE = 0x20B2, kSaveD = 0x20B3,
                               kSaveF = 0x20B4, kSaveA = 0x20B5, kSaveHL = 0x20B6, kSaveSP = 0x20B8,
                               kSavePC = 0x20BA, kSaveIM = 0x20BC;
// docs/monitor.md, "Entry points".
inline constexpr std::uint16_t kAus = 0x05A8, kUmw = 0x05C9, kAnwein = 0x0701, kAnwazl = 0x07BC, kAnwaus = 0x07C7;

// A number as the monitor shows it: hex digits with the glyphs 0-9 A b C d E F.
inline std::string hex(unsigned v, int digits) {
    static constexpr char kGlyph[] = "0123456789AbCdEF";
    std::string s;
    for (int i = digits - 1; i >= 0; --i) s += kGlyph[(v >> (4 * i)) & 15];
    return s;
}

inline std::uint64_t ms(double v) { return Machine::tstates_from_ms(v); }

class Board {
public:
    Board() {
        m.load(firmware::kMonitorRom_origin,
               std::span<const std::uint8_t>(firmware::kMonitorRom, firmware::kMonitorRom_size));
        m.reset();
    }

    LoadedImage load(const std::string& program) {
        return load_image(m, std::string(ALP85_MONITOR_PROGRAMS) + "/" + program);
    }

    void run_ms(double v) { m.run_for(ms(v)); }

    void press(Key k, double hold_ms = 30, double gap_ms = 30) {
        press_button(m, Button::Matrix, k, ms(hold_ms), ms(gap_ms));
    }
    void type(std::initializer_list<Key> keys) {
        for (Key k : keys) press(k);
    }
    void vect() { press_button(m, Button::Vect, Key::K0); }

    // Runs until the display reads `text` (true) or the timeout passes (false).
    bool wait_display(const std::string& text, double timeout_ms = 1000) {
        m.run_for(ms(timeout_ms), [&] { return m.display_text() == text; });
        return m.display_text() == text;
    }
    bool wait_halt(double timeout_ms = 1000) {
        m.run_for(ms(timeout_ms), [&] { return m.cpu().halted(); });
        return m.cpu().halted();
    }

    void type_hex(std::uint16_t v) {
        for (int shift = 12; shift >= 0; shift -= 4) press(static_cast<Key>((v >> shift) & 15));
    }
    // GO, the address, EXEC: as thesis Appendix C starts its firmware (R 7 ... is the same).
    void go(std::uint16_t address) {
        press(Key::Go);
        type_hex(address);
        press(Key::Exec);
    }

    struct Saved {
        std::uint8_t a, f, b, c, d, e, im;
        std::uint16_t hl, sp, pc;
    };
    Saved saved() const {
        return {byte(kSaveA), byte(kSaveF),  byte(kSaveB),  byte(kSaveC),  byte(kSaveD),
                byte(kSaveE), byte(kSaveIM), word(kSaveHL), word(kSaveSP), word(kSavePC)};
    }

    std::string display() const { return m.display_text(); }
    std::uint8_t byte(std::uint16_t a) const { return m.peek(a); }
    std::uint16_t word(std::uint16_t a) const {
        return static_cast<std::uint16_t>(m.peek(a) | m.peek(static_cast<std::uint16_t>(a + 1)) << 8);
    }

    Machine m;
};

}  // namespace alp85::test
