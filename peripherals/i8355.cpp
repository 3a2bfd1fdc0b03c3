// Intel 8355 ROM-I/O. Facts and sources: docs/peripherals.md, section "8355".
#include "peripherals/i8355.h"

#include <algorithm>

#include "peripherals/state_io.h"

namespace alp85::periph {

void I8355::reset(std::uint64_t now) {
    // RESET clears both data direction registers: every port line becomes an input.
    const bool drove_a = s_.ddr[0] != 0, drove_b = s_.ddr[1] != 0;
    s_.ddr = {0, 0};
    s_.now = std::max(now, s_.now);
    if (on_port_write_) {
        if (drove_a) on_port_write_(Port::A, s_.latch[0], s_.now);
        if (drove_b) on_port_write_(Port::B, s_.latch[1], s_.now);
    }
}

std::uint8_t I8355::input_levels(Port port, std::uint64_t now) const {
    if (input_) return input_(port, now);
    return s_.pins[static_cast<int>(port)];
}

std::uint8_t I8355::port_output(Port port) const {
    const int i = static_cast<int>(port);
    return static_cast<std::uint8_t>(s_.latch[i] & s_.ddr[i]);
}

std::uint8_t I8355::peek_port(Port port) const {
    const int i = static_cast<int>(port);
    return static_cast<std::uint8_t>((s_.latch[i] & s_.ddr[i]) | (s_.pins[i] & ~s_.ddr[i]));
}

std::uint8_t I8355::read(std::uint8_t offset, std::uint64_t now) {
    advance(now);
    switch (offset & 3) {
        case kPortA:
        case kPortB: {
            const Port port = (offset & 3) == kPortA ? Port::A : Port::B;
            const int i = static_cast<int>(port);
            // Output lines read back their latch, input lines the pins.
            const std::uint8_t in = s_.ddr[i] == 0xFF ? 0 : input_levels(port, now);
            return static_cast<std::uint8_t>((s_.latch[i] & s_.ddr[i]) | (in & ~s_.ddr[i]));
        }
        default: return 0xFF;  // a DDR: loaded by IOW, not read (see the header)
    }
}

void I8355::write(std::uint8_t offset, std::uint8_t value, std::uint64_t now) {
    advance(now);
    const auto port = static_cast<Port>(offset & 1);
    const int i = static_cast<int>(port);
    if ((offset & 2) == 0)
        s_.latch[i] = value;
    else
        s_.ddr[i] = value;
    if (on_port_write_) on_port_write_(port, s_.latch[i], now);
}

void I8355::pins(Pins& p, std::uint64_t now) const {
    (void)now;  // every line changes at a write, which the board is told of
    static constexpr std::string_view kNames[2][8] = {{"PA0", "PA1", "PA2", "PA3", "PA4", "PA5", "PA6", "PA7"},
                                                      {"PB0", "PB1", "PB2", "PB3", "PB4", "PB5", "PB6", "PB7"}};
    p.scope("8355");
    for (int i = 0; i < 2; ++i) {
        const auto port = static_cast<Port>(i);
        const std::uint8_t mask = port_output_mask(port), out = port_output(port);
        for (int b = 0; b < 8; ++b) {
            if (mask >> b & 1)
                p.logic(kNames[i][b], out >> b & 1);
            else
                p.undriven(kNames[i][b]);
        }
    }
}

void I8355::describe(Description& d) const {
    d.title = "8355 (ROM-I/O)";
    static constexpr const char* kNames[] = {"port A", "port B"};
    static constexpr const char* kWatches[] = {"porta", "portb"};
    static constexpr const char* kDdrWatches[] = {"ddra", "ddrb"};
    for (int i = 0; i < 2; ++i) {
        const auto port = static_cast<Port>(i);
        const auto k = static_cast<std::size_t>(i);
        const std::uint8_t ddr = s_.ddr[k];
        const std::string dir = ddr == 0 ? "input" : ddr == 0xFF ? "output" : "mixed";
        Field& p = d.add(Field::hex(kNames[i], s_.latch[k], 8, dir)).watched_as(kWatches[i]);
        p.add(Field::hex("latch", s_.latch[k], 8));
        p.add(Field::hex("input pins", s_.pins[k], 8));
        p.add(Field::hex("driven", port_output(port), 8));
        p.add(Field::hex("read", peek_port(port), 8, "what IN gives: latch on outputs, pins on inputs"));
        d.add(Field::hex(std::string("DDR ") + (i == 0 ? "A" : "B"), ddr, 8, "1 = output"))
            .watched_as(kDdrWatches[i]);
    }
}

void I8355::load_state(StateReader& r) {
    State s;
    State::fields(s, r);
    r.expect_end();
    s_ = s;
}

}  // namespace alp85::periph
