// Running under the debugger: the run loop, steps with CALL/RET tracking, stops as values.
#include "emu/debug/debugger.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "asm/isa.h"
#include "emu/debug/observer.h"

namespace alp85::debug {

std::string_view name(StopReason reason) {
    switch (reason) {
        case StopReason::Deadline: return "deadline";
        case StopReason::Condition: return "condition";
        case StopReason::Breakpoint: return "breakpoint";
        case StopReason::Watchpoint: return "watchpoint";
        case StopReason::Target: return "target";
        case StopReason::Step: return "step";
        case StopReason::Finished: return "finished";
        case StopReason::Interrupted: return "interrupted";
        case StopReason::HistoryStart: return "history-start";
        case StopReason::Error: return "error";
        case StopReason::Halted: return "halted";
        case StopReason::Runaway: return "runaway";
        case StopReason::Paused: return "paused";
    }
    return "?";
}

Debugger::Debugger(Machine& machine)
    : m_(machine), observer_(std::make_unique<Observer>(*this)), history_(std::make_unique<History>()) {}

Debugger::~Debugger() {
    if (m_.observer() == observer_.get()) m_.set_observer(nullptr);
}

Stop Debugger::here(StopReason reason) const {
    Stop s;
    s.reason = reason;
    s.at = m_.now();
    s.pc = m_.cpu().regs().pc;
    s.line = program_.line_of(s.pc);
    return s;
}

CpuStatus Debugger::cpu_status() const {
    const I8085& c = m_.cpu();
    return {c.halted(), c.interrupts_enabled(), c.masks(), c.rst75_latched(), c.trap_latched(), c.sod(), c.rim_value(),
            c.variant()};
}

bool Debugger::in_ram(std::uint16_t address) const {
    for (const board::MemoryRegion& r : m_.memory_map())
        if (r.kind == board::MemoryKind::Ram && address >= r.base && address - r.base < r.size) return true;
    return false;
}

void Debugger::arm() {
    Observer& mon = *observer_;
    mon.rebuild();
    const bool needed = mon.replay && !mon.hits ? mon.record != nullptr : mon.needed();
    m_.set_observer(needed ? &mon : nullptr);
}

void Debugger::rebaseline() {
    m_.tool().advance(m_.now());
    for (Watchpoint& w : watchpoints_) {
        switch (w.kind) {
            case WatchKind::Write:
                if (w.last - w.first > 1) {
                    w.shadow.resize(static_cast<std::size_t>(w.last - w.first) + 1);
                    for (std::uint32_t a = w.first; a <= w.last; ++a) w.shadow[a - w.first] = m_.peek(static_cast<std::uint16_t>(a));
                } else {
                    w.last_value = m_.peek(w.first) | (w.last != w.first ? m_.peek(w.last) << 8 : 0);
                }
                break;
            case WatchKind::Tool: w.last_value = tool_value(w.quantity, w.axis); break;
            case WatchKind::Part:
                w.shadow.clear();
                w.last_value = part_watch_value(w);
                break;
            default: break;
        }
    }
}

Stop Debugger::finish_stop(Stop s) {
    if (s.reason == StopReason::Breakpoint) {
        const Breakpoint* b = breakpoint(s.number);
        if (b && b->temporary) remove(s.number);
    }
    return s;
}

namespace {
std::string runaway_message(const Machine& m, std::uint16_t pc, std::optional<std::uint16_t> after) {
    const Variant v = m.cpu().variant();
    std::string text = fmt::format("the program ran away: it fetched an instruction at {:04X}H ({}), where no program is",
                                   pc, disassemble(m.bus(), pc, v).text);
    if (after) text += fmt::format(", after {:04X}H ({})", *after, disassemble(m.bus(), *after, v).text);
    return text;
}
}  // namespace

std::optional<Stop> Debugger::drive(const Budget& budget) {
    Active& run = *active_;
    check_inputs();
    Observer& mon = *observer_;
    mon.skip_at = run.first ? std::optional<std::uint64_t>(m_.now()) : std::nullopt;
    run.first = false;
    mon.stop_hit.reset();
    mon.pending.clear();
    mon.error.clear();
    mon.target_reached = false;
    rebaseline();
    arm();
    const auto started = std::chrono::steady_clock::now();
    if (m_.now() >= time_limit_ && run.until > m_.now()) return end_run(time_limit_stop());
    const std::uint64_t until = std::min(run.until, time_limit_);
    const std::uint64_t slice_end = budget.tstates < until - std::min(until, m_.now()) ? m_.now() + budget.tstates : until;
    const auto stop_condition = [&] { return interrupt_.load() || halted_ || (run.condition && run.condition()); };
    for (;;) {
        std::uint64_t chunk = std::min(slice_end, m_.now() + kHistoryInterval);  // Ctrl-C is seen between chunks
        if (history_on_) {
            if (history_->due(m_.now())) history_->take(m_);
            chunk = std::min(slice_end, std::max(history_->next_due(), m_.now() + 1));
        }
        switch (m_.run_until(chunk, stop_condition)) {
            case Machine::RunEnd::Condition:
                if (interrupt_.exchange(false)) return end_run(here(StopReason::Interrupted));
                if (halted_) {
                    Stop s = here(StopReason::Halted);
                    s.message = fmt::format("the CPU halted: HLT at {:04X}H", static_cast<std::uint16_t>(s.pc - 1));
                    return end_run(s);
                }
                return end_run(here(StopReason::Condition));
            case Machine::RunEnd::Deadline:
                if (m_.now() >= run.until) return end_run(here(StopReason::Deadline));
                if (m_.now() >= time_limit_) return end_run(time_limit_stop());
                if (m_.now() >= slice_end) return std::nullopt;
                if (budget.seconds > 0 &&
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >= budget.seconds)
                    return std::nullopt;
                continue;
            case Machine::RunEnd::Target: return end_run(here(StopReason::Target));
            case Machine::RunEnd::Observer: break;
        }
        if (!mon.error.empty()) {
            Stop s = here(StopReason::Error);
            s.message = mon.error;
            return end_run(s);
        }
        if (mon.stop_hit) {
            Stop s = from_hit(here(mon.stop_hit->reason), *mon.stop_hit);
            if (s.reason == StopReason::Runaway) s.message = runaway_message(m_, s.pc, s.after);
            return end_run(s);
        }
        if (!mon.pending.empty()) {
            const std::vector<Hit> kept = mon.decide_pending(true);
            if (!kept.empty()) {
                Stop s = from_hit(here(StopReason::Watchpoint), kept.front());
                for (std::size_t i = 1; i < kept.size(); ++i)
                    s.changes.insert(s.changes.end(), kept[i].changes.begin(), kept[i].changes.end());
                return end_run(s);
            }
        }
        if (mon.target_reached) return end_run(here(StopReason::Target));
        mon.skip_at.reset();  // a watch whose condition was false: on, a breakpoint here still stops
    }
}

std::optional<Stop> Debugger::begin(Active a, std::function<bool(const I8085&)> target) {
    if (active_) pause();
    if (a.stop_at_halt && m_.cpu().halted() && !m_.can_wake()) {
        // Nothing can end the HLT but RESET: a run would only idle (gdb: the program is not running).
        Stop s = here(StopReason::Halted);
        s.message = fmt::format("the CPU is halted (HLT at {:04X}H) with nothing to wake it: only RESET does",
                                static_cast<std::uint16_t>(s.pc - 1));
        return s;
    }
    if (target) {
        const std::uint64_t start = m_.now();
        observer_->target = [start, t = std::move(target)](const I8085& cpu) { return cpu.tstates() != start && t(cpu); };
    }
    halted_ = false;
    if (a.stop_at_halt) m_.cpu().on_halt = [this] {
        halted_ = true;
        m_.cpu().request_stop();
    };
    active_ = std::move(a);
    return std::nullopt;
}

Stop Debugger::end_run(Stop s) {
    const Active run = std::move(*active_);
    active_.reset();
    observer_->target = nullptr;
    m_.cpu().on_halt = nullptr;
    halted_ = false;
    arm();
    if (run.target_as && s.reason == StopReason::Target) s.reason = *run.target_as;
    if (run.limit && s.reason == StopReason::Deadline) {
        // The guard of machine time gave up: say what did not happen in it.
        const std::string_view what = !run.target_as                           ? "no breakpoint or watchpoint stopped the run"
                                      : *run.target_as == StopReason::Finished ? "the routine did not return"
                                      : *run.target_as == StopReason::Target   ? "the PC did not reach the location"
                                                                               : "the line did not end";
        s.message = fmt::format("{} within {:.0f} s of simulated time", what, board::ms_from_tstates(run.limit) / 1000.0);
    }
    s = finish_stop(std::move(s));
    if (run.emit_stops && (s.reason == StopReason::Breakpoint || s.reason == StopReason::Watchpoint ||
                           s.reason == StopReason::Error || s.reason == StopReason::Runaway))
        emit({Event::Kind::Stopped, s, {}, run.origin});
    return s;
}

std::optional<Stop> Debugger::resume(const Budget& budget) {
    if (!active_) return here(StopReason::Paused);
    return drive(budget);
}

Stop Debugger::pause() {
    if (!active_) return here(StopReason::Paused);
    return end_run(here(StopReason::Paused));
}

Stop Debugger::complete(std::optional<Stop> begun) {
    if (begun) return *begun;
    for (;;)
        if (auto s = drive({})) return *s;
}

Stop Debugger::run_until(std::uint64_t until, const std::function<bool()>& condition, const Origin& origin) {
    Active a;
    a.until = until;
    a.condition = condition;
    a.emit_stops = true;
    a.origin = origin;
    return complete(begin(std::move(a)));
}

Stop Debugger::time_limit_stop() {
    time_limit_hit_ = true;
    Stop s = here(StopReason::Error);
    s.message = time_limit_why_;
    return s;
}

Stop Debugger::run_to(std::uint16_t pc, std::uint64_t until) {
    check_inputs();
    // Breakpoints and watchpoints do not stop it: their observer is off for the run (one left on
    // stopped the machine at a breakpoint on the way again and again, until the deadline).
    m_.set_observer(nullptr);
    for (;;) {
        if (m_.now() >= time_limit_ && until > m_.now()) return time_limit_stop();
        if (interrupt_.exchange(false)) return here(StopReason::Interrupted);
        std::uint64_t chunk = std::min({until, time_limit_, m_.now() + kHistoryInterval});  // Ctrl-C is seen between chunks
        if (history_on_) {
            if (history_->due(m_.now())) history_->take(m_);
            chunk = std::min(chunk, std::max(history_->next_due(), m_.now() + 1));
        }
        const Machine::RunEnd s = m_.run_to(pc, chunk);
        if (s == Machine::RunEnd::Target || m_.now() >= until) {
            arm();
            return here(s == Machine::RunEnd::Target ? StopReason::Target : StopReason::Deadline);
        }
    }
}

std::optional<Stop> Debugger::begin_continue(std::uint64_t limit, bool stop_at_halt) {
    Active a;
    a.until = limit > ~std::uint64_t{0} - m_.now() ? ~std::uint64_t{0} : m_.now() + limit;
    a.limit = limit;
    a.stop_at_halt = stop_at_halt;
    return begin(std::move(a));
}

namespace {
// The flow class of the instruction at the PC, as this CPU decodes it (asm/isa.h).
isa::Flow flow_at(const Machine& m, std::uint16_t pc) {
    return isa::flow_of(m.peek(pc), m.cpu().variant() == Variant::I8080);
}
}  // namespace

Stop Debugger::stepi() {
    if (active_) pause();
    check_inputs();
    if (history_on_ && history_->due(m_.now())) history_->take(m_);
    Observer& mon = *observer_;
    mon.skip_at = m_.now();
    mon.stop_hit.reset();
    mon.pending.clear();
    mon.error.clear();
    rebaseline();
    arm();
    m_.step();
    mon.check_state(m_.cpu());  // a table that moved during the instruction
    const std::vector<Hit> kept = mon.decide_pending(true);
    if (!kept.empty()) return from_hit(here(StopReason::Watchpoint), kept.front());
    if (mon.stop_hit && mon.stop_hit->reason == StopReason::Watchpoint) {
        Stop s = from_hit(here(StopReason::Watchpoint), *mon.stop_hit);
        mon.stop_hit.reset();
        return s;
    }
    return here(StopReason::Step);
}

std::optional<Stop> Debugger::begin_with_target(std::function<bool(const I8085&)> target, StopReason reason) {
    Active a;
    a.until = m_.now() + continue_limit_;
    a.limit = continue_limit_;  // for the message when it gives up
    a.stop_at_halt = true;
    a.target_as = reason;
    return begin(std::move(a), std::move(target));
}

std::optional<Stop> Debugger::begin_step() {
    const Registers before = m_.cpu().regs();
    const isa::Flow flow = flow_at(m_, before.pc);
    Stop s = stepi();
    if (s.reason != StopReason::Step) return s;
    const Registers& now = m_.cpu().regs();
    // Into a routine without source lines (the monitor's, say) from one with: run it whole.
    const bool entered = isa::may_call(flow) && now.sp == static_cast<std::uint16_t>(before.sp - 2);
    if (entered && !program_.line_of(now.pc) && program_.line_of(before.pc)) {
        const auto slot = return_slot();
        if (!slot) return s;
        const std::uint32_t above = *slot + 2u;
        return begin_with_target([above](const I8085& cpu) { return cpu.regs().sp >= above; }, StopReason::Step);
    }
    return s;
}

std::optional<Stop> Debugger::begin_next() {
    const Registers r = m_.cpu().regs();
    const std::uint8_t op = m_.peek(r.pc);
    if (!isa::may_call(flow_at(m_, r.pc))) return stepi();
    const auto ret = static_cast<std::uint16_t>(r.pc + isa::kOpcodes[op].length);
    const std::uint16_t sp = r.sp;
    return begin_with_target([ret, sp](const I8085& cpu) { return cpu.regs().pc == ret && cpu.regs().sp >= sp; },
                             StopReason::Step);
}

std::optional<Stop> Debugger::begin_finish() {
    const auto slot = return_slot();
    if (!slot) {
        Stop s = here(StopReason::Error);
        s.message = "\"finish\" not meaningful in the outermost routine (no return address on the stack)";
        return s;
    }
    const std::uint32_t above = *slot + 2u;  // the return address popped: the routine has returned
    return begin_with_target([above](const I8085& cpu) { return cpu.regs().sp >= above; }, StopReason::Finished);
}

std::optional<Stop> Debugger::begin_advance(std::uint16_t pc) {
    return begin_with_target([pc](const I8085& cpu) { return cpu.regs().pc == pc; }, StopReason::Target);
}

std::optional<Stop> Debugger::begin_until(std::optional<std::uint16_t> pc) {
    const auto slot = return_slot();
    const std::uint32_t above = slot ? *slot + 2u : 0x10000u;
    if (pc) {
        const std::uint16_t to = *pc;
        return begin_with_target([to, above](const I8085& cpu) { return cpu.regs().pc == to || cpu.regs().sp >= above; },
                                 StopReason::Target);
    }
    // Past the current instruction in this routine: out of a loop whose jump goes back.
    const Registers r = m_.cpu().regs();
    if (isa::may_call(flow_at(m_, r.pc))) return begin_next();
    const std::uint16_t from = r.pc, sp = r.sp;
    return begin_with_target(
        [from, sp, above](const I8085& cpu) {
            return (cpu.regs().pc > from && cpu.regs().sp == sp) || cpu.regs().sp >= above;
        },
        StopReason::Step);
}

void Debugger::set_runaway_guard(const std::bitset<0x10000>* code) {
    if (code) code_ = *code;
    else code_.reset();
    observer_->runaway_armed = false;
    arm();
}


// ---- looking ---------------------------------------------------------------------------------------

Debugger::Value Debugger::evaluate(std::string_view expression) const {
    Value v;
    ExprError err;
    const auto e = Expr::parse(expression, program_, err, Expr::Names::RegistersFirst, 0, &vars_);
    if (!e) {
        v.error = err.message;
        v.col = err.col;
        return v;
    }
    try {
        v.value = e->eval(m_);
        v.width = e->width();
    } catch (const ExprError& x) {
        v.error = x.message;
        v.col = x.col;
    }
    return v;
}

std::int64_t Debugger::tool_value(ToolQuantity q, periph::MachineTool::Axis axis) const {
    const periph::MachineTool& t = m_.tool();
    switch (q) {
        case ToolQuantity::Steps: return std::llround(t.table_steps(axis));
        case ToolQuantity::Count: return t.transducer_count(axis);
        case ToolQuantity::Lost: return t.lost_steps(axis);
        case ToolQuantity::EndStop: return t.end_stop(axis).at;
    }
    return 0;
}

periph::Description Debugger::describe(const periph::Part& part) const {
    periph::Description d;
    d.now = m_.now();
    part.describe(d);
    return d;
}

std::int64_t Debugger::part_watch_value(Watchpoint& w, bool io) {
    const periph::Part* p = m_.find_part(w.part);
    if (!p) return w.last_value;
    if (!io && !w.shadow.empty() && p->now() == w.part_now && m_.input_log().size() == w.part_inputs) return w.last_value;
    w.part_now = p->now();
    w.part_inputs = m_.input_log().size();
    part_state_.clear();
    p->save(part_state_);
    if (part_state_ == w.shadow) return w.last_value;
    w.shadow.swap(part_state_);
    periph::Description d;
    d.now = p->now();
    p->describe(d);
    const periph::Field* f = d.find_watch(w.field);
    return f ? f->value : w.last_value;
}

}  // namespace alp85::debug
