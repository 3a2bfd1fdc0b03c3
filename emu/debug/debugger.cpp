#include "emu/debug/debugger.h"

#include <fmt/format.h>

namespace alp85::debug {

std::string_view name(StopReason reason) {
    switch (reason) {
        case StopReason::Deadline: return "deadline";
        case StopReason::Condition: return "condition";
        case StopReason::Breakpoint: return "breakpoint";
        case StopReason::Watchpoint: return "watchpoint";
        case StopReason::Target: return "target";
        case StopReason::Step: return "step";
    }
    return "?";
}

namespace {
StopReason reason_of(Machine::Stop s) {
    switch (s) {
        case Machine::Stop::Deadline: return StopReason::Deadline;
        case Machine::Stop::Condition: return StopReason::Condition;
        case Machine::Stop::Breakpoint: return StopReason::Breakpoint;
        case Machine::Stop::Watchpoint: return StopReason::Watchpoint;
        case Machine::Stop::Target: return StopReason::Target;
    }
    return StopReason::Deadline;
}
}  // namespace

Stop Debugger::here(StopReason reason) const {
    Stop s;
    s.reason = reason;
    s.at = m_.now();
    s.pc = m_.cpu().regs().pc;
    if (reason == StopReason::Watchpoint) s.data = m_.watch_hit();
    s.line = program_.line_of(s.pc);
    return s;
}

Stop Debugger::run_until(std::uint64_t until, const std::function<bool()>& condition, const Origin& origin) {
    const Stop s = here(reason_of(m_.run_until(until, condition)));
    if (s.reason == StopReason::Breakpoint || s.reason == StopReason::Watchpoint)
        emit({Event::Kind::Stopped, s, {}, origin});
    return s;
}

Stop Debugger::run_to(std::uint16_t pc, std::uint64_t until) { return here(reason_of(m_.run_to(pc, until))); }

Stop Debugger::step() {
    m_.step();
    return here(StopReason::Step);
}

Debugger::Location Debugger::locate_line(std::string_view file, int line) const {
    Location loc;
    const std::optional<SourceLine> next = program_.next_line_with_code(file, line);
    if (!next) {
        loc.error = fmt::format("no code at or after {}:{} in the loaded programs", file, line);
        return loc;
    }
    loc.addresses = program_.addresses_of(next->file, next->line);
    if (next->line != line) loc.bound = next;
    return loc;
}

}  // namespace alp85::debug
