#include "emu/script/debug_shell.h"

#include <fmt/format.h>

namespace alp85::script {

DebugShell::DebugShell(SessionOptions options) : session_(std::move(options)), console_(session_.debugger()) {
    console_.set_fallback([this](std::string_view line, std::string& out) { return run_script_line(line, out); });
    // The script's commands join the console's in its one list (help, completion).
    std::vector<debug::Console::CommandDef> script;
    for (const CommandInfo& c : commands()) {
        debug::Console::CommandDef d;
        d.name = c.name;
        d.help = c.help;
        d.forms = c.forms;
        d.takes_file = c.takes_file;
        script.push_back(std::move(d));
    }
    console_.add_commands(script);
}

bool DebugShell::run_script_line(std::string_view line, std::string& out) {
    std::vector<ParseError> errors;
    const std::optional<Command> c = parse_line(line, file_.empty() ? "(alp85)" : file_, line_ ? line_ : 1, errors);
    if (!errors.empty()) {
        const ParseError& e = errors.front();
        if (file_.empty()) {
            out += fmt::format("column {}: error: {}\n  {}\n  {}^\n", e.where.col, e.message, e.line,
                               std::string(static_cast<std::size_t>(std::max(e.where.col, 1) - 1), ' '));
        } else {
            out += e.format();
        }
        return false;
    }
    if (!c) return true;
    const Session::Outcome o = session_.execute(*c);
    if (o.status == Session::Status::Failed) {
        out += o.message + '\n';
        return false;
    }
    return true;
}

}  // namespace alp85::script
