#include "peripherals/uart.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <limits>

#include <fmt/format.h>

namespace alp85::periph {

bool UartFormat::parity_bit(std::uint8_t value) const {
    const unsigned mask = (1u << data_bits) - 1u;
    const bool odd_ones = std::popcount(value & mask) % 2 != 0;
    // Even parity: the ones of the data and parity bits are even; odd: they are odd.
    return parity == Parity::Even ? odd_ones : !odd_ones;
}

std::string UartFormat::text() const {
    const char p = parity == Parity::None ? 'N' : parity == Parity::Even ? 'E' : 'O';
    return fmt::format("{},{}{}{}", baud, data_bits, p, stop_bits);
}

std::optional<UartFormat> parse_uart_format(std::string_view text, std::string& why) {
    UartFormat f;
    const auto comma = text.find(',');
    const std::string_view rate = text.substr(0, comma);
    std::uint64_t baud = 0;
    const auto [end, ec] = std::from_chars(rate.data(), rate.data() + rate.size(), baud);
    if (rate.empty() || ec != std::errc{} || end != rate.data() + rate.size() || baud < UartFormat::kMinBaud ||
        baud > UartFormat::kMaxBaud) {
        why = fmt::format("bad baud rate '{}' (a whole number from {} to {}, e.g. 9600)", rate, UartFormat::kMinBaud,
                          UartFormat::kMaxBaud);
        return std::nullopt;
    }
    f.baud = static_cast<std::uint32_t>(baud);
    if (comma == std::string_view::npos) return f;
    const std::string_view frame = text.substr(comma + 1);
    const auto bad_frame = [&] {
        why = fmt::format("bad frame '{}' (data bits 5-8, parity N, E or O, stop bits 1 or 2, e.g. 8N1 or 7E1)", frame);
        return std::nullopt;
    };
    if (frame.size() != 3 || frame[0] < '5' || frame[0] > '8' || (frame[2] != '1' && frame[2] != '2')) return bad_frame();
    switch (frame[1]) {
        case 'N': case 'n': f.parity = Parity::None; break;
        case 'E': case 'e': f.parity = Parity::Even; break;
        case 'O': case 'o': f.parity = Parity::Odd; break;
        default: return bad_frame();
    }
    f.data_bits = static_cast<std::uint8_t>(frame[0] - '0');
    f.stop_bits = static_cast<std::uint8_t>(frame[2] - '0');
    return f;
}

// ---- transmitter -----------------------------------------------------------------------------

void UartTransmitter::send(std::uint8_t value, std::uint64_t at) {
    if (!busy()) {  // idle: after the gap that follows the last character, or now
        s_.start = std::max(s_.start, at);
        s_.queue.clear();
        s_.head = 0;
    }
    s_.queue.push_back(value);
    s_.sending = true;
}

bool UartTransmitter::bit_level(unsigned k) const {
    const unsigned data = format_.data_bits;
    if (k == 0) return false;                      // start bit: space
    const std::uint8_t value = s_.queue[s_.head];
    if (k <= data) return (value >> (k - 1)) & 1u;  // data, least significant first
    if (k == data + 1 && format_.parity != Parity::None) return format_.parity_bit(value);
    return true;                                   // stop bits, then the idle line: mark
}

std::uint64_t UartTransmitter::next_event() const {
    if (!s_.sending) return std::numeric_limits<std::uint64_t>::max();
    return s_.start + s_.bit * clock_ / format_.baud;
}

void UartTransmitter::advance(std::uint64_t now, const std::function<void(bool, std::uint64_t)>& on_level) {
    while (s_.sending) {
        const std::uint64_t t = next_event();
        if (t > now) return;
        if (s_.bit == format_.frame_bits()) {  // the stop bits are over: the next may follow after the gap
            ++s_.head;
            s_.start = t + gap_;
            s_.bit = 0;
            s_.sending = busy();
            continue;
        }
        const bool level = bit_level(s_.bit);
        ++s_.bit;
        if (level != s_.level) {
            s_.level = level;
            if (on_level) on_level(level, t);
        }
    }
}

// ---- receiver --------------------------------------------------------------------------------

std::uint64_t UartReceiver::sample_time(unsigned k) const {
    return s_.start + (2ull * k + 1) * clock_ / (2ull * format_.baud);
}

void UartReceiver::take_samples_before(std::uint64_t t, const Sink& sink) {
    const unsigned data = format_.data_bits;
    const unsigned stop = format_.frame_bits() - format_.stop_bits;  // the first stop bit
    while (s_.framing) {
        const std::uint64_t at = sample_time(s_.bit);
        if (at >= t) return;
        const unsigned k = s_.bit++;
        if (s_.level) s_.bits = static_cast<std::uint16_t>(s_.bits | (1u << k));
        if (k == 0 && s_.level) {  // high again in the start bit's middle: a glitch
            s_ = {.level = s_.level};
            continue;
        }
        if (k < stop) continue;
        UartChar c;
        c.value = static_cast<std::uint8_t>((s_.bits >> 1) & ((1u << data) - 1u));
        c.at = at;
        if (!s_.level)
            c.error = UartChar::Error::Framing;
        else if (format_.parity != Parity::None && ((s_.bits >> (data + 1)) & 1u) != format_.parity_bit(c.value))
            c.error = UartChar::Error::Parity;
        s_ = {.level = s_.level};  // wait for the next falling edge
        if (sink) sink(c);
    }
}

void UartReceiver::edge(bool level, std::uint64_t t, const Sink& sink) {
    take_samples_before(t, sink);
    if (level == s_.level) return;
    s_.level = level;
    if (!level && !s_.framing) {  // a falling edge on a waiting line: a start bit
        s_.framing = true;
        s_.start = t;
        s_.bit = 0;
        s_.bits = 0;
    }
}

void UartReceiver::advance(std::uint64_t now, const Sink& sink) { take_samples_before(now, sink); }

}  // namespace alp85::periph
