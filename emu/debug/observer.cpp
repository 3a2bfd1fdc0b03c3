#include "emu/debug/observer.h"

#include <algorithm>

#include <fmt/format.h>

namespace alp85::debug {

namespace {
// A memory watch's value: up to two bytes little-endian (a byte, a word), else the byte at `addr`.
std::int64_t memory_value(const Machine& m, const Watchpoint& w) {
    if (w.last - w.first > 1) return 0;
    std::int64_t v = m.peek(w.first);
    if (w.last != w.first) v |= m.peek(w.last) << 8;
    return v;
}
}  // namespace

void Debugger::Observer::rebuild() {
    bp_.reset();
    read_.reset();
    write_.reset();
    port_in_.reset();
    port_out_.reset();
    state_watches_ = false;
    for (const Breakpoint& b : d_.breakpoints_)
        if (b.enabled) bp_[b.address] = true;
    for (const Watchpoint& w : d_.watchpoints_) {
        if (!w.enabled) continue;
        switch (w.kind) {
            case WatchKind::Write:
            case WatchKind::Read:
            case WatchKind::Access:
                for (std::uint32_t a = w.first; a <= w.last; ++a) {
                    if (w.kind != WatchKind::Read) write_[a] = true;
                    if (w.kind != WatchKind::Write) read_[a] = true;
                }
                break;
            case WatchKind::Port:
                if (w.dir != PortDir::Out) port_in_[w.first] = true;
                if (w.dir != PortDir::In) port_out_[w.first] = true;
                break;
            case WatchKind::Tool:
            case WatchKind::Part: state_watches_ = true; break;
        }
    }
    any_bp_ = bp_.any();
    guard_ = d_.code_.has_value();
    accesses_ = read_.any() || write_.any() || port_in_.any() || port_out_.any();
    // The fence serves a run that needs breakpoints and the guard alone. The guard needs the
    // PC inside the code when the run starts (out there it waits, instruction by instruction,
    // for the PC to come back before it arms).
    const bool in_code = guard_ && (*d_.code_)[d_.m_.cpu().regs().pc];
    fence_ok_ = !accesses_ && !state_watches_ && !target && record == nullptr && !replay && hits == nullptr &&
                (!guard_ || in_code || runaway_armed);
    if (fence_ok_) {
        fence_ = bp_;
        if (guard_) {
            fence_ |= ~*d_.code_;
            runaway_armed = true;
        }
    }
}

bool Debugger::Observer::at_fence(const I8085& cpu) {
    last_pc = cpu.fence_previous();  // the instruction before, for a runaway's "after"
    return before_instruction(cpu);
}

bool Debugger::Observer::before_instruction(const I8085& cpu) {
    const std::uint64_t t = cpu.tstates();
    const Registers& r = cpu.regs();
    if (!pending.empty() && hits) flush_pending(t);
    if (record) record->push_back({t, r, d_.m_.peek(r.pc)});
    if (replay && !hits) return false;
    // The machine tool and the chips changed during the instruction at last_pc (stop after it).
    if (state_watches_ && check_state(cpu)) return true;
    if (guard_ && !replay) {
        if ((*d_.code_)[r.pc]) {
            runaway_armed = true;
        } else if (runaway_armed) {  // stop before running what is not a program
            runaway_armed = false;
            stop_hit = Hit{t, StopReason::Runaway, 0, {}, {}, last_pc, {}};
            return true;
        }
    }
    last_pc = r.pc;
    if (any_bp_ && bp_[r.pc] && check_breakpoint(cpu)) return true;
    if (target && target(cpu)) {
        target_reached = true;
        return true;
    }
    return false;
}

bool Debugger::Observer::check_breakpoint(const I8085& cpu) {
    const std::uint64_t t = cpu.tstates();
    if (skip_at && *skip_at == t) return false;
    std::vector<int> stopping;
    for (Breakpoint& b : d_.breakpoints_) {
        if (!b.enabled || b.address != cpu.regs().pc) continue;
        if (b.condition) {
            try {
                if (b.condition->eval(d_.m_) == 0) continue;
            } catch (const ExprError& e) {
                if (hits) continue;
                error = "breakpoint " + std::to_string(b.number) + ": the condition '" + b.condition->text() +
                        "' cannot be evaluated: " + e.message;
                stopping = {b.number};
                break;
            }
        }
        if (hits) {  // re-execution: a position, nothing counted (a log point is no stop)
            if (b.log_message.empty()) stopping.push_back(b.number);
            continue;
        }
        if (b.ignore > 0) {
            ++b.hits;
            --b.ignore;
            continue;
        }
        ++b.hits;
        if (b.hit_condition && !b.hit_condition->met(b.hits)) continue;
        if (!b.log_message.empty()) {
            d_.emit({Event::Kind::Output, {}, d_.interpolate(b.log_message), {}});
            continue;
        }
        stopping.push_back(b.number);
    }
    if (stopping.empty()) return false;
    if (hits) {  // one position for all the breakpoints here, as a forward run's stop names them all
        hits->push_back({t, StopReason::Breakpoint, stopping.front(), {}, {}, {}, stopping});
        return false;
    }
    stop_hit = Hit{t, StopReason::Breakpoint, stopping.front(), {}, {}, {}, stopping};
    return true;
}

bool Debugger::Observer::check_state(const I8085& cpu) {
    const std::uint64_t t = cpu.tstates();
    Hit hit{t, StopReason::Watchpoint, 0, {}, {}, last_pc};
    for (Watchpoint& w : d_.watchpoints_) {
        if (!w.enabled || (w.kind != WatchKind::Tool && w.kind != WatchKind::Part)) continue;
        std::int64_t v = 0;
        if (w.kind == WatchKind::Tool) {
            d_.m_.tool().advance(t);  // the table moves on its own
            v = d_.tool_value(w.quantity, w.axis);
        } else {
            const std::uint8_t op = d_.m_.peek(last_pc);
            v = d_.part_watch_value(w, op == 0xD3 || op == 0xDB);  // OUT, IN
        }
        if (v == w.last_value) continue;
        const std::int64_t old = w.last_value;
        w.last_value = v;
        if (w.condition) {
            try {
                if (w.condition->eval(d_.m_) == 0) continue;
            } catch (const ExprError&) {
                continue;
            }
        }
        if (!hits) {
            ++w.hits;
            if (w.ignore > 0) {
                --w.ignore;
                continue;
            }
            if (w.hit_condition && !w.hit_condition->met(w.hits)) continue;
        }
        if (!hit.number) hit.number = w.number;
        hit.changes.push_back({w.number, w.what, old, v, w.kind == WatchKind::Tool ? 0 : w.digits, false});
    }
    if (hit.changes.empty()) return false;
    if (hits) {
        hits->push_back(std::move(hit));
        return false;
    }
    stop_hit = std::move(hit);
    return true;
}

void Debugger::Observer::memory_access(std::uint16_t addr, bool write) {
    for (Watchpoint& w : d_.watchpoints_) {
        if (!w.enabled || addr < w.first || addr > w.last) continue;
        if (w.kind == WatchKind::Write && write) {
            // A byte or a word: its value; a longer range: the byte written, against its shadow.
            const bool wide = w.last - w.first > 1;
            std::int64_t before = 0, after = 0;
            std::string what = w.what;
            if (wide) {
                std::uint8_t& shadow = w.shadow[static_cast<std::size_t>(addr - w.first)];
                before = shadow;
                after = d_.m_.peek(addr);
                shadow = static_cast<std::uint8_t>(after);
                what = fmt::format("{} at {:04X}H", w.what, addr);
            } else {
                before = w.last_value;
                after = memory_value(d_.m_, w);
                w.last_value = after;
            }
            if (after == before) continue;  // written with the value it had: not a change (gdb's watch)
            const Change change{w.number, what, before, after, !wide && w.last != w.first ? 4 : 2, false};
            auto it = std::find_if(pending.begin(), pending.end(), [&](const Hit& h) { return h.number == w.number; });
            if (it == pending.end())
                pending.push_back({0, StopReason::Watchpoint, w.number, {change}, addr, last_pc});
            else if (wide)
                it->changes.push_back(change);
            else
                it->changes.front().new_value = after;  // the second byte of the same word
        } else if ((w.kind == WatchKind::Read && !write) || w.kind == WatchKind::Access) {
            if (std::any_of(pending.begin(), pending.end(), [&](const Hit& h) { return h.number == w.number; })) continue;
            pending.push_back({0, StopReason::Watchpoint, w.number,
                               {{w.number, w.what, 0, d_.m_.peek(addr), 2, true}}, addr, last_pc});
        }
    }
}

bool Debugger::Observer::on_read(std::uint16_t addr, std::uint8_t) {
    if (!read_[addr]) return false;
    memory_access(addr, false);
    return !pending.empty() && !hits;
}

bool Debugger::Observer::on_write(std::uint16_t addr, std::uint8_t) {
    if (!write_[addr]) return false;
    memory_access(addr, true);
    return !pending.empty() && !hits;
}

bool Debugger::Observer::on_io(std::uint8_t port, std::uint8_t value, bool is_out) {
    if (!(is_out ? port_out_[port] : port_in_[port])) return false;
    for (const Watchpoint& w : d_.watchpoints_) {
        if (!w.enabled || w.kind != WatchKind::Port || w.first != port) continue;
        if (w.dir != PortDir::Any && (w.dir == PortDir::Out) != is_out) continue;
        if (w.value && *w.value != value) continue;
        pending.push_back({0, StopReason::Watchpoint, w.number,
                           {{w.number, w.what + (w.dir != PortDir::Any ? "" : is_out ? " (OUT)" : " (IN)"), 0, value, 2, true}}, port, last_pc});
    }
    return !pending.empty() && !hits;
}

std::vector<Hit> Debugger::Observer::decide_pending(bool count) {
    std::vector<Hit> kept;
    for (Hit& h : pending) {
        Watchpoint* w = d_.find_wp(h.number);
        if (!w) continue;
        if (w->condition) {
            try {
                if (w->condition->eval(d_.m_) == 0) continue;
            } catch (const ExprError&) {
                continue;
            }
        }
        if (count) {
            ++w->hits;
            if (w->ignore > 0) {
                --w->ignore;
                continue;
            }
            if (w->hit_condition && !w->hit_condition->met(w->hits)) continue;
        }
        kept.push_back(std::move(h));
    }
    pending.clear();
    return kept;
}

void Debugger::Observer::flush_pending(std::uint64_t t) {
    for (Hit& h : decide_pending(false)) {
        h.t = t;
        hits->push_back(std::move(h));
    }
}

// ---- History --------------------------------------------------------------------------------------

void Debugger::History::take(const Machine& m) {
    if (!points.empty() && points.back().t >= m.now()) return;
    points.push_back({m.now(), m.snapshot_bytes(), m.input_log().size()});
    thin();
}

void Debugger::History::thin() {
    // Beyond kKeep checkpoints, every other one of the older half goes: recent history stays
    // dense (a step back is cheap), old history sparser (going far back re-executes more).
    constexpr std::size_t kKeep = 2048;
    if (points.size() <= kKeep) return;
    std::vector<Checkpoint> kept;
    const std::size_t half = points.size() / 2;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (i == 0 || i >= half || i % 2 == 0) kept.push_back(std::move(points[i]));
    points = std::move(kept);
}

void Debugger::History::drop_from(std::uint64_t t) {
    std::erase_if(points, [t](const Checkpoint& c) { return c.t >= t; });
}

const Checkpoint* Debugger::History::before(std::uint64_t t, bool at_ok) const {
    for (auto it = points.rbegin(); it != points.rend(); ++it)
        if (it->t < t || (at_ok && it->t == t)) return &*it;
    return nullptr;
}

void Debugger::History::restore(Machine& m, const Checkpoint& c) const {
    // Every input of this timeline not applied by the checkpoint's time: the ones applied since
    // (in the log) and the ones still queued. Keys pressed later are not lost by going back.
    std::vector<InputEvent> future(m.input_log().begin() + static_cast<std::ptrdiff_t>(std::min(c.log_size, m.input_log().size())),
                                   m.input_log().end());
    for (const InputEvent& e : m.inputs().pending()) future.push_back(e);
    const std::uint64_t seq = m.inputs().next_seq();
    m.restore_bytes(c.bytes);
    m.rewind_inputs(c.log_size, future, seq);
}

}  // namespace alp85::debug
