// The debugging API every front end uses (the script session, the debugger's prompt, the GUI,
// DAP): runs that end in a Stop value, events to listeners instead of text, the program's symbols
// and source lines in one table, and the machine's input log for exact replay.
//
// It wraps one Machine and adds no cost to a plain run: breakpoints and watchpoints are the
// machine's, armed on the CPU only while some exist.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/board/machine.h"
#include "emu/program/symbols.h"

namespace alp85::debug {

enum class StopReason : std::uint8_t {
    Deadline,    // the requested time was reached
    Condition,   // the caller's condition became true
    Breakpoint,  // the PC reached a breakpoint (the instruction there has not run)
    Watchpoint,  // a watched address was accessed (after the instruction)
    Target,      // run_to reached its address
    Step,        // one instruction was executed
};
std::string_view name(StopReason reason);  // "deadline", "breakpoint", ...

struct Stop {
    StopReason reason = StopReason::Deadline;
    std::uint64_t at = 0;                // T-state
    std::uint16_t pc = 0;                // the next instruction
    std::optional<std::uint16_t> data;   // Watchpoint: the address accessed
    std::optional<SourceLine> line;      // the source line of pc, when a loaded program has one
};

// Where a command came from (a script's file and line), for front ends that print it.
struct Origin {
    std::string file;
    int line = 0;
};

struct Event {
    enum class Kind : std::uint8_t {
        Stopped,       // a run ended at a breakpoint or watchpoint (stop)
        ExpectFailed,  // an expectation did not hold (text: what was expected and found)
        Output,        // text for the user (print, a display dump)
    };
    Kind kind = Kind::Output;
    Stop stop;
    std::string text;
    Origin origin;
};

class Debugger {
public:
    using Listener = std::function<void(const Event&)>;

    explicit Debugger(Machine& machine) : m_(machine) {}

    Machine& machine() { return m_; }
    const Machine& machine() const { return m_; }
    // The symbols and source lines of everything loaded.
    SymbolTable& program() { return program_; }
    const SymbolTable& program() const { return program_; }

    // Listeners receive every event in order; front ends format them.
    void listen(Listener listener) { listeners_.push_back(std::move(listener)); }
    void emit(const Event& e) const {
        for (const Listener& l : listeners_) l(e);
    }

    // Runs as Machine does; a stop at a breakpoint or watchpoint is also sent as a Stopped event
    // (with `origin`, the command that ran).
    Stop run_until(std::uint64_t until, const std::function<bool()>& condition = {}, const Origin& origin = {});
    Stop run_for(std::uint64_t tstates, const std::function<bool()>& condition = {}, const Origin& origin = {}) {
        return run_until(m_.now() + tstates, condition, origin);
    }
    Stop run_to(std::uint16_t pc, std::uint64_t until);
    Stop step();
    Stop here(StopReason reason) const;  // a Stop describing the machine now

    // A breakpoint location: a symbol, a number, or FILE:LINE through the source lines (a line
    // without code binds to the next line that has some; `bound` says which).
    struct Location {
        std::vector<std::uint16_t> addresses;
        std::optional<SourceLine> bound;
        std::string error;  // empty when found
    };
    Location locate_line(std::string_view file, int line) const;

    // Every outside input applied so far, with its T-state (Machine::input_log).
    const std::vector<InputEvent>& input_log() const { return m_.input_log(); }

private:
    Machine& m_;
    SymbolTable program_;
    std::vector<Listener> listeners_;
};

}  // namespace alp85::debug
