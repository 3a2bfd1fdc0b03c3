#include "emu/debug/signal_trace.h"

#include <algorithm>

#include <fmt/format.h>

namespace alp85::debug {

SignalTrace::~SignalTrace() { stop(); }

void SignalTrace::start(Machine& machine, const std::vector<std::string>& selection, std::uint64_t span,
                        std::uint64_t period) {
    PinTap tap;
    tap.attach(machine, selection, period);  // throws before the open trace is touched
    stop();
    tap_ = std::move(tap);
    selection_ = selection;
    span_ = std::max<std::uint64_t>(span, 1);
    start_t_ = last_t_ = machine.now();
    for (const PinTap::Channel& c : tap_.channels()) traces_.push_back({c.pin, c.level, c.value, {}});
    machine_ = &machine;
    machine.add_probe(this);
}

void SignalTrace::stop() {
    if (machine_) machine_->remove_probe(this);
    machine_ = nullptr;
    tap_.detach();
    traces_.clear();
}

void SignalTrace::set_span(std::uint64_t span) {
    span_ = std::max<std::uint64_t>(span, 1);
    trim();
}

void SignalTrace::trim() {
    const std::uint64_t oldest = last_t_ > span_ ? last_t_ - span_ : 0;
    for (Trace& tr : traces_) {
        while (!tr.edges.empty() && (tr.edges.front().t < oldest || tr.edges.size() > kMaxEdges)) {
            tr.level_before = tr.edges.front().level;
            tr.value_before = tr.edges.front().value;
            tr.edges.pop_front();
        }
    }
}

void SignalTrace::look(std::uint64_t t) {
    if (!machine_) return;
    if (t < last_t_) {
        // The machine was taken back: what was seen after t is not this timeline's.
        for (Trace& tr : traces_)
            while (!tr.edges.empty() && tr.edges.back().t > t) tr.edges.pop_back();
        tap_.rewind(t);
        if (t < start_t_) start_t_ = t;
    }
    last_t_ = t;
    for (const std::size_t k : tap_.read(t)) {
        const PinTap::Channel& c = tap_.channels()[k];
        Trace& tr = traces_[k];
        // Two changes at one T-state (a level read again after a rewind): the last one stands.
        if (!tr.edges.empty() && tr.edges.back().t == t) tr.edges.pop_back();
        const bool same = tr.edges.empty() ? (c.pin.real ? tr.value_before == c.value : tr.level_before == c.level)
                                           : (c.pin.real ? tr.edges.back().value == c.value : tr.edges.back().level == c.level);
        if (!same) tr.edges.push_back({t, c.level, c.value});
    }
    trim();
}

std::uint64_t SignalTrace::next() const { return tap_.next(last_t_); }

namespace {
// The last edge of `tr` at or before t, or nullptr.
const SignalTrace::Edge* edge_at_or_before(const SignalTrace::Trace& tr, std::uint64_t t) {
    const auto after = std::upper_bound(tr.edges.begin(), tr.edges.end(), t,
                                        [](std::uint64_t x, const SignalTrace::Edge& e) { return x < e.t; });
    return after == tr.edges.begin() ? nullptr : &*std::prev(after);
}
}  // namespace

char SignalTrace::level_at(std::size_t k, std::uint64_t t) const {
    const Trace& tr = traces_.at(k);
    const Edge* e = edge_at_or_before(tr, t);
    return e ? e->level : tr.level_before;
}

double SignalTrace::value_at(std::size_t k, std::uint64_t t) const {
    const Trace& tr = traces_.at(k);
    const Edge* e = edge_at_or_before(tr, t);
    return e ? e->value : tr.value_before;
}

std::optional<std::uint64_t> SignalTrace::edge_near(std::size_t k, std::uint64_t t, std::uint64_t within) const {
    const Trace& tr = traces_.at(k);
    const auto at = std::lower_bound(tr.edges.begin(), tr.edges.end(), t,
                                     [](const Edge& e, std::uint64_t x) { return e.t < x; });
    std::optional<std::uint64_t> best;
    const auto consider = [&](std::uint64_t e) {
        const std::uint64_t d = e > t ? e - t : t - e;
        if (d <= within && (!best || d < (*best > t ? *best - t : t - *best))) best = e;
    };
    if (at != tr.edges.end()) consider(at->t);
    if (at != tr.edges.begin()) consider(std::prev(at)->t);
    return best;
}

std::string interval_text(std::uint64_t a, std::uint64_t b) {
    const bool negative = b < a;
    const std::uint64_t d = negative ? a - b : b - a;
    // nanoseconds, rounded, in integers (no overflow for any d): microseconds to three places
    constexpr std::uint64_t hz = board::kCpuHz;
    const std::uint64_t ns = d / hz * 1'000'000'000ull + (d % hz * 1'000'000'000ull + hz / 2) / hz;
    const char* sign = negative ? "-" : "";
    return fmt::format("{}{} T = {}{}.{:03} \u00b5s", sign, d, sign, ns / 1000, ns % 1000);
}

}  // namespace alp85::debug
