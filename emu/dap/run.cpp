// continue, next, stepIn, stepOut, pause, stepBack, reverseContinue, goto. Every run is the
// Debugger's: forward runs that may last (continue, a step over a call, a step out) are begun
// here and resumed in slices between messages (advance), so pause is answered within one slice;
// breakpoint conditions, hit conditions, log points and the runaway guard are the Debugger's.
#include <chrono>

#include <fmt/format.h>

#include "emu/dap/adapter.h"
#include "emu/front/views.h"
#include "emu/script/parser.h"
#include "emu/util/text.h"

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
    if (running()) throw RequestError("the program is running: pause it first");
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
    run_.console = false;
    run_.steps_left = 0;
    if (s) {
        report(*s, step_reason);
        return;
    }
    run_.step_reason = std::string(step_reason);
    run_.pacer.rebase(session_->now(), front::HostClock::now());
}

// How a run ended, as a stopped event.
void Adapter::report(const debug::Stop& s, std::string_view step_reason, bool tell) {
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
            if (tell) output("stderr", s.message);
            stopped("exception", "runaway", {}, s.message);
            return;
        case debug::StopReason::Halted:
            if (tell) output("console", s.message);
            stopped("halted", s.message, {}, s.message);
            return;
        case debug::StopReason::Interrupted:
        case debug::StopReason::Paused: stopped("pause"); return;
        case debug::StopReason::Deadline:
            if (tell && !s.message.empty()) output("console", s.message);
            stopped("pause", s.message);
            return;
        case debug::StopReason::HistoryStart:
            if (tell) output("console", s.message);
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
    if (!running()) return;  // already stopped: DAP asks for no error
    run_.steps_left = 0;  // step N: no more steps
    const std::optional<std::string> text = ended(session_->debugger().pause());
    if (text && !text->empty()) output("console", *text);
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
    session_->set_pc(static_cast<std::uint16_t>(id - 1));
    stopped("goto");
}

std::optional<std::string> Adapter::ended(const debug::Stop& s) {
    if (run_.steps_left > 0 && (s.reason == debug::StopReason::Step || s.reason == debug::StopReason::Finished))
        return std::nullopt;
    run_.steps_left = 0;
    if (!run_.console) {
        report(s, run_.step_reason);
        return std::string();
    }
    run_.console = false;
    if (run_.timed && s.reason == debug::StopReason::Deadline) {  // run TIME: done, as the console says nothing
        stopped("step", "after the console command");
        return std::string();
    }
    std::string text = shell_->console().describe(s);
    // The stop's console commands (commands ... end), as the console runs them: one that runs
    // the machine ends the list and is the next run, which reports its own stop.
    bool again = false;
    // A run that ends at once runs its stop's commands in turn: a bound on the nesting keeps a
    // chain of them (a watch whose commands step into the next hit) from taking the stack.
    if (commands_depth_ < kMaxCommandsDepth) {
        ++commands_depth_;
        for (const std::string& line : session_->debugger().commands_for(s)) {
            try {
                if (const auto begun = begin_console_run(line)) {
                    text += *begun;
                    again = true;
                    break;
                }
            } catch (const RequestError& e) {
                text += std::string(e.what()) + '\n';
                continue;
            }
            capturing_ = true;
            text += shell_->execute(line);
            capturing_ = false;
            captured_.clear();
        }
        --commands_depth_;
    }
    if (!again) report(s, "step", /*tell=*/false);
    while (text.starts_with('\n')) text.erase(0, 1);
    while (text.ends_with('\n')) text.pop_back();
    return text;
}

std::optional<debug::Stop> Adapter::begin_console_step() {
    debug::Debugger& d = session_->debugger();
    --run_.steps_left;
    switch (run_.step) {
        case Run::Step::Line: return d.begin_step();
        case Run::Step::Over: return d.begin_next();
        case Run::Step::Instruction: return d.stepi();
    }
    return d.stepi();
}

namespace {

// The first word of a console line, as the console splits it (at a blank or '/').
std::string_view first_word(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '/') ++i;
    return s.substr(0, i);
}

}  // namespace

