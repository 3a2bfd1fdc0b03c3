// Intel 8355: 2048 x 8 mask ROM and two 8-bit I/O ports (A, B) with a data direction register
// each. The SDK-85's monitor ROM sits in one (0000H-07FFH, ports at I/O 00H-03H).
//
// Pins as modelled (the board wires them; this chip knows nothing of the CPU or the board):
//   AD0-AD7, A8-A10, ALE, IO/M, RD -> read_rom() (IO/M low: the ROM, A10-A0) and read() (IO/M high,
//                                     or IOR low: a port, AD1-AD0); the board decodes CE1/CE2
//   IOW                            -> write() (AD1-AD0 select what is loaded)
//   RESET                          -> reset(now): both DDRs cleared, so every port line is an input
//   PA0-7, PB0-7                   -> input levels: set_port_input() or an input callback;
//                                     output levels: port_output(); on_port_write() callback.
//
// AD1-AD0 select: 00 port A, 01 port B, 10 DDR A, 11 DDR B. A DDR bit 1 makes that port line an
// output driven from the port's output latch; 0 an input. Reading a port gives the output latch's
// bits where the DDR has a 1 and the pins' levels where it has a 0.
//
// The ROM contents are the board's: it loads them (load_rom) and maps rom() into its memory, as
// it does the 8155's RAM, and saves them with its memory, not in this chip's state.
//
// Not emulated (honest list):
//   - electrical and bus timing (access times, ALE latching) and READY (the wait state the chip
//     can ask for on a slow bus; CLK drives nothing else): the SDK-85 runs it without wait states;
//   - the chip enables (CE1 low, CE2 high) and the IOR/RD, IOW/IO/M alternatives: the board
//     decodes them and calls read()/write() only when the chip is selected;
//   - what a read of a DDR address drives on the bus: the data sheet describes the DDRs as loaded
//     by IOW only; this model answers FFH (a floating, pulled-up bus);
//   - the output latches' contents after RESET (the data sheet clears the DDRs; the latches are
//     kept, and drive nothing until a DDR bit is set again).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>

#include "peripherals/part.h"

namespace alp85::periph {

class I8355 final : public Part {
public:
    static constexpr std::size_t kRomSize = 2048;

    enum class Port : std::uint8_t { A = 0, B = 1 };

    // I/O offsets (AD1-AD0) of the data sheet's port selection.
    enum Offset : std::uint8_t {
        kPortA = 0,
        kPortB = 1,
        kDdrA = 2,
        kDdrB = 3,
    };

    // Everything the chip remembers besides its ROM; plain data, inspectable by a debugger.
    struct State {
        std::array<std::uint8_t, 2> latch{};             // output latches A, B
        std::array<std::uint8_t, 2> ddr{};               // data direction A, B (1 = output)
        std::array<std::uint8_t, 2> pins{0xFF, 0xFF};    // input levels set by the board
        std::uint64_t now = 0;                           // last T-state caught up to

        // The fields of a snapshot, in order (one list for save and load).
        template <class S, class Io>
        static void fields(S& s, Io& io) {
            io(s.latch), io(s.ddr), io(s.pins), io(s.now);
        }
    };

    using InputFn = std::function<std::uint8_t(Port, std::uint64_t now)>;
    // A write to a port's output latch or its DDR: the latch as it now is (the levels driven are
    // port_output(), on the lines port_output_mask() names).
    using PortWriteFn = std::function<void(Port, std::uint8_t latch, std::uint64_t at)>;

    I8355() { rom_.fill(0xFF); }

    // Part
    std::string_view name() const override { return "8355"; }
    void describe(Description& d) const override;
    // PA0-7, PB0-7 (an input line: 'z', this chip does not drive it).
    void pins(Pins& p, std::uint64_t now) const override;
    std::string_view tag() const override { return "8355"; }
    std::uint8_t state_version() const override { return 1; }
    void reset(std::uint64_t now) override;
    void advance(std::uint64_t now) override {
        if (now > s_.now) s_.now = now;
    }
    std::uint64_t now() const override { return s_.now; }
    void save_state(StateWriter& w) const override { State::fields(s_, w); }
    void load_state(StateReader& r) override;

    // I/O space (IO/M high or IOR): offset = AD1-AD0 (higher bits ignored).
    std::uint8_t read(std::uint8_t offset, std::uint64_t now);
    void write(std::uint8_t offset, std::uint8_t value, std::uint64_t now);

    // Memory space (IO/M low): the ROM at A10-A0.
    std::uint8_t read_rom(std::uint16_t address) const { return rom_[address & (kRomSize - 1)]; }
    // The ROM itself, for a board that loads it and maps it straight into its CPU's page table.
    std::span<std::uint8_t, kRomSize> rom() { return rom_; }
    std::span<const std::uint8_t, kRomSize> rom() const { return rom_; }
    void load_rom(std::span<const std::uint8_t, kRomSize> image) { std::copy(image.begin(), image.end(), rom_.begin()); }

    // Pins.
    void set_port_input(Port port, std::uint8_t levels) { s_.pins[static_cast<int>(port)] = levels; }
    void set_input_callback(InputFn fn) { input_ = std::move(fn); }
    void on_port_write(PortWriteFn fn) { on_port_write_ = std::move(fn); }

    std::uint8_t port_output(Port port) const;                                   // levels driven (output lines only)
    std::uint8_t port_output_mask(Port port) const { return s_.ddr[static_cast<int>(port)]; }  // which lines are outputs

    // Debugger views (no side effects).
    const State& state() const { return s_; }
    // What reading the port would give now, with the pins as last set (not through the callback).
    std::uint8_t peek_port(Port port) const;

private:
    std::uint8_t input_levels(Port port, std::uint64_t now) const;

    State s_;
    std::array<std::uint8_t, kRomSize> rom_{};
    InputFn input_;
    PortWriteFn on_port_write_;
};

}  // namespace alp85::periph
