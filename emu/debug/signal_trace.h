// The window's logic analyzer (the Signals pane, docs/signals.md): the chosen pins over the last
// `span` T-states of machine time, kept in memory while the machine runs. It reads the board
// through the same PinTap as a VCD recording (`record signals`), installed beside it as a second
// PinProbe; with no trace open nothing is installed and the board pays nothing.
//
// Nothing is looked at while the machine stands (a breakpoint, Pause): the trace stands still
// with it. When the machine is taken back (a snapshot restored, reverse execution), the edges
// after its new time are dropped at the next look, and the pins are read again from there.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "emu/board/machine.h"
#include "emu/debug/pin_tap.h"

namespace alp85::debug {

class SignalTrace final : public PinProbe {
public:
    static constexpr std::uint64_t kDefaultPeriod = 96;  // the sampled pins' clock, as `record signals`
    // Edges kept per pin at most, the oldest dropped first: a TIMER OUT of a few T-states a period
    // over a long span would otherwise fill the memory.
    static constexpr std::size_t kMaxEdges = std::size_t{1} << 18;

    struct Edge {
        std::uint64_t t = 0;  // the T-state of the change
        char level = '0';     // a logic pin's new level
        double value = 0;     // a real pin's new value
    };
    struct Trace {
        PinTap::PinName pin;
        char level_before = '0';  // before the first edge kept
        double value_before = 0;
        std::deque<Edge> edges;   // oldest first
    };

    SignalTrace() = default;
    SignalTrace(const SignalTrace&) = delete;
    SignalTrace& operator=(const SignalTrace&) = delete;
    ~SignalTrace() override;

    // Opens the trace on the pins `selection` names (PinTap's words: "PA0", "X.PULSE", "8155"),
    // from the machine's present T-state, keeping `span` T-states. Throws std::runtime_error
    // (why) when a word names no pin; a trace already open is replaced.
    void start(Machine& machine, const std::vector<std::string>& selection, std::uint64_t span,
               std::uint64_t period = kDefaultPeriod);
    // Closes it: the probe comes off the board and the traces are dropped.
    void stop();
    bool open() const { return machine_ != nullptr; }
    const std::vector<std::string>& selection() const { return selection_; }

    std::uint64_t span() const { return span_; }
    void set_span(std::uint64_t span);  // edges older than the new span are dropped at the next look
    std::uint64_t started() const { return start_t_; }  // the T-state the trace began at
    std::uint64_t latest() const { return last_t_; }    // the last T-state looked at
    const std::vector<Trace>& traces() const { return traces_; }

    // Pin k's level (a logic pin) or value (a real one) at T-state t, from what is kept.
    char level_at(std::size_t k, std::uint64_t t) const;
    double value_at(std::size_t k, std::uint64_t t) const;
    // The edge of pin k nearest to t no further than `within` T-states away, if any.
    std::optional<std::uint64_t> edge_near(std::size_t k, std::uint64_t t, std::uint64_t within) const;

    // PinProbe
    void look(std::uint64_t t) override;
    std::uint64_t next() const override;

private:
    void trim();

    Machine* machine_ = nullptr;
    PinTap tap_;
    std::vector<std::string> selection_;
    std::vector<Trace> traces_;
    std::uint64_t span_ = 0;
    std::uint64_t start_t_ = 0;
    std::uint64_t last_t_ = 0;
};

// The time between two T-states as the pane's cursors read it: "3155 T = 1027.018 µs" (the 8085's
// clock, board::kCpuHz: 3.072 MHz); negative when b is before a.
std::string interval_text(std::uint64_t a, std::uint64_t b);

}  // namespace alp85::debug
