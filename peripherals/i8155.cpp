// Intel 8155/8156 RAM-I/O-timer. Facts and sources: docs/peripherals.md, section "8155".
#include "peripherals/i8155.h"

#include <algorithm>

#include "peripherals/state_io.h"

namespace alp85::periph {

namespace {
constexpr std::uint16_t kCountMask = 0x3FFF;

bool is_square(I8155::TimerMode m) {
    return m == I8155::TimerMode::SingleSquare || m == I8155::TimerMode::ContinuousSquare;
}
bool is_continuous(I8155::TimerMode m) {
    return m == I8155::TimerMode::ContinuousSquare || m == I8155::TimerMode::ContinuousPulse;
}
}  // namespace

void I8155::reset(std::uint64_t now) {
    // RESET puts all three ports in input mode (command register 00H) and stops the timer;
    // the RAM and the count length register keep their contents.
    const auto ram = s_.ram;
    const auto cl = s_.count_length;
    const auto pins = s_.pins;
    const bool old_out = s_.timer_out;
    const bool old_intr_a = intr(Port::A), old_intr_b = intr(Port::B);
    s_ = State{};
    s_.ram = ram;
    s_.count_length = cl;
    s_.pins = pins;
    s_.now = now;
    if (old_intr_a && on_intr_) on_intr_(Port::A, false, now);
    if (old_intr_b && on_intr_) on_intr_(Port::B, false, now);
    if (!old_out && on_timer_out_) on_timer_out_(true, now);
}

I8155::PortCMode I8155::port_c_mode() const {
    switch ((s_.command & kCmdPcMask) >> 2) {
        case 0: return PortCMode::Alt1;
        case 3: return PortCMode::Alt2;
        case 1: return PortCMode::Alt3;
        default: return PortCMode::Alt4;
    }
}

bool I8155::strobed(Port port) const {
    const PortCMode m = port_c_mode();
    if (port == Port::A) return m == PortCMode::Alt3 || m == PortCMode::Alt4;
    if (port == Port::B) return m == PortCMode::Alt4;
    return false;
}

bool I8155::intr(Port port) const {
    const int i = static_cast<int>(port) & 1;
    const std::uint8_t inte = i == 0 ? kCmdIea : kCmdIeb;
    return s_.intr_ff[i] && (s_.command & inte) != 0;
}

std::uint8_t I8155::input_levels(Port port, std::uint64_t now) const {
    if (input_) return input_(port, now);
    return s_.pins[static_cast<int>(port)];
}

void I8155::set_intr_ff(int i, bool v, std::uint64_t at) {
    const Port port = i == 0 ? Port::A : Port::B;
    const bool before = intr(port);
    s_.intr_ff[i] = v;
    const bool after = intr(port);
    if (before != after && on_intr_) on_intr_(port, after, at);
}

std::uint8_t I8155::port_output_mask(Port port) const {
    switch (port) {
        case Port::A: return (s_.command & kCmdPaOut) ? 0xFF : 0x00;
        case Port::B: return (s_.command & kCmdPbOut) ? 0xFF : 0x00;
        case Port::C:
            switch (port_c_mode()) {
                case PortCMode::Alt1: return 0x00;
                case PortCMode::Alt2: return 0x3F;
                case PortCMode::Alt3: return 0x3B;  // PC0, PC1 (A INTR, BF), PC3-PC5 outputs
                case PortCMode::Alt4: return 0x1B;  // PC0, PC1, PC3, PC4 (INTR, BF of A and B)
            }
    }
    return 0;
}

std::uint8_t I8155::port_output(Port port) const {
    const int i = static_cast<int>(port);
    if (port != Port::C) return s_.latch[i] & port_output_mask(port);
    std::uint8_t v = s_.latch[2] & 0x3F;
    const PortCMode m = port_c_mode();
    if (m == PortCMode::Alt3 || m == PortCMode::Alt4) {
        v = static_cast<std::uint8_t>((v & 0x38) | (intr(Port::A) ? 0x01 : 0) | (s_.bf[0] ? 0x02 : 0));
    }
    if (m == PortCMode::Alt4) {
        v = static_cast<std::uint8_t>((v & 0x07) | (intr(Port::B) ? 0x08 : 0) | (s_.bf[1] ? 0x10 : 0));
    }
    return v & port_output_mask(port);
}

std::uint8_t I8155::peek_status() const {
    std::uint8_t st = 0;
    if (intr(Port::A)) st |= kStIntrA;
    if (s_.bf[0]) st |= kStBfA;
    if (s_.command & kCmdIea) st |= kStInteA;
    if (intr(Port::B)) st |= kStIntrB;
    if (s_.bf[1]) st |= kStBfB;
    if (s_.command & kCmdIeb) st |= kStInteB;
    if (s_.timer_flag) st |= kStTimer;
    return st;
}

std::uint8_t I8155::read(std::uint8_t offset, std::uint64_t now) {
    advance(now);
    switch (offset & 7) {
        case kCommandStatus: {
            const std::uint8_t st = peek_status();
            s_.timer_flag = false;  // reading the status clears the latched TC
            return st;
        }
        case kPortA:
        case kPortB: {
            const Port port = (offset & 7) == kPortA ? Port::A : Port::B;
            const int i = static_cast<int>(port);
            if (port_output_mask(port)) return s_.latch[i];  // output ports read their latch
            if (!strobed(port)) return input_levels(port, now);
            // Strobed input: RD falling resets INTR, RD rising resets BF.
            const std::uint8_t v = s_.strobe_latch[i];
            set_intr_ff(i, false, now);
            s_.bf[i] = false;
            return v;
        }
        case kPortC: {
            const std::uint8_t in = input_levels(Port::C, now) & 0x3F;
            std::uint8_t v = 0;
            switch (port_c_mode()) {
                case PortCMode::Alt1: v = in; break;
                case PortCMode::Alt2: v = s_.latch[2] & 0x3F; break;
                case PortCMode::Alt3:
                case PortCMode::Alt4: {
                    v = static_cast<std::uint8_t>((intr(Port::A) ? 0x01 : 0) | (s_.bf[0] ? 0x02 : 0) |
                                                  (s_.stb[0] ? 0x04 : 0));
                    if (port_c_mode() == PortCMode::Alt3) {
                        v |= s_.latch[2] & 0x38;
                    } else {
                        v |= static_cast<std::uint8_t>((intr(Port::B) ? 0x08 : 0) | (s_.bf[1] ? 0x10 : 0) |
                                                       (s_.stb[1] ? 0x20 : 0));
                    }
                    break;
                }
            }
            return static_cast<std::uint8_t>(v | 0xC0);
        }
        case kTimerLow: return static_cast<std::uint8_t>(peek_counter(now) & 0xFF);
        case kTimerHigh: return static_cast<std::uint8_t>(peek_counter(now) >> 8);
        default: return 0xFF;
    }
}

void I8155::write(std::uint8_t offset, std::uint8_t value, std::uint64_t now) {
    advance(now);
    switch (offset & 7) {
        case kCommandStatus: {
            const bool a_before = intr(Port::A), b_before = intr(Port::B);
            s_.command = value & 0x3F;
            const bool a_after = intr(Port::A), b_after = intr(Port::B);
            if (a_before != a_after && on_intr_) on_intr_(Port::A, a_after, now);
            if (b_before != b_after && on_intr_) on_intr_(Port::B, b_after, now);
            timer_command(static_cast<std::uint8_t>(value >> 6), now);
            break;
        }
        case kPortA:
        case kPortB: {
            const Port port = (offset & 7) == kPortA ? Port::A : Port::B;
            const int i = static_cast<int>(port);
            s_.latch[i] = value;
            if (strobed(port) && port_output_mask(port)) {
                // Strobed output: WR falling resets INTR, WR rising sets BF.
                set_intr_ff(i, false, now);
                s_.bf[i] = true;
            }
            if (on_port_write_) on_port_write_(port, value, now);
            break;
        }
        case kPortC:
            s_.latch[2] = value & 0x3F;
            if (on_port_write_) on_port_write_(Port::C, s_.latch[2], now);
            break;
        case kTimerLow:
            s_.count_length = static_cast<std::uint16_t>((s_.count_length & 0xFF00) | value);
            break;
        case kTimerHigh:
            s_.count_length = static_cast<std::uint16_t>((s_.count_length & 0x00FF) | (value << 8));
            break;
        default: break;  // offsets 6 and 7 select nothing
    }
}

void I8155::set_stb(Port port, bool level, std::uint64_t now) {
    if (port == Port::C) return;
    advance(now);
    const int i = static_cast<int>(port);
    const bool old = s_.stb[i];
    s_.stb[i] = level;
    if (old == level || !strobed(port)) return;
    const bool output = port_output_mask(port) != 0;
    if (!level) {
        // STB falling: input latches the pins and sets BF; output (acknowledge) clears BF.
        if (output) {
            s_.bf[i] = false;
        } else {
            s_.strobe_latch[i] = input_levels(port, now);
            s_.bf[i] = true;
        }
    } else {
        set_intr_ff(i, true, now);  // STB rising requests an interrupt (gated by INTE)
    }
}

// ---- timer -------------------------------------------------------------------------------------

void I8155::set_timer_out(bool level, std::uint64_t at) {
    if (s_.timer_out == level) return;
    s_.timer_out = level;
    if (on_timer_out_) on_timer_out_(level, at);
}

void I8155::start_count(std::uint64_t at) {
    s_.count = std::max<std::uint16_t>(2, s_.count_length & kCountMask);
    s_.mode = static_cast<TimerMode>(s_.count_length >> 14);
    s_.period_start = at;
    s_.running = true;
    s_.counted = true;
    s_.pending_start = false;
    s_.stop_after_tc = false;
    if (s_.pulse_end == kNever) set_timer_out(true, at);  // every mode begins with TIMER OUT high
}

void I8155::timer_command(std::uint8_t tm, std::uint64_t now) {
    switch (tm & 3) {
        case 0: break;  // NOP
        case 1:         // STOP: no effect unless running; freezes the counter
            if (s_.running) {
                s_.held_value = counter_value(now);
                s_.running = false;
                s_.pending_start = false;
                s_.stop_after_tc = false;
            }
            break;
        case 2:  // STOP AFTER TC
            if (s_.running) {
                s_.stop_after_tc = true;
                s_.pending_start = false;
            }
            break;
        case 3:  // START: now if idle, else at the present TC
            s_.timer_flag = false;
            if (s_.running) {
                s_.pending_start = true;
                s_.stop_after_tc = false;
            } else {
                start_count(now);
            }
            break;
    }
}

std::uint64_t I8155::half_edge_time() const {
    // In the square-wave modes TIMER OUT falls after the first (larger) half: ceil(N/2) clocks.
    return s_.period_start + (s_.count + 1u) / 2u;
}

std::uint16_t I8155::counter_value(std::uint64_t t) const {
    const auto mode_bits = static_cast<std::uint16_t>(static_cast<unsigned>(s_.mode) << 14);
    const std::uint64_t e = t - s_.period_start;  // 0 <= e < count while running
    std::uint32_t v;
    if (is_square(s_.mode)) {
        // The counter steps by two; bit 0 tells the half (1 = first half, still to add N/2).
        const std::uint32_t half1 = (s_.count + 1u) / 2u;
        v = e < half1 ? (((half1 - static_cast<std::uint32_t>(e)) << 1) | 1u)
                      : ((s_.count - static_cast<std::uint32_t>(e)) << 1);
    } else {
        v = s_.count - static_cast<std::uint32_t>(e);
    }
    return static_cast<std::uint16_t>((v & kCountMask) | mode_bits);
}

std::uint16_t I8155::peek_counter(std::uint64_t now) const {
    if (s_.running) return counter_value(std::max(now, s_.now));
    if (!s_.counted) return s_.count_length;
    return s_.held_value;
}

void I8155::pins(Pins& p, std::uint64_t now) const {
    (void)now;  // every pin changes at a write or a timer event, which the board is told of
    static constexpr std::string_view kNames[3][8] = {{"PA0", "PA1", "PA2", "PA3", "PA4", "PA5", "PA6", "PA7"},
                                                      {"PB0", "PB1", "PB2", "PB3", "PB4", "PB5", "PB6", "PB7"},
                                                      {"PC0", "PC1", "PC2", "PC3", "PC4", "PC5", "", ""}};
    p.scope("8155");
    for (int i = 0; i < 3; ++i) {
        const auto port = static_cast<Port>(i);
        const std::uint8_t mask = port_output_mask(port), out = port_output(port);
        for (int b = 0; b < (i == 2 ? 6 : 8); ++b) {
            if (mask >> b & 1)
                p.logic(kNames[i][b], out >> b & 1);
            else
                p.undriven(kNames[i][b]);
        }
    }
    p.logic("TIMER_OUT", s_.timer_out);
}

void I8155::describe(Description& d) const {
    // Port C's modes as the data sheet's command register table names them (bits 3-2: 00 ALT1,
    // 11 ALT2, 01 ALT3, 10 ALT4) and its port control assignment says what the pins do.
    static constexpr const char* kPortC[] = {"ALT1 (input)", "ALT2 (output)", "ALT3 (port A strobed, PC3-5 output)",
                                             "ALT4 (ports A and B strobed)"};
    static constexpr const char* kModes[] = {"single square wave", "continuous square wave", "single pulse at TC",
                                             "continuous pulses"};
    const std::uint64_t now = std::max(d.now, s_.now);
    d.title = "8155 (RAM-I/O-timer)";

    Field& cmd = d.add(Field::hex("command", s_.command, 8)).watched_as("command");
    cmd.add(Field::bits("port A", s_.command, 0, 1, s_.command & kCmdPaOut ? "out" : "in"));
    cmd.add(Field::bits("port B", s_.command, 1, 1, s_.command & kCmdPbOut ? "out" : "in"));
    cmd.add(Field::bits("port C", s_.command, 2, 2, kPortC[static_cast<int>(port_c_mode())]));
    cmd.add(Field::flag("INTE A", s_.command & kCmdIea, 4, "on"));
    cmd.add(Field::flag("INTE B", s_.command & kCmdIeb, 5, "on"));
    cmd.text = summary(cmd.fields);

    const std::uint8_t st = peek_status();
    Field& status = d.add(Field::hex("status", st, 8));
    status.add(Field::flag("INTR A", st & kStIntrA, 0, "high"));
    status.add(Field::flag("BF A", st & kStBfA, 1, "full"));
    status.add(Field::flag("INTE A", st & kStInteA, 2, "on"));
    status.add(Field::flag("INTR B", st & kStIntrB, 3, "high"));
    status.add(Field::flag("BF B", st & kStBfB, 4, "full"));
    status.add(Field::flag("INTE B", st & kStInteB, 5, "on"));
    status.add(Field::flag("TIMER", st & kStTimer, 6, "TC reached"));
    status.text = summary(status.fields);

    const char* names[] = {"port A", "port B", "port C"};
    const char* watches[] = {"porta", "portb", "portc"};
    for (int i = 0; i < 3; ++i) {
        const auto port = static_cast<Port>(i);
        const std::string dir = i == 2 ? kPortC[static_cast<int>(port_c_mode())]
                                        : std::string(port_output_mask(port) ? "output" : "input") + (strobed(port) ? ", strobed" : "");
        Field& p = d.add(Field::hex(names[i], s_.latch[static_cast<std::size_t>(i)], i == 2 ? 6 : 8, dir)).watched_as(watches[i]);
        p.add(Field::hex("latch", s_.latch[static_cast<std::size_t>(i)], i == 2 ? 6 : 8));
        p.add(Field::hex("input pins", s_.pins[static_cast<std::size_t>(i)], i == 2 ? 6 : 8));
        p.add(Field::hex("driven", port_output(port), i == 2 ? 6 : 8));
    }

    Field& timer = d.add(Field::hex("count length", s_.count_length, 16)).watched_as("timer");
    timer.add(Field::bits("mode", s_.count_length, 14, 2, kModes[s_.count_length >> 14]));
    timer.add(Field::bits("count", s_.count_length, 0, 14, std::to_string(s_.count_length & 0x3FFF) + " clocks"));
    timer.text = summary(timer.fields);
    d.add(Field::hex("counter", peek_counter(now), 16, s_.running ? "running" : "stopped"));
    Field& out = d.add(Field::bits("TIMER OUT", s_.timer_out ? 1 : 0, 0, 1, s_.timer_out ? "high" : "low")).watched_as("timerout");
    out.lsb = -1;  // a pin, not a register's bit
}

std::uint64_t I8155::next_event() const {
    std::uint64_t t = s_.pulse_end;
    if (s_.running) {
        const std::uint64_t tc = s_.period_start + s_.count;
        t = std::min(t, tc);
        if (is_square(s_.mode) && s_.timer_out) {
            const std::uint64_t h = half_edge_time();
            if (h > s_.period_start && h < tc) t = std::min(t, h);
        }
    }
    return t;
}

void I8155::timer_event(std::uint64_t t) {
    if (t == s_.pulse_end) {
        s_.pulse_end = kNever;
        set_timer_out(true, t);
    }
    if (!s_.running) return;
    const std::uint64_t tc = s_.period_start + s_.count;
    if (t != tc) {
        if (is_square(s_.mode) && t == half_edge_time()) set_timer_out(false, t);
        return;
    }
    // Terminal count.
    s_.timer_flag = true;
    if (is_square(s_.mode)) {
        set_timer_out(true, t);
    } else {
        s_.pulse_end = t + 1;  // low for one TIMER IN period
        set_timer_out(false, t);
    }
    if (s_.pending_start) {
        start_count(t);
        return;
    }
    s_.period_start = t;  // reload
    if (s_.stop_after_tc || !is_continuous(s_.mode)) {
        s_.running = false;
        s_.stop_after_tc = false;
        s_.held_value = counter_value(t);
    }
}

void I8155::advance(std::uint64_t now) {
    if (now <= s_.now) return;
    // Skip whole periods of a free-running counter nobody listens to: O(1) catch-up. The skip
    // lands exactly on the last terminal count at or before `now`, as if it had just happened.
    if (!on_timer_out_ && s_.running && is_continuous(s_.mode) && !s_.pending_start && !s_.stop_after_tc &&
        now - s_.period_start >= 2ull * s_.count) {
        s_.period_start += (now - s_.period_start) / s_.count * s_.count;
        s_.timer_flag = true;
        if (is_square(s_.mode)) {
            s_.timer_out = true;
            s_.pulse_end = kNever;
        } else {
            s_.timer_out = false;
            s_.pulse_end = s_.period_start + 1;
        }
    }
    for (std::uint64_t t = next_event(); t <= now; t = next_event()) timer_event(t);
    s_.now = now;
}

// ---- snapshot ----------------------------------------------------------------------------------

void I8155::load_state(StateReader& r) {
    State s;
    State::fields(s, r);
    r.expect_end();
    r.check(s.command <= 0x3F, "invalid command register");
    r.check(s.count >= 2 && s.count <= kCountMask, "invalid timer count");
    r.check(!(s.running && (s.period_start > s.now || s.now >= s.period_start + s.count)),
            "timer state off its own clock");
    s_ = s;
}

}  // namespace alp85::periph
