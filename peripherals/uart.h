// An asynchronous serial line as a UART frames it, timed in the CPU's T-states: a start bit
// (space, 0), 5 to 8 data bits least significant first, an optional parity bit, 1 or 2 stop bits
// (mark, 1); the idle line is at mark. The ALP 85 has no UART: a program bit-bangs SOD and
// samples SID (RIM/SIM), and a terminal on those pins (serial_terminal.h) uses these models.
//
// Time: bit k of a frame that starts at T-state s begins at s + floor(k * clock / baud), so a
// rate that does not divide the clock (110 baud: 27 927.27 T-states at 3.072 MHz) keeps its
// average exactly and no error piles up within a frame. The receiver samples as a real UART
// does: it waits for a falling edge, then looks at the middle of each bit,
// s + floor((2k + 1) * clock / (2 * baud)); a start bit that is high again in its middle is a
// glitch, and a stop bit that is low is a framing error. Only the first stop bit is checked.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "peripherals/state_io.h"

namespace alp85::periph {

enum class Parity : std::uint8_t { None, Even, Odd };

struct UartFormat {
    static constexpr std::uint32_t kMinBaud = 50, kMaxBaud = 115200;

    std::uint32_t baud = 9600;
    std::uint8_t data_bits = 8;  // 5..8
    Parity parity = Parity::None;
    std::uint8_t stop_bits = 1;  // 1 or 2

    unsigned frame_bits() const { return 1u + data_bits + (parity == Parity::None ? 0u : 1u) + stop_bits; }
    // T-states from a frame's start bit to the end of its stop bits at `clock` Hz.
    std::uint64_t frame_tstates(std::uint64_t clock) const { return frame_bits() * clock / baud; }
    // The bit after the data bits for `value` (its low data_bits bits); only with parity.
    bool parity_bit(std::uint8_t value) const;
    std::string text() const;  // "9600,8N1"
    friend bool operator==(const UartFormat&, const UartFormat&) = default;
};

// "9600" or "9600,8N1", "110,7E2", "1200,8O1" (case-insensitive). nullopt with `why` otherwise.
std::optional<UartFormat> parse_uart_format(std::string_view text, std::string& why);

// A character as the receiver took it.
struct UartChar {
    enum class Error : std::uint8_t { None, Parity, Framing };
    std::uint8_t value = 0;  // the data bits (a framing error: as sampled)
    std::uint64_t at = 0;    // the T-state of the stop bit's sample
    Error error = Error::None;
    bool is_break() const { return error == Error::Framing && value == 0; }  // the line held at space
};

// Sends characters on a line: its level, changing at the bit boundaries.
class UartTransmitter {
public:
    struct State {
        std::vector<std::uint8_t> queue;  // characters handed over; queue[head] is the next to send
        std::uint32_t head = 0;           // (a long input is not moved up a character at a time)
        bool sending = false;             // queue[head] is on the line
        std::uint64_t start = 0;          // its start bit (sending), or when the next may start
        std::uint8_t bit = 0;             // the next bit boundary (0 = the start bit)
        bool level = true;                // the line
        template <class S, class Io> static void fields(S& s, Io& io) {
            io(s.queue), io(s.head), io(s.sending), io(s.start), io(s.bit), io(s.level);
        }
    };

    UartTransmitter(std::uint64_t clock, UartFormat format, std::uint64_t gap)
        : clock_(clock), format_(format), gap_(gap) {}

    // A character handed over at T-state `at`: it starts when the line is free and `gap` T-states
    // have passed since the last one's stop bits (at once if the line was idle that long).
    void send(std::uint8_t value, std::uint64_t at);
    // Moves the line through every bit boundary up to `now`, calling on_level(level, t) at each
    // change.
    void advance(std::uint64_t now, const std::function<void(bool, std::uint64_t)>& on_level);
    // The next bit boundary (Part::kNever when idle).
    std::uint64_t next_event() const;
    bool level() const { return s_.level; }
    bool busy() const { return s_.head < s_.queue.size(); }
    const UartFormat& format() const { return format_; }
    std::uint64_t gap() const { return gap_; }
    const State& state() const { return s_; }
    // A state read back from a snapshot: false if it cannot be this transmitter's.
    bool valid(const State& s) const {
        return s.bit <= format_.frame_bits() && s.head <= s.queue.size() && s.sending == (s.head < s.queue.size());
    }
    void set_state(State s) { s_ = std::move(s); }

private:
    bool bit_level(unsigned k) const;  // the level from boundary k of queue[head]'s frame on

    std::uint64_t clock_;
    UartFormat format_;
    std::uint64_t gap_;
    State s_;
};

// Takes characters off a line from its edges.
class UartReceiver {
public:
    struct State {
        bool level = true;        // the line
        bool framing = false;     // a start edge was seen: sampling a frame
        std::uint64_t start = 0;  // that edge
        std::uint8_t bit = 0;     // the next bit to sample (0 = the start bit)
        std::uint16_t bits = 0;   // sampled so far, bit k of the frame in bit k
        template <class S, class Io> static void fields(S& s, Io& io) {
            io(s.level), io(s.framing), io(s.start), io(s.bit), io(s.bits);
        }
    };
    using Sink = std::function<void(const UartChar&)>;

    UartReceiver(std::uint64_t clock, UartFormat format) : clock_(clock), format_(format) {}

    // The line as it is when the receiver is connected (no edge).
    void set_level(bool level) { s_.level = level; }
    // The line changes to `level` at T-state t (non-decreasing). A sample at the same T-state as
    // an edge sees the new level.
    void edge(bool level, std::uint64_t t, const Sink& sink);
    // Takes every sample before `now`.
    void advance(std::uint64_t now, const Sink& sink);
    const UartFormat& format() const { return format_; }
    const State& state() const { return s_; }
    bool valid(const State& s) const { return s.bit <= format_.frame_bits() && (s.framing || s.bit == 0); }
    void set_state(State s) { s_ = s; }

private:
    std::uint64_t sample_time(unsigned k) const;
    void take_samples_before(std::uint64_t t, const Sink& sink);

    std::uint64_t clock_;
    UartFormat format_;
    State s_;
};

}  // namespace alp85::periph
