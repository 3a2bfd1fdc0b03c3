#include "peripherals/serial_terminal.h"

#include <algorithm>

#include <fmt/format.h>

namespace alp85::periph {

SerialTerminal::SerialTerminal(std::uint64_t clock, UartFormat format, std::uint64_t gap)
    : tx_(clock, format, gap), rx_(clock, format) {}

void SerialTerminal::take(const UartChar& c) {
    ++received_;
    if (c.error != UartChar::Error::None) {
        ++errors_;
    } else {
        if (text_.size() == kTextKept) text_.erase(text_.begin());
        text_.push_back(c.value);
    }
    if (on_receive_) on_receive_(c);
}

void SerialTerminal::advance(std::uint64_t now) {
    if (now < now_) return;
    tx_.advance(now, on_txd_);
    rx_.advance(now, [this](const UartChar& c) { take(c); });
    now_ = now;
}

void SerialTerminal::sod(bool level, std::uint64_t t) {
    rx_.edge(level, t, [this](const UartChar& c) { take(c); });
}

namespace {
struct TerminalSaved {
    UartTransmitter::State tx;
    UartReceiver::State rx;
    std::vector<std::uint8_t> text;
    std::uint64_t received = 0, errors = 0, now = 0;
    template <class S, class Io> static void fields(S& s, Io& io) {
        decltype(s.tx)::fields(s.tx, io);
        decltype(s.rx)::fields(s.rx, io);
        io(s.text), io(s.received), io(s.errors), io(s.now);
    }
};
}  // namespace

void SerialTerminal::save_state(StateWriter& w) const {
    const TerminalSaved s{tx_.state(), rx_.state(), text_, received_, errors_, now_};
    TerminalSaved::fields(s, w);
}

void SerialTerminal::load_state(StateReader& r) {
    TerminalSaved s;
    TerminalSaved::fields(s, r);
    r.expect_end();
    r.check(tx_.valid(s.tx) && rx_.valid(s.rx), "a frame beyond its bits");
    r.check(s.text.size() <= kTextKept && s.errors <= s.received, "more text or errors than received");
    tx_.set_state(std::move(s.tx));
    rx_.set_state(s.rx);
    text_ = std::move(s.text);
    received_ = s.received;
    errors_ = s.errors;
    now_ = s.now;
}

void SerialTerminal::describe(Description& d) const {
    d.title = fmt::format("serial terminal on SID/SOD ({})", format().text());
    d.add(Field::note("TXD", tx_.level() ? "mark (1), to SID" : "space (0), to SID"));
    d.add(Field::note("RXD", rx_.state().level ? "mark (1), from SOD" : "space (0), from SOD"));
    d.add(Field::decimal("to send", static_cast<std::int64_t>(tx_.state().queue.size() - tx_.state().head), 32,
                         "characters queued"));
    d.add(Field::decimal("received", static_cast<std::int64_t>(received_), 32, "characters"));
    d.add(Field::decimal("errors", static_cast<std::int64_t>(errors_), 32, "framing or parity"));
}

}  // namespace alp85::periph
