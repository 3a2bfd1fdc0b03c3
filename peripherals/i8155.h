// Intel 8155/8156: 256 x 8 static RAM, two 8-bit ports (A, B), one 6-bit port (C), 14-bit timer.
//
// Pins as modelled (the board wires them; this chip knows nothing of the CPU or the board):
//   AD0-AD7, ALE, IO/M, RD, WR, CE  -> read()/write() with an I/O offset (IO/M high) and
//                                      read_memory()/write_memory() (IO/M low); the board decodes
//                                      CE (8155: active low, 8156: active high — the same model).
//   RESET                           -> reset(now)
//   PA0-7, PB0-7, PC0-5             -> input levels: set_port_input() or an input callback;
//                                      output levels: port_output(); on_port_write() callback.
//   PC2 = A STB, PC5 = B STB        -> set_stb(port, level, now) in ALT3/ALT4
//   PC0 = A INTR, PC1 = A BF,
//   PC3 = B INTR, PC4 = B BF        -> intr(), on_intr() callback (BF: read in port C and the status)
//   TIMER IN                        -> one pulse per CPU T-state (CLK OUT): the time base itself
//   TIMER OUT                       -> timer_out(), on_timer_out() callback (the board: TRAP)
//
// Time is a count of CPU T-states; every call passes `now` (non-decreasing). The chip catches up
// lazily and reports its next visible change through next_event().
//
// Not emulated (honest list):
//   - electrical and bus timing (access times, ALE latching, wait states); RAM is plain storage;
//   - TIMER IN from any clock other than CLK OUT (one count per T-state is hard-wired);
//   - counts 0 and 1 (outside the data sheet's 2..3FFFH): they run as the minimum count 2;
//   - the counter value read back while stopped after a single-mode TC is the reloaded count
//     (the data sheet does not say); STOP leaves TIMER OUT at its present level;
//   - bits 6-7 of port C read as 1 (the pins do not exist); I/O offsets 6 and 7 read FFH;
//   - changing the port C mode does not reset the handshake flip-flops (only RESET does).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "peripherals/part.h"

namespace alp85::periph {

class I8155 final : public Part {
public:

    enum class Port : std::uint8_t { A = 0, B = 1, C = 2 };

    // I/O offsets (AD0-AD2) of the data sheet's register map.
    enum Offset : std::uint8_t {
        kCommandStatus = 0,
        kPortA = 1,
        kPortB = 2,
        kPortC = 3,
        kTimerLow = 4,
        kTimerHigh = 5,
    };

    // Command register bits.
    static constexpr std::uint8_t kCmdPaOut = 0x01;
    static constexpr std::uint8_t kCmdPbOut = 0x02;
    static constexpr std::uint8_t kCmdPcMask = 0x0C;  // 00 ALT1, 11 ALT2, 01 ALT3, 10 ALT4
    static constexpr std::uint8_t kCmdIea = 0x10;
    static constexpr std::uint8_t kCmdIeb = 0x20;
    static constexpr std::uint8_t kCmdTimerMask = 0xC0;  // 00 NOP, 01 STOP, 10 STOP after TC, 11 START

    // Status register bits.
    static constexpr std::uint8_t kStIntrA = 0x01;
    static constexpr std::uint8_t kStBfA = 0x02;
    static constexpr std::uint8_t kStInteA = 0x04;
    static constexpr std::uint8_t kStIntrB = 0x08;
    static constexpr std::uint8_t kStBfB = 0x10;
    static constexpr std::uint8_t kStInteB = 0x20;
    static constexpr std::uint8_t kStTimer = 0x40;

    enum class PortCMode : std::uint8_t { Alt1, Alt2, Alt3, Alt4 };

    // Timer output modes (M2 M1 in bits 15-14 of the count length register).
    enum class TimerMode : std::uint8_t {
        SingleSquare = 0,      // 00: low for the second half of the count, once
        ContinuousSquare = 1,  // 01: square wave, reloaded at each TC
        SinglePulse = 2,       // 10: one low pulse at TC
        ContinuousPulse = 3,   // 11: a low pulse at every TC
    };

    // Everything the chip remembers; plain data, inspectable by a debugger.
    struct State {
        std::array<std::uint8_t, 256> ram{};
        std::uint8_t command = 0;                  // bits 0-5 of the last command (6-7 act, not stored)
        std::array<std::uint8_t, 3> latch{};       // output latches A, B, C (C: 6 bits)
        std::array<std::uint8_t, 3> pins{0xFF, 0xFF, 0x3F};  // input levels set by the board
        std::array<std::uint8_t, 2> strobe_latch{};  // strobed-input latches A, B
        std::array<bool, 2> intr_ff{};             // handshake request flip-flops A, B
        std::array<bool, 2> bf{};                  // buffer full A, B
        std::array<bool, 2> stb{true, true};       // STB pin levels A, B (idle high)
        bool timer_flag = false;                   // status bit 6: latched at TC
        std::uint16_t count_length = 0;            // the register as written: count | mode << 14
        bool counted = false;                      // the timer has been started since reset
        bool running = false;
        std::uint16_t count = 2;                   // count in use (2..3FFFH)
        TimerMode mode = TimerMode::SingleSquare;  // mode in use
        std::uint64_t period_start = 0;            // T-state at which the present count began
        bool pending_start = false;                // START while running: reload at the next TC
        bool stop_after_tc = false;
        std::uint16_t held_value = 0;              // counter read-back while stopped (with mode)
        bool timer_out = true;                     // TIMER OUT level
        std::uint64_t pulse_end = kNever;          // end of the one-clock low pulse
        std::uint64_t now = 0;                     // last T-state caught up to

