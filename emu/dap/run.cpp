// continue, next, stepIn, stepOut, pause, stepBack, reverseContinue, goto. Every run is the
// Debugger's: forward runs that may last (continue, a step over a call, a step out) are begun
// here and resumed in slices between messages (advance), so pause is answered within one slice;
// breakpoint conditions, hit conditions, log points and the runaway guard are the Debugger's.
#include <chrono>

#include <fmt/format.h>

#include "emu/dap/adapter.h"

namespace alp85::dap {
namespace {

// Machine time between looks at the client when pacing to real time; unpaced, a slice is cut by
// host time instead, long enough that the looks cost nothing, short enough that pause is prompt.
constexpr std::uint64_t kPacedSlice = board::kCpuHz / 100;  // 10 ms of the board's time
constexpr double kUnpacedSeconds = 0.02;

double host_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool by_instruction(const Json& args) { return opt_string(args, "granularity").value_or("") == "instruction"; }

std::string changes_text(const debug::Stop& s) {
    std::string out;
    for (const debug::Change& c : s.changes) {
        if (!out.empty()) out += "; ";
        if (c.value_only) out += fmt::format("{}: {:0{}X}H", c.what, c.new_value, c.digits);
        else if (c.digits == 0) out += fmt::format("{}: {} -> {}", c.what, c.old_value, c.new_value);
        else out += fmt::format("{}: {:0{}X}H -> {:0{}X}H", c.what, c.old_value, c.digits, c.new_value, c.digits);
    }
    return out;
}

}  // namespace

void Adapter::require_stopped() {
    session();
    if (session_->debugger().running()) throw RequestError("the program is running: pause it first");
}

void Adapter::stopped(std::string_view reason, const std::string& description, std::vector<int> hit_ids,
                      const std::string& text) {
    Json body = {{"reason", reason}, {"threadId", 1}, {"allThreadsStopped", true}};
    if (!description.empty()) body["description"] = description;
    if (!text.empty()) body["text"] = text;
    if (!hit_ids.empty()) body["hitBreakpointIds"] = hit_ids;
    event("stopped", std::move(body));
}

// A run begun: reported now when it already ended, else resumed by advance().
void Adapter::started(std::optional<debug::Stop> s, std::string_view step_reason) {
    if (s) {
        report(*s, step_reason);
        return;
    }
    run_.step_reason = std::string(step_reason);
    run_.started_at = machine().now();
    run_.host_start = host_seconds();
}

// How a run ended, as a stopped event.
void Adapter::report(const debug::Stop& s, std::string_view step_reason) {
    std::vector<int> ids;
    for (const int n : s.numbers.empty() ? std::vector<int>{s.number} : s.numbers)
        if (const auto it = engine_to_dap_.find(n); it != engine_to_dap_.end() &&
                                                    std::find(ids.begin(), ids.end(), it->second) == ids.end())
            ids.push_back(it->second);
    switch (s.reason) {
        case debug::StopReason::Breakpoint: stopped("breakpoint", {}, ids); return;
        case debug::StopReason::Watchpoint: stopped("data breakpoint", changes_text(s), ids); return;
        case debug::StopReason::Error: stopped("exception", s.message, {}, s.message); return;
        case debug::StopReason::Runaway:
            output("stderr", s.message);
            stopped("exception", "runaway", {}, s.message);
            return;
        case debug::StopReason::Halted:
            output("console", s.message);
            stopped("halted", s.message, {}, s.message);
            return;
        case debug::StopReason::Interrupted:
        case debug::StopReason::Paused: stopped("pause"); return;
        case debug::StopReason::Deadline:
            if (!s.message.empty()) output("console", s.message);
            stopped("pause", s.message);
            return;
        case debug::StopReason::HistoryStart:
            output("console", s.message);
            stopped(step_reason, s.message);
            return;
        default: stopped(step_reason); return;
    }
}

void Adapter::continue_(const Json&, Json& body) {
    require_stopped();
    // No limit of machine time: an editor's continue runs until a stop or a pause.
    started(session_->debugger().begin_continue(~std::uint64_t{0}), "step");
    body = {{"allThreadsContinued", true}};
}

void Adapter::pause(const Json&, Json&) {
    session();
    debug::Debugger& d = session_->debugger();
    if (!d.running()) return;  // already stopped: DAP asks for no error
    report(d.pause(), "pause");
}

void Adapter::step_in(const Json& args, Json&) {
    require_stopped();
    debug::Debugger& d = session_->debugger();
    if (by_instruction(args)) report(d.stepi(), "step");
    else started(d.begin_step(), "step");
}

void Adapter::next(const Json&, Json&) {
    require_stopped();
    started(session_->debugger().begin_next(), "step");
}

void Adapter::step_out(const Json&, Json&) {
    require_stopped();
    if (session_->debugger().backtrace().size() < 2)
        throw RequestError("no caller to return to: no return address on the stack");
    started(session_->debugger().begin_finish(), "step");
}

void Adapter::step_back(const Json& args, Json&) {
    require_stopped();
    debug::Debugger& d = session_->debugger();
    report(by_instruction(args) ? d.reverse_stepi() : d.reverse_step(), "step");
}

void Adapter::reverse_continue(const Json&, Json&) {
    require_stopped();
    report(session_->debugger().reverse_continue(), "step");  // log points are no stops backwards either
}

void Adapter::goto_targets(const Json& args, Json& body) {
    session();
    const Json& src = opt_object(args, "source");
    const std::string path = need_string(src, "path");
    const int line = need_line(args, "line", lines_start_at_1_);
    Json targets = Json::array();
    const auto loc = session_->debugger().locate_line(path, line);
    if (loc.error.empty()) {
        for (const std::uint16_t a : loc.addresses) {
            const int bound = loc.bound ? loc.bound->line : line;
            targets.push_back({{"id", a + 1},
                               {"label", fmt::format("{} ({})", bound, hex4(a))},
                               {"line", bound - (lines_start_at_1_ ? 0 : 1)},
                               {"instructionPointerReference", hex4(a)}});
        }
    }
    body = {{"targets", targets}};
}

void Adapter::goto_(const Json& args, Json&) {
    require_stopped();
    const std::int64_t id = need_int(args, "targetId");
    if (id < 1 || id > 0x10000) throw RequestError(fmt::format("no goto target {}", id));
    machine().cpu().regs().pc = static_cast<std::uint16_t>(id - 1);
    session_->debugger().state_changed();
    stopped("goto");
}

int Adapter::advance() {
    if (!session_ || !session_->debugger().running()) return -1;
    Machine& m = machine();
    debug::Budget budget;
    if (config_.real_time) budget.tstates = kPacedSlice;
    else budget.seconds = kUnpacedSeconds;
    if (const auto s = session_->debugger().resume(budget)) {
        report(*s, run_.step_reason);
        return 0;
    }
    if (!config_.real_time) return 0;
    // Paced: the board's 3.072 MHz against the host's clock since the run began.
    const double ahead = static_cast<double>(m.now() - run_.started_at) / board::kCpuHz -
                         (host_seconds() - run_.host_start);
    return ahead > 0 ? static_cast<int>(ahead * 1000) : 0;
}

}  // namespace alp85::dap
