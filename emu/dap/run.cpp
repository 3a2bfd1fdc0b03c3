// continue, next, stepIn, stepOut, pause, stepBack, reverseContinue, goto: the machine runs in
// slices between messages (advance), so that pause is answered within one slice.
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
    arm();  // drops a step's temporary breakpoint
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

void Adapter::step_in(const Json&, Json&) {
    require_stopped();
    session_->debugger().step();
    stopped("step");
}

void Adapter::next(const Json&, Json&) {
    require_stopped();
    Machine& m = machine();
    const Registers before = m.cpu().regs();
    const std::uint8_t op = m.peek(before.pc);
    const auto len = alp85::disassemble(m.bus(), before.pc, m.cpu().variant()).length;
    session_->debugger().step();
    const Registers& after = m.cpu().regs();
    const std::uint16_t ret = static_cast<std::uint16_t>(before.pc + len);
    if (!pushes_return(op) || after.pc == ret || after.sp != static_cast<std::uint16_t>(before.sp - 2)) {
        stopped("step");
        return;
    }
    // The call was taken: run until it returns here with the stack as it was.
    run_.kind = Run::Kind::Over;
    run_.target = ret;
    run_.sp = before.sp;
    m.add_breakpoint(ret);
    start_run();
}

void Adapter::step_out(const Json&, Json&) {
    require_stopped();
    throw RequestError("stepOut needs CALL/RET tracking from the debugger engine (issue #15), not merged yet");
}

void Adapter::step_back(const Json&, Json&) {
    require_stopped();
    throw RequestError("stepBack needs reverse execution from the debugger engine (issue #15), not merged yet");
}

void Adapter::reverse_continue(const Json&, Json&) {
    require_stopped();
    throw RequestError("reverseContinue needs reverse execution from the debugger engine (issue #15), not merged yet");
}

void Adapter::goto_targets(const Json& args, Json& body) {
    session();
    const Json& src = opt_object(args, "source");
    const std::string path = need_string(src, "path");
    const int line = static_cast<int>(need_int(args, "line")) + (lines_start_at_1_ ? 0 : 1);
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
            stopped("exception", "runaway",
                    {}, fmt::format("the program ran away: it executed {:04X}H ({}), where no program was loaded", at, d.text));
            return 0;
        }
        case debug::StopReason::Breakpoint: {
            if (run_.kind == Run::Kind::Over && s.pc == run_.target && m.cpu().regs().sp >= run_.sp) {
                end_run();
                stopped("step");
                return 0;
            }
            std::vector<int> ids;
            if (stop_at_breakpoint(s.pc, ids)) {
                end_run();
                stopped("breakpoint", {}, ids);
            }
            return 0;
        }
        case debug::StopReason::Watchpoint: {
            std::vector<int> ids;
            if (s.data && stop_at_data(*s.data, ids)) {
                end_run();
                stopped("data breakpoint",
                        fmt::format("{:04X}H accessed (now {:02X}H)", *s.data, m.peek(*s.data)), ids);
            }
            return 0;
        }
        default: break;
    }
    if (!config_.real_time) return 0;
    // Paced: the board's 3.072 MHz against the host's clock since the run began.
    const double ahead = static_cast<double>(m.now() - run_.started_at) / board::kCpuHz -
                         (host_seconds() - run_.host_start);
    return ahead > 0 ? static_cast<int>(ahead * 1000) : 0;
}

}  // namespace alp85::dap
