// Outside inputs (keys, the RESET and VECT INTR keys, later the machine tool) as events stamped in
// simulated time. The queue orders them by time and, for equal times, by the order they were
// scheduled, so a run with the same inputs is the same run.
#pragma once

#include <cstdint>
#include <limits>
#include <set>
#include <vector>

namespace alp85 {

enum class InputKind : std::uint8_t {
    Key,       // code = keypad key id, level = pressed
    VectIntr,  // the VECT INTR key (RST 7.5), level = pressed
    Reset,     // the RESET key, level = pressed (the CPU is held in reset while pressed)
    Serial,    // a character typed at the serial terminal on SID/SOD, code = the character
};

struct InputEvent {
    std::uint64_t at = 0;   // T-state
    std::uint64_t seq = 0;  // scheduling order, breaks ties
    InputKind kind = InputKind::Key;
    std::uint16_t code = 0;
    bool level = false;

    friend bool operator<(const InputEvent& a, const InputEvent& b) {
        return a.at != b.at ? a.at < b.at : a.seq < b.seq;
    }
};

class InputQueue {
public:
    static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();

    void schedule(std::uint64_t at, InputKind kind, std::uint16_t code, bool level) {
        events_.insert(InputEvent{at, next_seq_++, kind, code, level});
    }
    std::uint64_t next_time() const { return events_.empty() ? kNever : events_.begin()->at; }
    bool due(std::uint64_t now) const { return !events_.empty() && events_.begin()->at <= now; }
    InputEvent pop() {
        InputEvent e = *events_.begin();
        events_.erase(events_.begin());
        return e;
    }
    bool empty() const { return events_.empty(); }
    std::size_t size() const { return events_.size(); }
    void clear() { events_.clear(); }

    // For snapshots and the debugger.
    std::vector<InputEvent> pending() const { return {events_.begin(), events_.end()}; }
    std::uint64_t next_seq() const { return next_seq_; }
    void restore(const std::vector<InputEvent>& events, std::uint64_t next_seq) {
        events_ = {events.begin(), events.end()};
        next_seq_ = next_seq;
    }

private:
    std::set<InputEvent> events_;
    std::uint64_t next_seq_ = 0;
};

}  // namespace alp85
