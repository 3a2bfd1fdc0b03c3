// Inside the Debugger (not for front ends): the RunObserver it installs on the machine while
// breakpoints, watchpoints, a step or a re-execution need to see the run, and the snapshots
// of reverse execution.
#pragma once

#include <bitset>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "emu/debug/debugger.h"

namespace alp85::debug {

// An instruction boundary seen while re-executing (reverse execution, history).
struct Boundary {
    std::uint64_t t = 0;
    Registers regs;
    std::uint8_t op = 0;  // the opcode at pc
};

// A breakpoint or watchpoint hit, as the observer saw it.
struct Hit {
    std::uint64_t t = 0;  // the position: before the breakpoint's instruction, after the watched one
    StopReason reason = StopReason::Breakpoint;
    int number = 0;
    std::vector<Change> changes;
    std::optional<std::uint16_t> data;
    std::optional<std::uint16_t> after;
    std::vector<int> numbers{};  // breakpoints: all that stop here
};

// A stop at a hit: what stopped the run, as the stop reports it.
inline Stop from_hit(Stop s, const Hit& h) {
    s.number = h.number;
    s.numbers = h.numbers;
    s.changes = h.changes;
    s.data = h.data;
    s.after = h.after;
    return s;
}

class Debugger::Observer final : public RunObserver {
public:
    explicit Observer(Debugger& d) : d_(d) {}

    // What is armed, rebuilt by Debugger::arm() from the breakpoint and watchpoint lists.
    void rebuild();
    bool needed() const {
        return any_bp_ || accesses_ || state_watches_ || target || record != nullptr || guard_;
    }
    // Breakpoints and the runaway guard alone need only a fetch fence (the CPU's plain path):
    // the breakpoints' addresses and, with the guard armed, every address outside the code.
    const std::bitset<0x10000>* fetch_fence() const override { return fence_ok_ ? &fence_ : nullptr; }
    bool at_fence(const I8085& cpu) override;

    bool before_instruction(const I8085& cpu) override;
    bool on_read(std::uint16_t addr, std::uint8_t value) override;
    bool on_write(std::uint16_t addr, std::uint8_t value) override;
    bool on_io(std::uint8_t port, std::uint8_t value, bool is_out) override;
    bool wants_accesses() const override { return accesses_ && !(replay && !hits); }

    // ---- one run's settings and findings --------------------------------------------------------
    std::optional<std::uint64_t> skip_at;  // a breakpoint at this T-state does not stop (the start)
    std::function<bool(const I8085&)> target;  // a step's end, checked before every instruction
    bool target_reached = false;
    std::vector<Hit> pending;  // watch hits of the instruction that just ran (decided after it)
    std::optional<Hit> stop_hit;  // the breakpoint or state watch that stopped the run
    std::string error;            // a condition that could not be evaluated
    // Re-execution: every boundary (when `record`) and every hit (when `hits`), nothing stops.
    bool replay = false;  // re-executing: only `record` and `hits` matter
    std::vector<Boundary>* record = nullptr;
    std::vector<Hit>* hits = nullptr;
    std::uint16_t last_pc = 0;  // the instruction running (for "after" in watch reports)
    bool runaway_armed = false;  // the runaway guard: the PC has been in code since the last runaway

    // Watch hits of the last instruction that survive their conditions and ignore counts (counted).
    std::vector<Hit> decide_pending(bool count);

    // Machine-tool and chip watches: a change since the last check is a hit (true: stop_hit set).
    bool check_state(const I8085& cpu);

private:
    bool check_breakpoint(const I8085& cpu);
    void memory_access(std::uint16_t addr, bool write);
    void flush_pending(std::uint64_t t);  // re-execution: pending hits become positions

    Debugger& d_;
    std::bitset<0x10000> bp_, read_, write_;
    std::bitset<256> port_in_, port_out_;
    bool any_bp_ = false, accesses_ = false, state_watches_ = false, guard_ = false;
    std::bitset<0x10000> fence_;
    bool fence_ok_ = false;
};

// Snapshots every interval of simulated time, for reverse execution.
struct Checkpoint {
    std::uint64_t t = 0;
    std::vector<std::uint8_t> bytes;
    std::size_t log_size = 0;  // inputs applied when it was taken
};

class Debugger::History {
public:
    std::uint64_t interval = kHistoryInterval;
    std::vector<Checkpoint> points;  // in time order

    void take(const Machine& m);
    bool due(std::uint64_t now) const { return points.empty() || now >= points.back().t + interval; }
    std::uint64_t next_due() const { return points.empty() ? 0 : points.back().t + interval; }
    void drop_from(std::uint64_t t);  // removes checkpoints at or after t
    // The latest checkpoint strictly before t (or at t when `at_ok`), or nullptr.
    const Checkpoint* before(std::uint64_t t, bool at_ok = false) const;
    // Puts the machine back at checkpoint `c`, keeping every input still to come on this timeline.
    void restore(Machine& m, const Checkpoint& c) const;

private:
    void thin();  // old checkpoints made sparser when there are many (memory stays bounded)
};

}  // namespace alp85::debug
