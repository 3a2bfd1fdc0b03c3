// A serial terminal on the 8085's SID and SOD pins (an accessory, not on the thesis's board): its
// transmit data drives SID, its receive data listens to SOD, both at one baud rate and frame
// (uart.h). A program on the ALP 85 talks to it by bit-banging SOD with SIM and sampling SID
// with RIM, as the SDK-85's monitor talks to a teletype (firmware/demo/echo85.asm).
//
// Pins (the board wires them, Machine::connect_serial):
//   TXD -> SID: on_txd(level, t) at each change (idle: mark, 1)
//   RXD <- SOD: sod(level, t) at each change the 8085 makes
// Characters to send come from the front end (Machine::serial_at, through the input queue, so
// the debugger replays them); the characters received go to on_receive and, the last
// kTextKept of them, into the state (a window's Terminal pane shows them, and a snapshot takes
// them back with the machine).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "peripherals/part.h"
#include "peripherals/uart.h"

namespace alp85::periph {

class SerialTerminal final : public Part {
public:
    static constexpr std::size_t kTextKept = 4096;  // received characters the state keeps

    // `gap`: T-states of idle line the terminal leaves between the characters it sends.
    SerialTerminal(std::uint64_t clock, UartFormat format, std::uint64_t gap);

    std::string_view name() const override { return "serial terminal"; }
    void describe(Description& d) const override;
    std::string_view tag() const override { return "SERL"; }
    std::uint8_t state_version() const override { return 1; }
    // The terminal is not on RESET OUT: a RESET of the board leaves it alone.
    void reset(std::uint64_t now) override { advance(now); }
    void advance(std::uint64_t now) override;
    std::uint64_t next_event() const override { return tx_.next_event(); }
    std::uint64_t now() const override { return now_; }
    void save_state(StateWriter& w) const override;
    void load_state(StateReader& r) override;

    // ---- pins ---------------------------------------------------------------------------------
    void on_txd(std::function<void(bool level, std::uint64_t t)> fn) { on_txd_ = std::move(fn); }
    bool txd() const { return tx_.level(); }
    // SOD changed to `level` at T-state t (not before now()).
    void sod(bool level, std::uint64_t t);
    // SOD's level when the terminal is connected (no edge).
    void set_sod_level(bool level) { rx_.set_level(level); }

    // ---- the keyboard and the screen ----------------------------------------------------------
    // A character typed at T-state `at`: sent when the line is free (UartTransmitter::send).
    void type(std::uint8_t value, std::uint64_t at) { tx_.send(value, at); }
    bool sending() const { return tx_.busy(); }
    void on_receive(std::function<void(const UartChar&)> fn) { on_receive_ = std::move(fn); }
    // The last kTextKept characters received without an error, oldest first.
    const std::vector<std::uint8_t>& text() const { return text_; }
    std::uint64_t received() const { return received_; }  // characters taken, errors included
    std::uint64_t errors() const { return errors_; }      // of them with a framing or parity error
    const UartFormat& format() const { return tx_.format(); }
    std::uint64_t gap() const { return tx_.gap(); }

private:
    void take(const UartChar& c);

    UartTransmitter tx_;
    UartReceiver rx_;
    std::function<void(bool, std::uint64_t)> on_txd_;
    std::function<void(const UartChar&)> on_receive_;
    std::vector<std::uint8_t> text_;
    std::uint64_t received_ = 0, errors_ = 0;
    std::uint64_t now_ = 0;
};

}  // namespace alp85::periph