        // The fields of a snapshot, in order (one list for save and load).
        template <class S, class Io>
        static void fields(S& s, Io& io) {
            io(s.ram), io(s.command), io(s.latch), io(s.pins), io(s.strobe_latch);
            for (int i = 0; i < 2; ++i) io(s.intr_ff[i]), io(s.bf[i]), io(s.stb[i]);
            io(s.timer_flag), io(s.count_length), io(s.counted), io(s.running), io(s.count);
            io(s.mode, TimerMode::ContinuousPulse), io(s.period_start), io(s.pending_start);
            io(s.stop_after_tc), io(s.held_value), io(s.timer_out), io(s.pulse_end), io(s.now);
        }
    };

    using InputFn = std::function<std::uint8_t(Port, std::uint64_t now)>;
    using LevelFn = std::function<void(bool level, std::uint64_t at)>;
    using IntrFn = std::function<void(Port, bool level, std::uint64_t at)>;
    using PortWriteFn = std::function<void(Port, std::uint8_t value, std::uint64_t at)>;

    I8155() = default;
    // A second 8155 on one board needs its own name and snapshot tag (four characters).
    I8155(std::string_view name, std::string_view tag) : name_(name), tag_(tag) {}

    // Part
    std::string_view name() const override { return name_; }
    void describe(Description& d) const override;
    // PA0-7, PB0-7, PC0-5 (an input pin: 'z', this chip does not drive it) and TIMER OUT. TIMER IN
    // is CLK OUT, one pulse per T-state: the recording's time base, not a pin of its own.
    void pins(Pins& p, std::uint64_t now) const override;
    std::string_view tag() const override { return tag_; }
    std::uint8_t state_version() const override { return 2; }
    void reset(std::uint64_t now) override;
    void advance(std::uint64_t now) override;
    std::uint64_t next_event() const override;
    std::uint64_t now() const override { return s_.now; }
    void save_state(StateWriter& w) const override { State::fields(s_, w); }
    void load_state(StateReader& r) override;

    // I/O space (IO/M high): offset = AD0-AD2.
    std::uint8_t read(std::uint8_t offset, std::uint64_t now);
    void write(std::uint8_t offset, std::uint8_t value, std::uint64_t now);
    // Memory space (IO/M low): the 256-byte RAM.
    // The RAM itself, for a board that maps it straight into its CPU's page table.
    std::span<std::uint8_t, 256> ram() { return s_.ram; }
    std::uint8_t read_memory(std::uint8_t address) const { return s_.ram[address]; }
    void write_memory(std::uint8_t address, std::uint8_t value) { s_.ram[address] = value; }

    // Pins.
    void set_port_input(Port port, std::uint8_t levels) { s_.pins[static_cast<int>(port)] = levels; }
    void set_input_callback(InputFn fn) { input_ = std::move(fn); }
    void set_stb(Port port, bool level, std::uint64_t now);  // port A or B
    void on_timer_out(LevelFn fn) { on_timer_out_ = std::move(fn); }
    void on_intr(IntrFn fn) { on_intr_ = std::move(fn); }
    void on_port_write(PortWriteFn fn) { on_port_write_ = std::move(fn); }

    bool timer_out() const { return s_.timer_out; }
    bool intr(Port port) const;
    std::uint8_t port_output(Port port) const;  // levels driven on the pins (output bits only)
    std::uint8_t port_output_mask(Port port) const;  // which pins are outputs
    PortCMode port_c_mode() const;

    // Debugger views (no side effects).
    const State& state() const { return s_; }
    std::uint8_t peek_status() const;
    std::uint16_t peek_counter(std::uint64_t now) const;  // what reading offsets 4/5 would give

private:
    std::uint8_t input_levels(Port port, std::uint64_t now) const;
    bool strobed(Port port) const;
    void set_intr_ff(int i, bool v, std::uint64_t at);
    void set_timer_out(bool level, std::uint64_t at);
    void timer_command(std::uint8_t tm, std::uint64_t now);
    void start_count(std::uint64_t at);
    std::uint64_t half_edge_time() const;
    std::uint16_t counter_value(std::uint64_t t) const;
    void timer_event(std::uint64_t t);

    State s_;
    std::string_view name_ = "8155";
    std::string_view tag_ = "8155";
    InputFn input_;
    LevelFn on_timer_out_;
    IntrFn on_intr_;
    PortWriteFn on_port_write_;
};

}  // namespace alp85::periph
