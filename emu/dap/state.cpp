// threads, stackTrace, scopes, variables, setVariable, evaluate: the machine as the editor shows
// it. Scopes: the registers and flags, the firmware's variables (RAM symbols with their sizes),
// each part's description (machine_view.h) and the display.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "asm/isa.h"
#include "emu/dap/adapter.h"
#include "emu/dap/machine_view.h"
#include "emu/front/views.h"
#include "emu/script/parser.h"
#include "emu/util/text.h"

namespace alp85::dap {

Json Adapter::source_of(const std::string& file) const {
    return {{"name", std::filesystem::path(file).filename().string()}, {"path", file}};
}

void Adapter::threads(const Json&, Json& body) {
    body = {{"threads", Json::array({{{"id", 1}, {"name", "8085"}}})}};
}

void Adapter::stack_trace(const Json& args, Json& body) {
    require_stopped();
    const std::int64_t start = std::max<std::int64_t>(0, opt_int(args, "startFrame").value_or(0));
    const std::int64_t levels = opt_int(args, "levels").value_or(0);
    const std::vector<CallFrame> frames = call_frames(session_->debugger());
    Json out = Json::array();
    for (std::size_t i = static_cast<std::size_t>(start); i < frames.size(); ++i) {
        if (levels > 0 && static_cast<std::int64_t>(out.size()) >= levels) break;
        const CallFrame& f = frames[i];
        Json j = {{"id", static_cast<int>(i) + 1},
                  {"name", f.name},
                  {"line", 0},
                  {"column", 0},
                  {"instructionPointerReference", hex4(f.pc)}};
        if (f.line) {
            j["source"] = source_of(f.line->file);
            j["line"] = f.line->line - (lines_start_at_1_ ? 0 : 1);
            j["column"] = lines_start_at_1_ ? 1 : 0;
        } else {
            j["presentationHint"] = "subtle";
        }
        out.push_back(std::move(j));
    }
    body = {{"stackFrames", out}, {"totalFrames", frames.size()}};
}

void Adapter::scopes(const Json& args, Json& body) {
    require_stopped();
    need_int(args, "frameId");
    Json out = Json::array();
    for (const ScopeInfo& s : scope_list(session_->debugger()))
        out.push_back({{"name", s.name}, {"variablesReference", s.ref}, {"expensive", false},
                       {"presentationHint", s.hint}});
    body = {{"scopes", out}};
}

void Adapter::variables(const Json& args, Json& body) {
    session();
    const std::int64_t ref = need_int(args, "variablesReference");
    Json out = Json::array();
    for (const Variable& v : list_variables(session_->debugger(), ref)) {
        Json j = {{"name", v.name}, {"value", v.value}, {"variablesReference", v.children}};
        if (!v.type.empty()) j["type"] = v.type;
        if (v.memory) j["memoryReference"] = hex4(*v.memory);
        if (v.read_only) j["presentationHint"] = {{"attributes", Json::array({"readOnly"})}};
        out.push_back(std::move(j));
    }
    body = {{"variables", out}};
}

void Adapter::set_variable(const Json& args, Json& body) {
    require_stopped();
    const std::int64_t ref = need_int(args, "variablesReference");
    const std::string name = need_string(args, "name");
    const std::string value = need_string(args, "value");
    const auto v = script::parse_number(value);
    if (!v) throw RequestError(fmt::format("'{}' is not a number (12, 0CH, 0x0C, 1100B)", value));
    const std::string error = assign_variable(session_->debugger(), ref, name, *v);
    if (!error.empty()) throw RequestError(error);
    for (const Variable& x : list_variables(session_->debugger(), ref))
        if (x.name == name) body = {{"value", x.value}, {"variablesReference", x.children}};
}

std::optional<std::pair<std::uint16_t, std::uint16_t>> Adapter::data_target(const std::string& name, std::int64_t ref) {
    session();
    if (ref != 0 && ref != kFirmwareScope) return std::nullopt;
    const SymbolTable& t = session_->debugger().program();
    if (const auto v = t.value_of(name)) return std::pair{*v, variable_size(t, *v)};
    if (const auto n = script::parse_number(name); n && *n >= 0 && *n <= 0xFFFF)
        return std::pair{static_cast<std::uint16_t>(*n), std::uint16_t{1}};
    return std::nullopt;
}

void Adapter::evaluate(const Json& args, Json& body) {
    session();
    const std::string expression = need_string(args, "expression");
    const std::string context = opt_string(args, "context").value_or("repl");
    std::string error;
    if (context != "repl") {
        const auto v = expression_value(session_->debugger(), expression, error);
        if (!v) throw RequestError(error);
        body = {{"result", *v}, {"variablesReference", 0}};
        return;
    }
    // The debug console: one word that is a value shows it (YAC, HL, word[1B30H]); anything else
    // is a line for the debugger's console (break, x, info PART, finish, ...) or the command
    // language (press, type, expect, print display, ...).
    std::string word = expression.substr(0, expression.find_first_of(" \t"));
    const bool one_word = expression.find_first_not_of(" \t", word.size()) == std::string::npos;
    bool command = !one_word;
    for (const std::string& c : shell_->console().complete(word, true)) command = command || to_upper(c) == to_upper(word);
    if (!command)
        if (const auto v = expression_value(session_->debugger(), expression, error)) {
            body = {{"result", *v}, {"variablesReference", 0}};
            return;
        }
    if (running()) throw RequestError("the program is running: pause it before a console command");
    // A run (continue, step, run 3000s, ...) goes on between messages, as the continue request's.
    if (auto text = begin_console_run(expression)) {
        body = {{"result", *text}, {"variablesReference", 0}};
        return;
    }
    const std::uint64_t before = session_->now();
    const std::uint16_t pc = front::cpu_view(*session_).pc;
    const int errors = shell_->console().errors();
    capturing_ = true;  // the console gathers the debugger's output itself
    std::string text = shell_->execute(expression);
    capturing_ = false;
    captured_.clear();
    while (!text.empty() && text.back() == '\n') text.pop_back();
    const bool moved = session_->now() != before || front::cpu_view(*session_).pc != pc;
    if (shell_->console().errors() > errors) {
        if (moved) stopped("step", "after the console command");
        throw RequestError(text);
    }
    body = {{"result", text.empty() ? "ok" : text}, {"variablesReference", 0}};
    // A command that ran the machine: the editor shows where it is now.
    if (moved) stopped("step", "after the console command");
}

void Adapter::source(const Json&, Json&) {
    throw RequestError("sources are the files on disk: every Source this adapter sends has a path");
}

}  // namespace alp85::dap
