// Reverse execution: the machine goes back to a checkpoint (a whole snapshot: memory, chips,
// machine tool, time) and runs forward again to the wanted instruction. The machine is
// deterministic, so the re-run is the run; while it runs the observer records each instruction
// boundary or each breakpoint/watchpoint hit, from which the wanted position is chosen.
#include <algorithm>
#include <chrono>
#include <deque>
#include <map>

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

bool Debugger::replay(const Checkpoint& c, std::uint64_t t, std::vector<Boundary>* record, std::vector<Hit>* hits,
                      const std::function<void()>& drain) {
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
    // A slice at a time: Ctrl-C is seen between slices, and what a slice recorded is handed on
    // and dropped (a reverse command's memory does not grow with the span it re-executes).
    bool whole = true;
    while (m_.now() < t) {
        if (interrupt_.load()) {
            whole = false;
            break;
        }
        const std::uint64_t slice = std::min(t, m_.now() + kReplaySlice);
        while (m_.now() < slice)
            if (m_.run_until(slice) == Machine::RunEnd::Deadline) break;
        if (hits && m_.now() >= t && !mon.pending.empty()) {
            for (Hit& h : mon.decide_pending(false)) {
                h.t = m_.now();
                hits->push_back(std::move(h));
            }
        }
        if (drain) drain();
        // Due across re-executions: a walk back over short intervals re-executes many, each
        // shorter than the period.
        if (poll_ && std::chrono::steady_clock::now() >= poll_due_) {
            poll_();
            poll_due_ = std::chrono::steady_clock::now() + kPollPeriod;
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
    return whole;
}

Stop Debugger::interrupted_reverse() {
    interrupt_.store(false);
    Stop s = here(StopReason::Interrupted);
    s.message = "interrupted: the machine is where re-execution had got to";
    return s;
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
    std::uint64_t target = c->t;
    const auto last_before_now = [&] {
        for (const Boundary& x : b)
            if (x.t < now) target = x.t;
        b.clear();
    };
    if (!replay(*c, now, &b, nullptr, last_before_now)) return interrupted_reverse();
    if (!replay(*c, target, nullptr, nullptr)) return interrupted_reverse();
    return here(StopReason::Step);
}

Stop Debugger::reverse_step() { return reverse_stepi(); }

// Back through the checkpoints one span at a time (the latest first), each re-executed once:
// a forward pass over a span gives each boundary's call depth relative to the span's start,
// and keeps for each depth only the latest boundary at it. The depth of the span's end relative
// to now is known from the spans after it, so the wanted boundary (the latest one shallower
// than now for finish, not deeper for next) is found without keeping the span's boundaries.
namespace {
constexpr std::size_t kMaxDepths = 65'536;  // call depths one interval's table holds (about 3 MB)
}  // namespace

Stop Debugger::reverse_frame(bool finish) {
    if (!history_on_) return no_history("reverse execution needs the history (set history on)");
    if (finish && !return_slot()) {
        Stop s = here(StopReason::Error);
        s.message = "\"reverse-finish\" not meaningful in the outermost routine (no return address on the stack)";
        return s;
    }
    const bool i8080 = m_.cpu().variant() == Variant::I8080;
    const std::uint64_t now = m_.now();
    int end_depth = 0;  // the depth at the span's end, relative to now
    std::uint64_t end = now;
    for (const Checkpoint* c = history_->before(now); c; end = c->t, c = history_->before(c->t)) {
        std::map<int, std::uint64_t> latest;  // depth from the span's start -> the latest boundary at it
        int depth = 0;
        std::optional<Boundary> prev;
        std::vector<Boundary> b;
        bool too_deep = false;
        const auto fold = [&] {
            for (const Boundary& x : b) {
                if (x.t >= end || too_deep) continue;
                if (prev) depth += depth_delta(*prev, x.regs, i8080);
                latest[depth] = x.t;
                prev = x;
                too_deep = latest.size() > kMaxDepths;
            }
            b.clear();
        };
        if (!replay(*c, end, &b, nullptr, fold)) return interrupted_reverse();
        if (too_deep) {  // the memory cap: back to where the command began, and why it stopped
            if (const Checkpoint* from = history_->before(now); from && !replay(*from, now, nullptr, nullptr))
                return interrupted_reverse();
            Stop s = here(StopReason::Error);
            s.message = fmt::format("{}: the call depth takes more than {} values within one snapshot interval "
                                    "(SP reset inside calls?); stopped at the memory cap of reverse execution",
                                    finish ? "reverse-finish" : "reverse-next", kMaxDepths);
            return s;
        }
        if (prev) depth += depth_delta(*prev, m_.cpu().regs(), i8080);  // to the boundary at the span's end
        // A boundary at depth d from the span's start is at d - depth + end_depth from now.
        const int bound = depth - end_depth;
        std::optional<std::uint64_t> best;
        for (const auto& [d, t] : latest) {
            if (finish ? d >= bound : d > bound) break;
            if (!best || t > *best) best = t;
        }
        if (best) {
            if (!replay(*c, *best, nullptr, nullptr)) return interrupted_reverse();
            return here(finish ? StopReason::Finished : StopReason::Step);
        }
        end_depth -= depth;
    }
    const Checkpoint& oldest = history_->points.front();
    if (!replay(oldest, oldest.t, nullptr, nullptr)) return interrupted_reverse();
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
        std::optional<Hit> best;  // the latest hit before now in this span
        const auto keep_latest = [&] {
            for (Hit& h : hits)
                if (h.t < now && (!best || h.t >= best->t)) best = std::move(h);
            hits.clear();
        };
        if (!replay(*c, end, nullptr, &hits, keep_latest)) return interrupted_reverse();
        if (!best) continue;
        const Hit hit = std::move(*best);
        if (!replay(*c, hit.t, nullptr, nullptr)) return interrupted_reverse();
        return from_hit(here(hit.reason), hit);
    }
    const Checkpoint& oldest = history_->points.front();
    if (!replay(oldest, oldest.t, nullptr, nullptr)) return interrupted_reverse();
    return no_history("no more reverse-execution history");
}

std::vector<Executed> Debugger::last_instructions(std::size_t n) {
    std::vector<Executed> out;  // newest first while collecting
    if (!history_on_ || n == 0) return out;
    const std::uint64_t now = m_.now();
    std::uint64_t end = now;
    for (const Checkpoint* c = history_->before(now); c && out.size() < n; end = c->t, c = history_->before(c->t)) {
        const std::size_t want = n - out.size();
        std::deque<Boundary> kept;  // the span's last `want` boundaries
        std::vector<Boundary> b;
        const auto keep_last = [&] {
            for (Boundary& x : b) {
                if (x.t >= end) continue;
                kept.push_back(x);
                if (kept.size() > want) kept.pop_front();
            }
            b.clear();
        };
        if (!replay(*c, end, &b, nullptr, keep_last)) break;
        Registers after = m_.cpu().regs();
        for (auto j = kept.rbegin(); j != kept.rend(); ++j) {
            out.push_back({j->t, j->regs.pc, j->regs, after});
            after = j->regs;
        }
    }
    interrupt_.store(false);
    // Back to now (one span re-executed, or none when the last span ended there).
    if (m_.now() != now) {
        if (const Checkpoint* c = history_->before(now, true)) replay(*c, now, nullptr, nullptr);
    }
    std::reverse(out.begin(), out.end());
    return out;
}

}  // namespace alp85::debug
