// Intel 8279 programmable keyboard/display interface.
//
// Pins as modelled (this chip knows nothing of the CPU or the board):
//   DB0-7, RD, WR, CS, A0   -> read(a0, now) / write(a0, value, now); A0 = 1: command/status,
//                              A0 = 0: data (FIFO/sensor RAM or display RAM)
//   RESET                   -> reset(now)
//   CLK                     -> one pulse per CPU T-state (CLK OUT); divided by the prescaler (2..31)
//                              into the internal clock
//   IRQ                     -> irq(), on_irq() callback (the board: RST 5.5)
//   SL0-3                   -> scan_lines(now); the return-lines source is called with them
//   RL0-7                   -> set_return_lines_source(fn): pin levels for a given SL0-3 value
//                              (1 = open/high, a closed key pulls its line low); the board calls
//                              inputs_changed(now) whenever what the source returns changes
//   SHIFT, CNTL/STB         -> set_shift(level, now), set_cntl_stb(level, now) (pulled up: 1)
//   OUT A0-3, OUT B0-3, BD  -> digit_output(position): the byte the digit at that position shows
//                              (A nibble = RAM bits 7-4, B nibble = bits 3-0, blanking applied)
//
// Time is a count of CPU T-states; calls pass a non-decreasing `now`. Scanning is evaluated lazily:
// while no key is pressed or being debounced, catching up is O(1) and next_event() is kNever.
//
// Timing model (data sheet: 100 kHz internal clock gives 5.1 ms scan and 10.3 ms debounce): one digit
// (scan) time is 64 internal clocks (480 us digit-on + 160 us blanking at 100 kHz); the keyboard row
// SL0-2 (SL0-1 decoded) is sampled at the start of each digit time; a key is entered when it is still
// closed two full keyboard scans after it was first seen (2 x 8 x 64 = 1024 clocks = 10.24 ms).
//
// Not emulated (honest list):
//   - electrical timing, the BD (blank display) pin and the segment-level multiplexing waveform:
//     digit_output() is the steady picture, not the instant-by-instant scan;
//   - the exact order in which the silicon clears display RAM: a clear writes the whole RAM at once
//     and display writes are ignored for the 16 internal clocks (160 us at 100 kHz) that DU is set;
//   - the return lines are sampled with SL3 = 0 in encoded mode (the keyboard uses SL0-2 only);
//   - right entry without auto-increment: every data write shifts the display by one position;
//   - the prescaler's divider restarts on a program-clock command (its phase is not modelled);
//   - FIFO status bits F and NNN read 0 in the sensor-matrix modes.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "peripherals/part.h"

namespace alp85::periph {

class I8279 final : public Part {
public:
    static constexpr unsigned kClocksPerDigit = 64;  // internal clocks per scan (digit) time
    static constexpr unsigned kClearClocks = 16;     // display unavailable after a clear

    // Status word bits.
    static constexpr std::uint8_t kStDU = 0x80;  // display unavailable (clearing)
    static constexpr std::uint8_t kStSE = 0x40;  // sensor closure / special error
    static constexpr std::uint8_t kStO = 0x20;   // overrun
    static constexpr std::uint8_t kStU = 0x10;   // underrun
    static constexpr std::uint8_t kStF = 0x08;   // FIFO full
    static constexpr std::uint8_t kStCount = 0x07;

    enum class KeyMode : std::uint8_t {
        Encoded2KeyLockout = 0,
        Decoded2KeyLockout = 1,
        EncodedNKeyRollover = 2,
        DecodedNKeyRollover = 3,
        EncodedSensor = 4,
        DecodedSensor = 5,
        StrobedEncoded = 6,
        StrobedDecoded = 7,
    };

    struct State {
        std::array<std::uint8_t, 16> display_ram{};
        std::array<std::uint8_t, 8> fifo{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};  // FIFO / sensor RAM
        std::uint8_t fifo_head = 0;
        std::uint8_t fifo_count = 0;
        std::uint8_t mode = 0x08;      // D D K K K of the last mode set (reset: 16 digits left, encoded 2KL)
        std::uint8_t prescaler = 31;   // reset value
        bool read_display = false;     // data reads: display RAM (else FIFO/sensor RAM)
        std::uint8_t display_address = 0;
        bool display_ai = false;
        std::uint8_t sensor_address = 0;
        bool sensor_ai = false;
        std::uint8_t inhibit_blank = 0;  // IW A, IW B, BL A, BL B (bits 3..0)
        std::uint8_t blank_code = 0x00;  // pattern of the last clear command
        std::uint8_t right_offset = 0;   // right entry: how far the display has shifted
        bool overrun = false;
        bool underrun = false;
        bool error = false;              // special error mode: multiple closure
        bool special_error_mode = false;
        bool sensor_irq = false;
        bool irq = false;                // IRQ pin level
        std::uint64_t du_until = 0;      // display unavailable before this T-state
        bool shift = true;               // pin levels (internal pull-ups)
        bool cntl = true;
        // Scan timing: internal clock c happens at origin_t + (c - origin_clk) * prescaler.
        std::uint64_t origin_t = 0;
        std::uint64_t origin_clk = 0;
        std::uint64_t next_digit = 0;    // next digit time (scan step) to process
        // Keyboard.
        std::array<std::uint8_t, 8> matrix{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};  // RL per row
        bool dirty = false;              // the matrix changed since the scan last settled
        std::uint8_t quiet = 0;          // consecutive digit times without a change
        std::int8_t candidate = -1;      // 2-key lockout: key being debounced (row * 8 + column)
        bool candidate_multi = false;    //   another key was seen during its debounce
        std::uint64_t candidate_digit = 0;
        std::int8_t locked = -1;         // 2-key lockout: entered key still held
        std::array<std::uint8_t, 64> nkro{};        // N-key rollover: 0 open, 1 debouncing, 2 entered
        std::array<std::uint64_t, 64> nkro_digit{};  //   digit time at which debouncing began
        std::uint64_t now = 0;

