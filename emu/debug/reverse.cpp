// Reverse execution: the machine goes back to a checkpoint (a whole snapshot: memory, chips,
// machine tool, time) and runs forward again to the wanted instruction. The machine is
// deterministic, so the re-run is the run; while it runs the observer records each instruction
// boundary or each breakpoint/watchpoint hit, from which the wanted position is chosen.
#include <fmt/format.h>

#include "asm/isa.h"
#include "emu/debug/debugger.h"
#include "emu/debug/observer.h"

namespace alp85::debug {

void Debugger::set_history(bool on, std::uint64_t interval) {
    history_on_ = on;
    history_->points.clear();
    history_->interval = interval ? interval : kHistoryInterval;
    if (on) history_->take(m_);
}

void Debugger::state_changed(bool new_timeline) {
    rebaseline();
    if (!history_on_) return;
    if (new_timeline) history_->points.clear();
    history_->drop_from(m_.now());
    history_->take(m_);
}

void Debugger::check_inputs() {
    const std::uint64_t seq = m_.inputs().next_seq();
    if (seq == seen_seq_) return;
    seen_seq_ = seq;
    if (history_on_) history_->drop_from(m_.now() + 1);
}

std::uint64_t Debugger::history_start() const {
    return history_->points.empty() ? m_.now() : history_->points.front().t;
}
std::size_t Debugger::history_snapshots() const { return history_->points.size(); }

void Debugger::replay(const Checkpoint& c, std::uint64_t t, std::vector<Boundary>* record, std::vector<Hit>* hits) {
    Observer& mon = *observer_;
    const auto target = std::move(mon.target);
    mon.target = nullptr;
    history_->restore(m_, c);
    replaying_ = true;
    mon.replay = true;
    mon.record = record;
    mon.hits = hits;
    mon.skip_at.reset();
    mon.pending.clear();
    mon.stop_hit.reset();
    rebaseline();
    arm();
    m_.pause_sampler(true);
    while (m_.now() < t)
        if (m_.run_until(t) == Machine::RunEnd::Deadline) break;
    if (hits && !mon.pending.empty()) {
        for (Hit& h : mon.decide_pending(false)) {
            h.t = m_.now();
            hits->push_back(std::move(h));
        }
    }
    m_.pause_sampler(false);
    mon.replay = false;
    mon.record = nullptr;
    mon.hits = nullptr;
    replaying_ = false;
    mon.target = target;
    rebaseline();
    arm();
}

Stop Debugger::no_history(std::string why) {
    Stop s = here(StopReason::HistoryStart);
    s.message = std::move(why);
    return s;
}

namespace {
// How the call depth changes from boundary b to the next one (whose registers are `next`).
int depth_delta(const Boundary& b, const Registers& next, bool i8080) {
    const isa::Flow flow = isa::flow_of(b.op, i8080);
    const bool pushed = next.sp == static_cast<std::uint16_t>(b.regs.sp - 2);
    const bool popped = next.sp == static_cast<std::uint16_t>(b.regs.sp + 2);
    if (isa::may_call(flow)) return pushed ? 1 : 0;
    if (isa::may_return(flow)) return popped ? -1 : 0;
    const std::uint8_t op = b.op;
    const bool push = (op & 0xCF) == 0xC5, sp_op = op == 0x3B || op == 0x31 || op == 0xF9 || op == 0xE3;
    // Anything else that leaves two bytes pushed and the PC elsewhere: an interrupt acknowledged.
    const bool vector = next.pc <= 0x3C && (next.pc % 8 == 0 || next.pc % 8 == 4);  // RST n, TRAP, RST x.5
    if (pushed && !push && !sp_op && !isa::may_jump(flow) && vector) return 1;
    return 0;
}
}  // namespace

Stop Debugger::reverse_stepi() {
    if (!history_on_) return no_history("reverse execution needs the history (set history on)");
    const std::uint64_t now = m_.now();
    const Checkpoint* c = history_->before(now);
    if (!c) return no_history("no more reverse-execution history");
    std::vector<Boundary> b;
    replay(*c, now, &b, nullptr);
    std::uint64_t target = c->t;
    for (const Boundary& x : b)
        if (x.t < now) target = x.t;
    replay(*c, target, nullptr, nullptr);
    return here(StopReason::Step);
}

Stop Debugger::reverse_step() { return reverse_stepi(); }

Stop Debugger::reverse_frame(bool finish) {
    if (!history_on_) return no_history("reverse execution needs the history (set history on)");
    const std::uint64_t now = m_.now();
    for (const Checkpoint* c = history_->before(now); c; c = history_->before(c->t)) {
        std::vector<Boundary> b;
        replay(*c, now, &b, nullptr);
        const Registers at_now = m_.cpu().regs();
        int depth = 0;  // of boundary j, relative to now
        for (std::size_t j = b.size(); j-- > 0;) {
            if (b[j].t >= now) continue;
            const Registers& next = j + 1 < b.size() && b[j + 1].t <= now ? b[j + 1].regs : at_now;
            depth -= depth_delta(b[j], next, m_.cpu().variant() == Variant::I8080);
            if (finish ? depth < 0 : depth <= 0) {
                const std::uint64_t target = b[j].t;
                replay(*c, target, nullptr, nullptr);
                return here(finish ? StopReason::Finished : StopReason::Step);
            }
        }
    }
    const Checkpoint& oldest = history_->points.front();
    replay(oldest, oldest.t, nullptr, nullptr);
    return no_history(finish ? "no more reverse-execution history: the routine was entered before it began"
                             : "no more reverse-execution history");
}

Stop Debugger::reverse_next() { return reverse_frame(false); }
Stop Debugger::reverse_finish() { return reverse_frame(true); }

Stop Debugger::reverse_continue() {
    if (!history_on_) return no_history("reverse execution needs the history (set history on)");
    const std::uint64_t now = m_.now();
    std::uint64_t end = now;
    for (const Checkpoint* c = history_->before(now); c; end = c->t, c = history_->before(c->t)) {
        std::vector<Hit> hits;
        replay(*c, end, nullptr, &hits);
        const Hit* best = nullptr;
        for (const Hit& h : hits)
            if (h.t < now && (!best || h.t >= best->t)) best = &h;
        if (!best) continue;
        const Hit hit = *best;
        replay(*c, hit.t, nullptr, nullptr);
        Stop s = here(hit.reason);
        s.number = hit.number;
        s.numbers = hit.numbers;
        s.changes = hit.changes;
        s.data = hit.data;
        s.after = hit.after;
        return s;
    }
    const Checkpoint& oldest = history_->points.front();
    replay(oldest, oldest.t, nullptr, nullptr);
    return no_history("no more reverse-execution history");
}

std::vector<Executed> Debugger::last_instructions(std::size_t n) {
    std::vector<Executed> out;
    if (!history_on_ || n == 0) return out;
    const std::uint64_t now = m_.now();
    for (const Checkpoint* c = history_->before(now); c; c = history_->before(c->t)) {
        std::vector<Boundary> b;
        replay(*c, now, &b, nullptr);
        std::erase_if(b, [now](const Boundary& x) { return x.t >= now; });
        if (b.size() < n && history_->before(c->t)) continue;  // reach further back
        const Registers at_now = m_.cpu().regs();
        const std::size_t first = b.size() > n ? b.size() - n : 0;
        for (std::size_t j = first; j < b.size(); ++j)
            out.push_back({b[j].t, b[j].regs.pc, b[j].regs, j + 1 < b.size() ? b[j + 1].regs : at_now});
        return out;
    }
    return out;
}

}  // namespace alp85::debug
