// continue, next, stepIn, stepOut, pause, stepBack, reverseContinue, goto. Forward runs that may
// last (continue, a step over a call, a step out) go in slices between messages (advance), so
// pause is answered within one slice; single steps and reverse execution are the Debugger's.
#include <chrono>

#include <fmt/format.h>

#include "asm/disasm.h"
#include "emu/dap/adapter.h"

namespace alp85::dap {
namespace {

constexpr std::uint64_t kSlice = 30'720;  // 10 ms of the board's time between looks at the input

double host_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CALL, Ccc and RST push a return address: `next` runs them whole.
bool pushes_return(std::uint8_t op) { return op == 0xCD || (op & 0xC7) == 0xC4 || (op & 0xC7) == 0xC7; }

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
    if (run_.active) throw RequestError("the program is running: pause it first");
}

void Adapter::stopped(std::string_view reason, const std::string& description, std::vector<int> hit_ids,
                      const std::string& text) {
    Json body = {{"reason", reason}, {"threadId", 1}, {"allThreadsStopped", true}};
    if (!description.empty()) body["description"] = description;
    if (!text.empty()) body["text"] = text;
    if (!hit_ids.empty()) body["hitBreakpointIds"] = hit_ids;
    event("stopped", std::move(body));
}

void Adapter::start_run() {
    run_.active = true;
    run_.started_at = machine().now();
    run_.host_start = host_seconds();
}

void Adapter::end_run() {
    run_.active = false;
    if (run_.temporary) session_->debugger().remove(run_.temporary);
    run_.temporary = 0;
}

void Adapter::run_until_return(std::uint16_t target, std::uint16_t sp, Run::Kind kind) {
    run_.kind = kind;
    run_.target = target;
    run_.sp = sp;
    run_.temporary = session_->debugger().add_breakpoint_at(target).number;
    start_run();
}

// How a step or a reverse run ended, as a stopped event.
void Adapter::report(const debug::Stop& s, std::string_view step_reason) {
    switch (s.reason) {
        case debug::StopReason::Breakpoint: {
            const auto it = engine_to_dap_.find(s.number);
            stopped("breakpoint", {}, it == engine_to_dap_.end() ? std::vector<int>{} : std::vector<int>{it->second});
            return;
        }
        case debug::StopReason::Watchpoint: {
            const auto it = engine_to_dap_.find(s.number);
            stopped("data breakpoint", changes_text(s), it == engine_to_dap_.end() ? std::vector<int>{} : std::vector<int>{it->second});
            return;
        }
        case debug::StopReason::Error: stopped("exception", s.message, {}, s.message); return;
        case debug::StopReason::HistoryStart:
            output("console", s.message);
            stopped(step_reason, s.message);
            return;
        default: stopped(step_reason); return;
    }
}

void Adapter::continue_(const Json&, Json& body) {
    require_stopped();
    run_.kind = Run::Kind::Continue;
    start_run();
    body = {{"allThreadsContinued", true}};
}

void Adapter::pause(const Json&, Json&) {
    session();
    if (!run_.active) return;  // already stopped: DAP asks for no error
    end_run();
    stopped("pause");
}

void Adapter::step_in(const Json& args, Json&) {
    require_stopped();
    debug::Debugger& d = session_->debugger();
    report(by_instruction(args) ? d.stepi() : d.step(), "step");
}

void Adapter::next(const Json&, Json&) {
    require_stopped();
    Machine& m = machine();
    const Registers before = m.cpu().regs();
    const std::uint8_t op = m.peek(before.pc);
    const auto len = alp85::disassemble(m.bus(), before.pc, m.cpu().variant()).length;
    const debug::Stop s = session_->debugger().stepi();
    const Registers& after = m.cpu().regs();
    const auto ret = static_cast<std::uint16_t>(before.pc + len);
    if (s.reason != debug::StopReason::Step || !pushes_return(op) || after.pc == ret ||
        after.sp != static_cast<std::uint16_t>(before.sp - 2)) {
        report(s, "step");
        return;
    }
    // The call was taken: run until it returns here with the stack as it was.
    run_until_return(ret, before.sp, Run::Kind::Over);
}

void Adapter::step_out(const Json&, Json&) {
    require_stopped();
    // The caller's frame from the Debugger's CALL/RET view of the stack: its return address and
    // the slot it sits in; returned when the PC is there with that slot popped.
    const std::vector<debug::Frame> frames = live_frames(session_->debugger(), stack_base_);
    if (frames.size() < 2) throw RequestError("no caller to return to: no return address on the stack");
    run_until_return(frames[1].pc, static_cast<std::uint16_t>(frames[1].slot + 2), Run::Kind::Out);
}

void Adapter::step_back(const Json& args, Json&) {
    require_stopped();
    debug::Debugger& d = session_->debugger();
    report(by_instruction(args) ? d.reverse_stepi() : d.reverse_step(), "step");
}

void Adapter::reverse_continue(const Json&, Json&) {
    require_stopped();
    debug::Debugger& d = session_->debugger();
    // Back to the previous hit that a forward run would have stopped at: log points and hit
    // conditions not met are passed (a bounded number of times).
    for (int tries = 0; tries < 1000; ++tries) {
        const debug::Stop s = d.reverse_continue();
        if (s.reason == debug::StopReason::Breakpoint) {
            const auto it = engine_to_dap_.find(s.number);
            bool log_only = false;
            if (it != engine_to_dap_.end())
                for (const Breakpoint* b : bps_.at(s.pc))
                    if (b->id == it->second && !b->log_message.empty()) log_only = true;
            if (log_only) continue;
        }
        report(s, "step");
        return;
    }
    stopped("pause", "reverse-continue passed 1000 log points");
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
    if (!run_.active || !session_) return -1;
    Machine& m = machine();
    runaway_.reset();
    const debug::Stop s = session_->debugger().run_for(kSlice, [this] { return runaway_.has_value(); });
    switch (s.reason) {
        case debug::StopReason::Condition: {
            end_run();
            const std::uint16_t at = *runaway_;
            const auto d = alp85::disassemble(m.bus(), at, m.cpu().variant());
            const std::string text =
                fmt::format("the program ran away: it fetched an instruction at {:04X}H ({}), where no program is", at, d.text);
            output("stderr", text);
            stopped("exception", "runaway", {}, text);
            return 0;
        }
        case debug::StopReason::Breakpoint: {
            if (run_.temporary && s.number == run_.temporary) {
                if (m.cpu().regs().sp >= run_.sp) {  // returned (not a deeper, recursive visit)
                    end_run();
                    stopped("step");
                }
                return 0;
            }
            std::vector<int> ids;
            if (!engine_to_dap_.contains(s.number) || stop_at_breakpoint(s.pc, ids)) {
                end_run();
                stopped("breakpoint", {}, ids);
            }
            return 0;
        }
        case debug::StopReason::Watchpoint: {
            std::vector<int> ids;
            if (stop_at_data(s, ids)) {
                end_run();
                stopped("data breakpoint", changes_text(s), ids);
            }
            return 0;
        }
        case debug::StopReason::Error:
            end_run();
            stopped("exception", s.message, {}, s.message);
            return 0;
        default: break;
    }
    if (!config_.real_time) return 0;
    // Paced: the board's 3.072 MHz against the host's clock since the run began.
    const double ahead = static_cast<double>(m.now() - run_.started_at) / board::kCpuHz -
                         (host_seconds() - run_.host_start);
    return ahead > 0 ? static_cast<int>(ahead * 1000) : 0;
}

}  // namespace alp85::dap
