// Intel 8279 keyboard/display interface. Facts and sources: docs/peripherals.md, section "8279".
#include "peripherals/i8279.h"

#include <algorithm>
#include <bit>

#include "peripherals/state_io.h"

namespace alp85::periph {

namespace {
}

void I8279::reset(std::uint64_t now) {
    // RESET: 16-digit left entry, encoded scan 2-key lockout, prescaler 31 (data sheet). The display
    // RAM keeps its contents; the FIFO and its status are emptied, IRQ falls.
    const auto ram = s_.display_ram;
    const bool shift = s_.shift, cntl = s_.cntl, old_irq = s_.irq;
    s_ = State{};
    s_.display_ram = ram;
    s_.shift = shift;
    s_.cntl = cntl;
    s_.now = now;
    resync(now);
    resample();
    if (old_irq && on_irq_) on_irq_(false, now);
}

void I8279::resync(std::uint64_t now) {
    s_.origin_t = now;
    s_.origin_clk = 0;
    s_.next_digit = 0;
    // Debounces in progress start again with the new scan.
    s_.candidate_digit = 0;
    s_.nkro_digit.fill(0);
}

std::uint64_t I8279::clk_at(std::uint64_t t) const {
    return s_.origin_clk + (t - s_.origin_t) / s_.prescaler;
}

std::uint64_t I8279::time_of_digit(std::uint64_t d) const {
    const std::uint64_t c = d * kClocksPerDigit;
    return c <= s_.origin_clk ? s_.origin_t : s_.origin_t + (c - s_.origin_clk) * s_.prescaler;
}

unsigned I8279::display_digits() const {
    if (decoded()) return 4;
    return sixteen_digits() ? 16 : 8;
}

std::uint8_t I8279::scan_value(unsigned row) const {
    // Encoded: SL0-3 count in binary; decoded: one of SL0-3 low.
    return decoded() ? static_cast<std::uint8_t>(~(1u << row) & 0x0F) : static_cast<std::uint8_t>(row & 7);
}

std::uint8_t I8279::scan_lines(std::uint64_t now) const {
    const std::uint64_t d = clk_at(std::max(now, s_.origin_t)) / kClocksPerDigit;
    if (decoded()) return static_cast<std::uint8_t>(~(1u << (d % 4)) & 0x0F);
    return static_cast<std::uint8_t>(d % (sixteen_digits() ? 16 : 8));
}

bool I8279::may_change() const {
    // Scanning can only change something while a key is closed, a key is being tracked, or the
    // sensor RAM differs from the matrix.
    if (s_.candidate >= 0 || s_.locked >= 0) return true;
    for (unsigned r = 0; r < rows(); ++r) {
        if (s_.matrix[r] != 0xFF) return true;
        if (sensor_mode() && s_.fifo[r] != s_.matrix[r]) return true;
    }
    return std::any_of(s_.nkro.begin(), s_.nkro.end(), [](std::uint8_t k) { return k != 0; });
}

void I8279::mark_dirty() {
    if (may_change()) {
        s_.dirty = true;
        s_.quiet = 0;
    }
}

void I8279::resample() {
    for (unsigned r = 0; r < 8; ++r) {
        s_.matrix[r] = (source_ && r < rows()) ? source_(scan_value(r)) : 0xFF;
    }
    mark_dirty();
}

std::uint8_t I8279::digit_output(unsigned position) const {
    const unsigned n = sixteen_digits() ? 16 : 8;
    if (position >= display_digits()) return 0x00;  // never scanned: dark
    const unsigned address = right_entry() ? (position + s_.right_offset) % n : position;
    std::uint8_t v = s_.display_ram[address];
    if (s_.inhibit_blank & 0x02) v = static_cast<std::uint8_t>((v & 0x0F) | (s_.blank_code & 0xF0));  // BL A
    if (s_.inhibit_blank & 0x01) v = static_cast<std::uint8_t>((v & 0xF0) | (s_.blank_code & 0x0F));  // BL B
    return v;
}

bool I8279::blanking(std::uint64_t now) const {
    return clk_at(std::max(now, s_.origin_t)) % kClocksPerDigit >= kClocksPerDigit - kBlankClocks;
}

void I8279::pins(Pins& p, std::uint64_t now) const {
    p.scope("8279");
    const std::uint8_t sl = scan_lines(now);
    p.logic("SL0", sl & 1);
    p.logic("SL1", sl & 2);
    p.logic("SL2", sl & 4);
    p.logic("SL3", sl & 8);
    p.logic("BD", !blanking(now));
    p.logic("IRQ", s_.irq);
}

std::uint64_t I8279::next_pin_change(std::uint64_t now) const {
    // The next internal clock edge at which the scan moves on (a new digit) or blanking starts.
    const std::uint64_t t = std::max(now, s_.origin_t);
    const std::uint64_t c = clk_at(t), in_digit = c % kClocksPerDigit, blank_at = kClocksPerDigit - kBlankClocks;
    const std::uint64_t next_clk = c - in_digit + (in_digit < blank_at ? blank_at : kClocksPerDigit);
    return s_.origin_t + (next_clk - s_.origin_clk) * s_.prescaler;
}

void I8279::describe(Description& d) const {
    // The keyboard/display mode set command 000DDKKK (data sheet): DD display, KKK keyboard.
    static constexpr const char* kDisplay[] = {"8 digits, left entry", "16 digits, left entry", "8 digits, right entry",
                                               "16 digits, right entry"};
    static constexpr const char* kKeys[] = {"encoded scan, 2-key lockout", "decoded scan, 2-key lockout",
                                            "encoded scan, N-key rollover", "decoded scan, N-key rollover",
                                            "encoded sensor matrix", "decoded sensor matrix", "strobed input, encoded",
                                            "strobed input, decoded"};
    auto hex2 = [](std::uint8_t v) {
        static constexpr char kDigits[] = "0123456789ABCDEF";
        return std::string{kDigits[v >> 4], kDigits[v & 15], 'H'};
    };
    d.title = "8279 (keyboard/display)";

    Field& mode = d.add(Field::hex("mode", s_.mode, 8));
    mode.add(Field::bits("display", s_.mode, 3, 2, kDisplay[(s_.mode >> 3) & 3]));
    mode.add(Field::bits("keyboard", s_.mode, 0, 3, kKeys[s_.mode & 7]));
    mode.text = summary(mode.fields);
    d.add(Field::decimal("prescaler", s_.prescaler, 5));

    const std::uint8_t st = peek_status(d.now);
    Field& status = d.add(Field::hex("status", st, 8)).watched_as("status");
    status.add(Field::flag("DU", st & kStDU, 7, "display unavailable"));
    status.add(Field::flag("S/E", st & kStSE, 6, sensor_mode() ? "sensor closure" : "multiple closure"));
    status.add(Field::flag("O", st & kStO, 5, "overrun"));
    status.add(Field::flag("U", st & kStU, 4, "underrun"));
    status.add(Field::flag("F", st & kStF, 3, "full"));
    const unsigned n = (st & kStF) ? 8 : st & kStCount;
    status.add(Field::bits("FIFO", st, 0, 3, sensor_mode() ? "" : std::to_string(n) + (n == 1 ? " entry" : " entries")));
    status.text = summary(status.fields);

    d.add(Field::decimal("FIFO count", s_.fifo_count, 4)).watched_as("fifo");
    std::string entries;
    for (unsigned i = 0; i < s_.fifo_count; ++i) entries += (i ? " " : "") + hex2(s_.fifo[(s_.fifo_head + i) % 8]);
    Field& fifo = d.add(Field::note("FIFO", entries.empty() ? "empty" : entries));
    for (unsigned i = 0; i < s_.fifo_count; ++i) fifo.add(Field::hex(std::to_string(i), s_.fifo[(s_.fifo_head + i) % 8], 8));

    d.add(Field::decimal("display address", s_.display_address, 4, s_.display_ai ? "auto-increment" : ""));
    Field& ram = d.add(Field::note("display RAM", "16 bytes"));
    for (std::size_t i = 0; i < s_.display_ram.size(); ++i) ram.add(Field::hex(std::to_string(i), s_.display_ram[i], 8));
    d.add(Field::note("data read", s_.read_display ? "display RAM" : sensor_mode() ? "sensor RAM" : "FIFO"));
    d.add(Field::bits("inhibit/blank", s_.inhibit_blank, 0, 4)).lsb = -1;
    d.add(Field::bits("IRQ", s_.irq ? 1 : 0, 0, 1, s_.irq ? "high" : "low")).lsb = -1;
}

std::uint8_t I8279::peek_status(std::uint64_t now) const {
    std::uint8_t st = 0;
    if (std::max(now, s_.now) < s_.du_until) st |= kStDU;
    if (sensor_mode()) {
        for (unsigned r = 0; r < rows(); ++r) {
            if (s_.fifo[r] != 0xFF) st |= kStSE;  // at least one sensor closure in the sensor RAM
        }
    } else {
        if (s_.error) st |= kStSE;
        if (s_.fifo_count == 8) st |= kStF;
        st |= s_.fifo_count & kStCount;
    }
    if (s_.overrun) st |= kStO;
    if (s_.underrun) st |= kStU;
    return st;
}

void I8279::update_irq(std::uint64_t at) {
    bool level;
    if (sensor_mode()) {
        level = s_.sensor_irq;
    } else {
        level = s_.fifo_count > 0 || s_.error;
    }
    if (level == s_.irq) return;
    s_.irq = level;
    if (on_irq_) on_irq_(level, at);
}

std::uint8_t I8279::key_entry(int key) const {
    // FIFO entry: CNTL, SHIFT, scan row (3 bits), return line (3 bits).
    return static_cast<std::uint8_t>((s_.cntl ? 0x80 : 0) | (s_.shift ? 0x40 : 0) | (key & 0x3F));
}

void I8279::push_fifo(std::uint8_t entry, std::uint64_t at) {
    if (s_.fifo_count == 8) {
        s_.overrun = true;  // the character is lost
        return;
    }
    s_.fifo[(s_.fifo_head + s_.fifo_count) & 7] = entry;
    ++s_.fifo_count;
    update_irq(at);
}

bool I8279::busy() const {
    if (strobed_mode()) return false;
    if (s_.dirty || s_.candidate >= 0) return true;
    if (nkro_mode()) {
        return std::any_of(s_.nkro.begin(), s_.nkro.end(), [](std::uint8_t k) { return k == 1; });
    }
    return false;
}

void I8279::process_digit(std::uint64_t d) {
    if (strobed_mode()) return;
    const unsigned nrows = rows();
    const unsigned row = static_cast<unsigned>(d % nrows);
    const std::uint8_t closed = static_cast<std::uint8_t>(~s_.matrix[row]);
    const std::uint64_t debounce = debounce_digits();
    const std::uint64_t at = time_of_digit(d);
    bool changed = false;

    if (sensor_mode()) {
        // No debounce: the row's return lines go straight into the sensor RAM, unless a previous
        // change has raised IRQ (writing is inhibited until it is cleared).
        if (s_.matrix[row] != s_.fifo[row] && !s_.sensor_irq) {
            s_.fifo[row] = s_.matrix[row];
            s_.sensor_irq = true;
            update_irq(at);
            changed = true;
        }
    } else if (nkro_mode()) {
        bool debouncing_other = false;
        for (int k = 0; k < 64; ++k) debouncing_other |= s_.nkro[k] == 1;
        for (unsigned c = 0; c < 8; ++c) {
            const int k = static_cast<int>(row * 8 + c);
            const bool down = (closed >> c) & 1;
            auto& st = s_.nkro[k];
            if (st == 0 && down) {
                if (s_.special_error_mode && debouncing_other && !s_.error) {
                    s_.error = true;  // simultaneous multiple depression
                    update_irq(at);
                }
                st = 1;
                s_.nkro_digit[k] = d;
                debouncing_other = true;
                changed = true;
            } else if (st == 1 && !down) {
                st = 0;
                changed = true;
            } else if (st == 1 && d >= s_.nkro_digit[k] + debounce) {
                st = 2;
                if (!s_.error) push_fifo(key_entry(k), at);
                changed = true;
            } else if (st == 2 && !down) {
                st = 0;
                changed = true;
            }
        }
    } else {  // 2-key lockout
        if (s_.candidate >= 0) {
            const unsigned crow = static_cast<unsigned>(s_.candidate) / 8;
            const std::uint8_t cbit = static_cast<std::uint8_t>(1u << (s_.candidate & 7));
            if (row == crow) {
                if (!(closed & cbit)) {
                    s_.candidate = -1;  // released before the debounce time: not registered
                } else {
                    if (closed & ~cbit) s_.candidate_multi = true;
                    if (d >= s_.candidate_digit + debounce) {
                        if (!s_.candidate_multi) {
                            push_fifo(key_entry(s_.candidate), at);
                            s_.locked = s_.candidate;
                        }
                        s_.candidate = -1;  // simultaneous keys: neither is entered; start again
                    }
                }
            } else if (closed) {
                s_.candidate_multi = true;
            }
            changed = true;
        } else if (s_.locked >= 0) {
            const unsigned lrow = static_cast<unsigned>(s_.locked) / 8;
            if (row == lrow && !(closed & (1u << (s_.locked & 7)))) {
                s_.locked = -1;
                changed = true;
            }
        } else if (closed) {
            s_.candidate = static_cast<std::int8_t>(row * 8 + static_cast<unsigned>(std::countr_zero(closed)));
            s_.candidate_digit = d;
            s_.candidate_multi = std::popcount(closed) > 1;
            changed = true;
        }
    }

    if (changed) {
        s_.quiet = 0;
    } else if (++s_.quiet >= nrows) {
        s_.dirty = false;  // a full scan without change: nothing more can happen until inputs change
        s_.quiet = 0;
    }
}

void I8279::advance(std::uint64_t now) {
    if (now < s_.now) now = s_.now;
    while (true) {
        if (!busy()) {
            // Idle: skip straight to the first digit time after `now` (already there when the
            // next digit is still ahead: the firmware polling the status, no division).
            if (time_of_digit(s_.next_digit) > now) break;
            const std::uint64_t next = clk_at(now) / kClocksPerDigit + 1;
            s_.next_digit = std::max(s_.next_digit, next);
            break;
        }
        if (time_of_digit(s_.next_digit) > now) break;
        process_digit(s_.next_digit);
        ++s_.next_digit;
    }
    s_.now = now;
}

std::uint64_t I8279::next_event() const {
    std::uint64_t t = kNever;
    if (s_.du_until > s_.now) t = s_.du_until;
    if (strobed_mode()) return t;
    const std::uint64_t debounce = debounce_digits();
    if (s_.candidate >= 0) {
        t = std::min(t, time_of_digit(s_.candidate_digit + debounce));
    } else if (s_.dirty) {
        t = std::min(t, time_of_digit(s_.next_digit));
    }
    if (nkro_mode()) {
        for (int k = 0; k < 64; ++k) {
            if (s_.nkro[k] == 1) t = std::min(t, time_of_digit(std::max(s_.nkro_digit[k] + debounce, s_.next_digit)));
        }
    }
    // Never report the past: the board's scheduler must always move forward.
    return t != kNever && t <= s_.now ? s_.now + 1 : t;
}

void I8279::inputs_changed(std::uint64_t now) {
    advance(now);
    resample();
}

void I8279::set_shift(bool level, std::uint64_t now) {
    advance(now);
    s_.shift = level;
}

void I8279::set_cntl_stb(bool level, std::uint64_t now) {
    advance(now);
    const bool rising = level && !s_.cntl;
    s_.cntl = level;
    if (rising && strobed_mode()) {
        // Strobed input: the return lines are entered into the FIFO on the rising edge of STB.
        push_fifo(source_ ? source_(scan_lines(now)) : 0xFF, now);
    }
}

std::uint8_t I8279::read(std::uint8_t a0, std::uint64_t now) {
    advance(now);
    if (a0 & 1) return peek_status(now);
    if (s_.read_display) {
        const std::uint8_t v = s_.display_ram[s_.display_address];
        if (s_.display_ai) s_.display_address = static_cast<std::uint8_t>((s_.display_address + 1) % address_wrap());
        return v;
    }
    if (sensor_mode()) {
        const std::uint8_t v = s_.fifo[s_.sensor_address];
        if (s_.sensor_ai) {
            s_.sensor_address = (s_.sensor_address + 1) & 7;
        } else {
            s_.sensor_irq = false;  // without auto-increment the first read clears IRQ
            update_irq(now);
            mark_dirty();           // writing into the sensor RAM may resume
        }
        return v;
    }
    if (s_.fifo_count == 0) {
        s_.underrun = true;
        return s_.fifo[s_.fifo_head];
    }
    const std::uint8_t v = s_.fifo[s_.fifo_head];
    s_.fifo_head = (s_.fifo_head + 1) & 7;
    --s_.fifo_count;
    // IRQ falls with each read and rises again if entries remain.
    if (s_.irq) {
        s_.irq = false;
        if (on_irq_) on_irq_(false, now);
    }
    update_irq(now);
    return v;
}

void I8279::write(std::uint8_t a0, std::uint8_t value, std::uint64_t now) {
    advance(now);
    if (a0 & 1) {
        command(value, now);
        return;
    }
    if (now < s_.du_until) return;  // the display RAM is being cleared
    std::uint8_t& cell = s_.display_ram[s_.display_address];
    std::uint8_t keep = 0;
    if (s_.inhibit_blank & 0x08) keep |= 0xF0;  // IW A protects bits 7-4
    if (s_.inhibit_blank & 0x04) keep |= 0x0F;  // IW B protects bits 3-0
    cell = static_cast<std::uint8_t>((cell & keep) | (value & ~keep));
    // Right entry: each entry shifts the picture one position left.
    if (right_entry()) s_.right_offset = static_cast<std::uint8_t>((s_.right_offset + 1) % address_wrap());
    // Auto-increment wraps after the last digit: the 9th (17th) character goes back to the left.
    if (s_.display_ai) s_.display_address = static_cast<std::uint8_t>((s_.display_address + 1) % address_wrap());
}

void I8279::command(std::uint8_t value, std::uint64_t now) {
    switch (value >> 5) {
        case 0: {  // keyboard/display mode set: 0 0 0 D D K K K
            s_.mode = value & 0x1F;
            s_.right_offset = 0;
            s_.candidate = -1;
            s_.locked = -1;
            s_.nkro.fill(0);
            resample();
            update_irq(now);
            break;
        }
        case 1: {  // program clock: 0 0 1 P P P P P
            const std::uint64_t c = clk_at(now);
            s_.prescaler = std::max<std::uint8_t>(2, value & 0x1F);
            s_.origin_t = now;
            s_.origin_clk = c;
            break;
        }
        case 2:  // read FIFO/sensor RAM: 0 1 0 AI X A A A
            s_.read_display = false;
            s_.sensor_ai = (value & 0x10) != 0;
            s_.sensor_address = value & 7;
            break;
        case 3:  // read display RAM: 0 1 1 AI A A A A
            s_.read_display = true;
            s_.display_ai = (value & 0x10) != 0;
            s_.display_address = value & 15;
            break;
        case 4:  // write display RAM: 1 0 0 AI A A A A
            s_.display_ai = (value & 0x10) != 0;
            s_.display_address = value & 15;
            break;
        case 5:  // display write inhibit/blanking: 1 0 1 X IW IW BL BL
            s_.inhibit_blank = value & 0x0F;
            break;
        case 6: {  // clear: 1 1 0 CD CD CD CF CA
            const bool ca = value & 0x01;
            const bool cf = value & 0x02;
            const bool cd = value & 0x10;
            switch ((value >> 2) & 3) {
                case 2: s_.blank_code = 0x20; break;  // AB = 0010 0000
                case 3: s_.blank_code = 0xFF; break;
                default: s_.blank_code = 0x00; break;
            }
            if (cd || ca) {
                s_.display_ram.fill(s_.blank_code);
                s_.right_offset = 0;
                s_.display_address = 0;
            }
            if (cf || ca) {
                // FIFO status cleared, IRQ reset, sensor RAM pointer to row 0.
                s_.fifo_count = 0;
                s_.fifo_head = 0;
                s_.overrun = s_.underrun = s_.error = false;
                s_.sensor_irq = false;
                s_.sensor_address = 0;
                mark_dirty();
                update_irq(now);
            }
            if (ca) resync(now);  // clear all also resynchronises the internal timing
            // DU stays set until the 16th internal clock after the command (~160 us at 100 kHz).
            if (cd || ca) s_.du_until = s_.origin_t + (clk_at(now) + kClearClocks - s_.origin_clk) * s_.prescaler;
            break;
        }
        case 7:  // end interrupt / error mode: 1 1 1 E X X X X
            s_.special_error_mode = (value & 0x10) != 0;
            if (sensor_mode()) {
                s_.sensor_irq = false;
                mark_dirty();
                update_irq(now);
            }
            break;
    }
}

// ---- snapshot ----------------------------------------------------------------------------------

void I8279::load_state(StateReader& r) {
    State s;
    State::fields(s, r);
    if (s.fifo_head > 7 || s.fifo_count > 8) r.fail("invalid FIFO pointers");
    if (s.mode > 0x1F) r.fail("invalid mode");
    if (s.prescaler < 2 || s.prescaler > 31) r.fail("invalid prescaler");
    if (s.display_address > 15 || s.sensor_address > 7 || s.inhibit_blank > 15 || s.right_offset > 15) {
        r.fail("invalid address or flags");
    }
    if (s.candidate < -1 || s.locked < -1) r.fail("invalid key index");
    for (auto v : s.nkro) {
        if (v > 2) r.fail("invalid key state");
    }
    r.expect_end();
    // The scan's invariants, so that a crafted file cannot leave a debounce that never ends (the
    // scan would then be revisited digit by digit forever):
    //   the digit being scanned at `now` is next_digit or the one before it (resync: both 0);
    //   a pending key lies in a scanned row and started at or before next_digit.
    if (s.origin_t > s.now || s.origin_clk > (1ull << 56) || (s.now - s.origin_t) / s.prescaler > (1ull << 56))
        r.fail("scan clock out of range");
    const std::uint64_t digit_now = (s.origin_clk + (s.now - s.origin_t) / s.prescaler) / kClocksPerDigit;
    if (s.next_digit < digit_now || s.next_digit > digit_now + 1 || s.next_digit * kClocksPerDigit < s.origin_clk)
        r.fail("scan state off its own clock");
    const int keys = (s.mode & 1) ? 32 : 64;  // decoded scan: 4 rows
    if (s.candidate >= keys || s.locked >= keys || (s.candidate >= 0 && s.candidate_digit > s.next_digit))
        r.fail("invalid pending key");
    for (int k = 0; k < 64; ++k) {
        if ((k >= keys && s.nkro[k] != 0) || (s.nkro[k] == 1 && s.nkro_digit[k] > s.next_digit))
            r.fail("invalid key state");
    }
    s_ = s;
}

}  // namespace alp85::periph
