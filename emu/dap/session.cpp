// initialize, launch, configurationDone, restart, disconnect, terminate: the adapter's life.
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "emu/dap/adapter.h"
#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/util/input_file.h"

namespace alp85::dap {

script::Session& Adapter::session() {
    if (!session_) throw RequestError("no program yet: send 'launch' first");
    return *session_;
}

void Adapter::initialize(const Json& args, Json& body) {
    if (initialized_) throw RequestError("'initialize' twice");
    initialized_ = true;
    lines_start_at_1_ = opt_bool(args, "linesStartAt1").value_or(true);
    body = {
        {"supportsConfigurationDoneRequest", true},
        {"supportsFunctionBreakpoints", true},
        {"supportsConditionalBreakpoints", true},
        {"supportsHitConditionalBreakpoints", true},
        {"supportsLogPoints", true},
        {"supportsEvaluateForHovers", true},
        {"supportsStepBack", true},
        {"supportsSetVariable", true},
        {"supportsRestartRequest", true},
        {"supportsGotoTargetsRequest", true},
        {"supportsReadMemoryRequest", true},
        {"supportsWriteMemoryRequest", true},
        {"supportsDisassembleRequest", true},
        {"supportsInstructionBreakpoints", true},
        {"supportsDataBreakpoints", true},
        {"supportsTerminateRequest", true},
        {"supportsSteppingGranularity", true},
        {"supportsBreakpointLocationsRequest", true},
        {"supportTerminateDebuggee", true},
        {"exceptionBreakpointFilters",
         Json::array({{{"filter", "runaway"},
                       {"label", "Runaway program"},
                       {"description", "Stop when the CPU fetches an instruction where no program was loaded"},
                       {"default", true}}})},
    };
}

void Adapter::launch(const Json& args, Json&) {
    if (shell_) throw RequestError("already launched (use 'restart')");
    config_ = parse_launch(args);
    start_session();
    event("initialized");
}

void Adapter::start_session() {
    run_ = {};
    script::SessionOptions so;
    so.base_dir = config_.cwd;
    so.board = script::Session::find_board(config_.board);
    if (firmware::have_monitor()) so.monitor_rom = firmware::monitor;
    auto shell = std::make_unique<script::DebugShell>(so);
    shell->debugger().listen([this](const debug::Event& e) { on_debug_event(e); });
    std::vector<std::string> warnings;
    load_program(config_, shell->session(), map_, warnings);  // throws: the old session stays
    engine_points_.clear();  // they belonged to the old session's Debugger
    engine_to_dap_.clear();
    shell_ = std::move(shell);
    session_ = &shell_->session();
    for (const std::string& w : warnings) output("stderr", w);
    debug::Debugger& d = session_->debugger();
    d.set_history(true);  // stepBack and reverseContinue from the first instruction on
    d.set_poll(poll_);    // a pause during a long reverseContinue
    // The stack's top as the program set it (LXI SP / SPHL): return addresses above it are left
    // over from earlier code (the monitor's), not callers.
    d.track_stack_base(true);
    d.set_runaway_guard(config_.stop_on_runaway ? &map_.code : nullptr);
    resolve_breakpoints();
}

void Adapter::configuration_done(const Json&, Json&) {
    if (!session_) throw RequestError("'configurationDone' before 'launch'");
    if (configured_) throw RequestError("'configurationDone' twice");
    configured_ = true;
    begin();
}

void Adapter::begin() {
    if (!config_.script.empty()) {
        std::filesystem::path path = config_.script;
        if (path.is_relative()) path = config_.cwd / path;
        std::string text;
        try {
            text = read_input(path, FileKind::Script);
        } catch (const InputError& e) {
            output("stderr", fmt::format("launch script: {}", e.what()));
            stopped("entry", "the launch script could not be read");
            return;
        }
        std::vector<script::ParseError> errors;
        std::vector<std::string> included;
        const auto commands = script::parse_script(text, path.string(), errors, &included);
        session().add_input(path, "the launch script");
        for (const std::string& f : included) session().add_input(f, "an included script");
        for (const auto& e : errors) output("stderr", e.format());
        if (!errors.empty()) {
            stopped("entry", "the launch script has errors");
            return;
        }
        for (const script::Command& c : commands) {
            const auto o = session_->execute(c);
            if (o.status != script::Session::Status::Ok) {
                output("stderr", o.message);
                stopped("entry", "the launch script failed");
                return;
            }
        }
    }
    if (config_.stop_on_entry) stopped("entry");
    else started(session_->debugger().begin_continue(~std::uint64_t{0}), "step");
}

void Adapter::restart(const Json& args, Json&) {
    if (!session_) throw RequestError("'restart' before 'launch'");
    if (args.is_object() && args.contains("arguments")) config_ = parse_launch(args["arguments"]);
    start_session();
    for (auto& [path, list] : bps_.source)
        for (Breakpoint& b : list) event("breakpoint", {{"reason", "changed"}, {"breakpoint", breakpoint_json(b, path)}});
    begin();
}

void Adapter::disconnect(const Json&, Json&) {
    if (session_) session_->debugger().pause();
    finished_ = true;
}

void Adapter::terminate(const Json&, Json&) {
    if (session_) session_->debugger().pause();
    run_.steps_left = 0;  // a console's step N ends too
    run_.console = false;
    event("terminated");
}

}  // namespace alp85::dap