        // The fields of a snapshot, in order (one list for save and load).
        template <class S, class Io>
        static void fields(S& s, Io& io) {
            io(s.display_ram), io(s.fifo), io(s.fifo_head), io(s.fifo_count), io(s.mode), io(s.prescaler);
            io(s.read_display), io(s.display_address), io(s.display_ai), io(s.sensor_address), io(s.sensor_ai);
            io(s.inhibit_blank), io(s.blank_code), io(s.right_offset), io(s.overrun), io(s.underrun), io(s.error);
            io(s.special_error_mode), io(s.sensor_irq), io(s.irq), io(s.du_until), io(s.shift), io(s.cntl);
            io(s.origin_t), io(s.origin_clk), io(s.next_digit), io(s.matrix), io(s.dirty), io(s.quiet);
            io(s.candidate), io(s.candidate_multi), io(s.candidate_digit), io(s.locked), io(s.nkro);
            io(s.nkro_digit), io(s.now);
        }
    };

    using ReturnLinesFn = std::function<std::uint8_t(std::uint8_t scan_lines)>;
    using LevelFn = std::function<void(bool level, std::uint64_t at)>;

    I8279() = default;

    // Part
    std::string_view name() const override { return "8279"; }
    void describe(Description& d) const override;
    // SL0-3 (scan_lines), BD and IRQ. BD (blank display, active low) follows this model's digit
    // time: low for its last kBlankClocks internal clocks (the 160 us blanking of the 640 us digit
    // time at 100 kHz), high for the first 48; the segment outputs themselves are not pins here.
    void pins(Pins& p, std::uint64_t now) const override;
    std::uint64_t next_pin_change(std::uint64_t now) const override;
    static constexpr unsigned kBlankClocks = 16;
    bool blanking(std::uint64_t now) const;
    std::string_view tag() const override { return "8279"; }
    std::uint8_t state_version() const override { return 2; }
    void reset(std::uint64_t now) override;
    void advance(std::uint64_t now) override;
    std::uint64_t next_event() const override;
    std::uint64_t now() const override { return s_.now; }
    void save_state(StateWriter& w) const override { State::fields(s_, w); }
    void load_state(StateReader& r) override;

    std::uint8_t read(std::uint8_t a0, std::uint64_t now);
    void write(std::uint8_t a0, std::uint8_t value, std::uint64_t now);
    // Pins.
    void set_return_lines_source(ReturnLinesFn fn) { source_ = std::move(fn); }
    void inputs_changed(std::uint64_t now);
    void set_shift(bool level, std::uint64_t now);
    void set_cntl_stb(bool level, std::uint64_t now);
    void on_irq(LevelFn fn) { on_irq_ = std::move(fn); }
    bool irq() const { return s_.irq; }

    // Display outputs: position 0 is the leftmost digit (scan 0).
    unsigned display_digits() const;  // 4 (decoded scan), 8 or 16
    std::uint8_t digit_output(unsigned position) const;

    // Debugger views (no side effects).
    const State& state() const { return s_; }
    std::uint8_t peek_status(std::uint64_t now) const;
    KeyMode key_mode() const { return static_cast<KeyMode>(s_.mode & 7); }
    bool sixteen_digits() const { return (s_.mode & 0x08) != 0; }
    bool right_entry() const { return (s_.mode & 0x10) != 0; }
    std::uint8_t scan_lines(std::uint64_t now) const;
    std::uint64_t digit_time() const { return std::uint64_t{kClocksPerDigit} * s_.prescaler; }  // T-states

private:
    bool decoded() const { return (s_.mode & 1) != 0; }
    bool sensor_mode() const { return (s_.mode & 6) == 4; }
    bool strobed_mode() const { return (s_.mode & 6) == 6; }
    bool nkro_mode() const { return (s_.mode & 6) == 2; }
    unsigned rows() const { return decoded() ? 4 : 8; }
    std::uint64_t debounce_digits() const { return 2ull * rows(); }  // two full keyboard scans
    unsigned address_wrap() const { return sixteen_digits() ? 16 : 8; }
    std::uint8_t scan_value(unsigned row) const;
    std::uint64_t clk_at(std::uint64_t t) const;
    std::uint64_t time_of_digit(std::uint64_t d) const;
    bool busy() const;
    void process_digit(std::uint64_t d);
    void push_fifo(std::uint8_t entry, std::uint64_t at);
    std::uint8_t key_entry(int key) const;
    void update_irq(std::uint64_t at);
    bool may_change() const;
    void mark_dirty();
    void resample();
    void resync(std::uint64_t now);
    void command(std::uint8_t value, std::uint64_t now);

    State s_;
    ReturnLinesFn source_;
    LevelFn on_irq_;
};

}  // namespace alp85::periph