std::optional<std::string> Adapter::begin_console_run(std::string_view line) {
    debug::Console& console = shell_->console();
    if (console.prompt() == ">") return std::nullopt;  // reading a breakpoint's commands: a line to keep
    const std::string_view t = trim_blanks(line);
    const std::string_view word = first_word(t);
    const auto name = console.command_name(word);
    if (!name) return std::nullopt;
    const std::string_view args = trim_blanks(t.substr(word.size()));
    // N of continue N, step N, ...: read as the console reads it; nullopt when it is no count
    // (the console then says why).
    const auto count = [&]() -> std::optional<int> {
        if (args.empty()) return 1;
        const auto n = parse_int(first_word(args));
        if (!n || *n <= 0 || *n > 1'000'000) return std::nullopt;
        return static_cast<int>(*n);
    };
    debug::Debugger& d = session_->debugger();
    std::optional<debug::Stop> s;
    std::string text;
    Run run;
    run.console = true;
    if (*name == "continue") {
        const auto n = count();
        if (!n) return std::nullopt;
        // gdb: continue N passes the breakpoint here N-1 more times.
        if (!args.empty())
            for (const debug::Breakpoint& b : d.breakpoints())
                if (b.address == front::cpu_view(*session_).pc) d.set_ignore(b.number, static_cast<unsigned>(*n - 1));
        text = "Continuing.";
        s = d.begin_continue(~std::uint64_t{0});  // as the continue request: until a stop or a pause
    } else if (*name == "step" || *name == "next" || *name == "nexti" || *name == "stepi") {
        const auto n = count();
        if (!n) return std::nullopt;
        run.step = *name == "step" ? Run::Step::Line : *name == "stepi" ? Run::Step::Instruction : Run::Step::Over;
        run.steps_left = *n;
        run_ = run;
        s = begin_console_step();
        run = run_;
    } else if (*name == "finish") {
        if (!args.empty()) return std::nullopt;  // the console says why at once
        const auto frames = d.backtrace();
        if (frames.size() < 2) throw RequestError("no caller to return to: no return address on the stack");
        text = fmt::format("Run till exit from {} ({:04X}H)", frames[0].routine.value_or("??"), frames[0].pc);
        s = d.begin_finish();
    } else if (*name == "until" || *name == "advance" || *name == "jump") {
        std::optional<std::uint16_t> to;
        if (!args.empty()) {
            const auto loc = d.locate(args);
            if (!loc.error.empty()) return std::nullopt;
            to = loc.addresses.front();
        } else if (*name != "until") {
            return std::nullopt;
        }
        if (*name == "until") {
            s = d.begin_until(to);
        } else if (*name == "advance") {
            s = d.begin_advance(*to);
        } else {
            session_->set_pc(*to);
            const auto routine = d.program().routine_at(*to);
            text = fmt::format("Continuing at {:04X}H{}.", *to, routine ? fmt::format(" ({})", *routine) : "");
            s = d.begin_continue(~std::uint64_t{0});
        }
    } else if (*name == "run") {
        std::string_view time = args;
        if (to_upper(first_word(time)) == "FOR") time = trim_blanks(time.substr(3));
        if (to_upper(first_word(time)) == "UNTIL") return std::nullopt;  // the command language's run until
        const auto tstates = script::parse_time(time);
        if (!tstates)
            throw RequestError(fmt::format("bad time '{}' (a number with a unit: t, us, ms or s): run [for] TIME", time));
        run.timed = true;
        text = fmt::format("Running for {}.", time);
        s = d.begin_continue(*tstates, /*stop_at_halt=*/false);  // as the console's run: HLT does not end it
    } else {
        return std::nullopt;
    }
    run.pacer.rebase(session_->now(), front::HostClock::now());
    run_ = run;
    if (s) {
        if (const auto told = ended(*s); told && !told->empty()) text += (text.empty() ? "" : "\n") + *told;
    }
    return text.empty() ? std::string("Running.") : text;
}

int Adapter::advance() {
    if (!running()) return -1;
    debug::Debugger& d = session_->debugger();
    const bool paced = config_.real_time && !run_.console;  // the console's runs go as fast as they can
    debug::Budget budget;
    if (paced) budget.tstates = kPacedSlice;
    else budget.seconds = kUnpacedSeconds;
    const double slice_start = host_seconds();
    for (;;) {
        const std::optional<debug::Stop> s = d.running() ? d.resume(budget) : begin_console_step();
        if (!s) break;  // the slice is over, or a step that lasts has begun
        if (const auto text = ended(*s)) {
            if (!text->empty()) output("console", *text);
            return 0;
        }
        if (host_seconds() - slice_start >= kUnpacedSeconds) return 0;  // step N: the next steps in the next slice
    }
    if (!paced) return 0;
    // Paced: the board's 3.072 MHz against the host's clock since the run began.
    return static_cast<int>(run_.pacer.ahead(session_->now(), front::HostClock::now()).count());
}

}  // namespace alp85::dap
