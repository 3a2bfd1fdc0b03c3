// The debugger's command line over a script Session: the debugger's commands (debug::Console)
// and, for every other line, the script language. `alp85 debug` drives one; the GUI's command
// pane and a DAP server's REPL can drive the same.
#pragma once

#include <string>
#include <string_view>

#include "emu/debug/console.h"
#include "emu/script/session.h"

namespace alp85::script {

class DebugShell {
public:
    // options.out should be null: the shell returns all text from execute().
    explicit DebugShell(SessionOptions options);

    Session& session() { return session_; }
    debug::Debugger& debugger() { return session_.debugger(); }
    debug::Console& console() { return console_; }

    // One line (a debugger command or a script command); the text to show.
    std::string execute(std::string_view line) { return console_.execute(line); }
    // Where the next lines come from ("session.gdb", 12), for error messages; "" interactively.
    void set_origin(const std::string& file, int line) {
        file_ = file;
        line_ = line;
        console_.set_origin(file, line);
    }

private:
    bool run_script_line(std::string_view line, std::string& out);

    Session session_;
    debug::Console console_;
    std::string file_;
    int line_ = 0;
};

}  // namespace alp85::script
