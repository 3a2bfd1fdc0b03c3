// alp85 debug [FIRMWARE...] [--script FILE] [--batch]: the source-level debugger (docs/debugging.md)
// on the script session's machine. Interactive with line editing, history and completion through
// libedit; --script runs a file of commands first (echoed after the prompt, so a batch log reads as
// a session), --batch ends there. Exit status: 0, 1 a command failed in a batch session, 2 usage.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string_view>

#include <editline/readline.h>
#include <fmt/format.h>

#include "emu/cli/commands.h"
#include "emu/util/input_file.h"
#include "emu/program/firmware.h"
#include "emu/script/debug_shell.h"

namespace alp85::cli {

namespace {
debug::Debugger* g_debugger = nullptr;       // for the Ctrl-C handler
script::DebugShell* g_completing = nullptr;  // for libedit's completion callbacks

volatile std::sig_atomic_t g_sigints = 0;  // Ctrl-C presses so far

extern "C" void on_sigint(int) {
    g_sigints = g_sigints + 1;
    if (g_debugger) g_debugger->interrupt();
}

std::vector<std::string> g_matches;
char* next_match(const char*, int state) {
    static std::size_t i = 0;
    if (state == 0) i = 0;
    return i < g_matches.size() ? strdup(g_matches[i++].c_str()) : nullptr;
}
char** complete(const char* text, int start, int) {
    rl_attempted_completion_over = 1;
    if (!g_completing) return nullptr;
    // The command the word follows (load, save, ... complete file names).
    std::string_view line = rl_line_buffer ? std::string_view(rl_line_buffer) : std::string_view{};
    line = line.substr(0, std::min<std::size_t>(static_cast<std::size_t>(start), line.size()));
    const auto from = line.find_first_not_of(" \t");
    const std::string_view command =
        from == std::string_view::npos ? std::string_view{} : line.substr(from, line.find_first_of(" \t", from) - from);
    g_matches = g_completing->console().complete(text, start == 0, command);
    // A folder is completed without the space after it, so that its files can follow.
    rl_completion_append_character = g_matches.size() == 1 && g_matches[0].ends_with('/') ? '\0' : ' ';
    return rl_completion_matches(text, next_match);
}

// Runs lines until quit or the end; true when no line failed.
bool run_lines(script::DebugShell& shell, std::istream& in, const std::string& file, bool echo) {
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        shell.set_origin(file, n);
        if (echo) std::cout << shell.console().prompt() << line << '\n';
        std::cout << shell.execute(line) << std::flush;
        if (shell.console().quit_requested()) break;
    }
    shell.set_origin("", 0);
    return shell.console().errors() == 0;
}

void interactive(script::DebugShell& shell) {
    g_completing = &shell;
    rl_attempted_completion_function = complete;
    const std::string history_file = [] {
        const char* home = std::getenv("HOME");
        return home ? std::string(home) + "/.alp85_debug_history" : std::string();
    }();
    using_history();
    if (!history_file.empty()) read_history(history_file.c_str());
    std::string last;
    while (!shell.console().quit_requested()) {
        const std::string prompt = shell.console().prompt();
        const std::sig_atomic_t sigints = g_sigints;
        char* raw = readline(prompt.c_str());
        if (!raw && g_sigints != sigints) {  // Ctrl-C at the prompt: a fresh line, as gdb does
            std::cout << "^C\n" << std::flush;
            continue;
        }
        if (!raw) {  // Ctrl-D
            std::cout << "quit\n";
            break;
        }
        std::string line(raw);
        std::free(raw);
        if (line.empty()) line = last;  // gdb: an empty line repeats the last command
        else add_history(line.c_str());
        last = line;
        std::cout << shell.execute(line) << std::flush;
    }
    if (!history_file.empty()) write_history(history_file.c_str());
    g_completing = nullptr;
}
}  // namespace

void add_debug_command(CLI::App& app, int& status) {
    struct Args {
        std::vector<std::string> firmware, firmware_option;
        std::string script;
        bool batch = false;
        bool no_history = false;
        std::string out_dir;
        std::string motor = "physical";
        std::string board = "alp85", rom;
        std::string max_time = "1h";
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("debug", "The source-level debugger (docs/debugging.md)");
    cmd->add_option("firmware", args->firmware,
                    "Built-in firmware (thesis-fixed, thesis) or program files (.asm, .hex) to load after the monitor");
    cmd->add_option("--firmware", args->firmware_option,
                    "Firmware to load, named as the positional arguments are (a built-in name or a file); may be repeated");
    cmd->add_option("--script", args->script, "Run the commands of FILE first (echoed as a session)");
    cmd->add_flag("--batch", args->batch, "End after --script (or after standard input); status 1 if a command failed");
    cmd->add_flag("--no-history", args->no_history, "No snapshots for reverse execution");
    add_motor_option(cmd, args->motor);
    add_board_option(cmd, args->board);
    add_rom_option(cmd, args->rom);
    add_max_time_option(cmd, args->max_time);
    cmd->add_option("--out-dir", args->out_dir, "Folder for the files save, restore, record and plot write");
    cmd->footer(
        "Examples:\n"
        "  alp85 debug thesis-fixed\n"
        "  alp85 debug thesis-fixed --script session.gdb --batch\n"
        "Exit status: 0, 1 a command failed in a batch session (a save, record or plot onto a file the\n"
        "session reads is such a failure; a run that reached --max-time fails), 2 a usage error (a\n"
        "--script that is missing, unreadable, empty or no file).");
    cmd->callback([args, &status] {
        args->firmware.insert(args->firmware.begin(), args->firmware_option.begin(), args->firmware_option.end());
        // The script is read whole before anything runs: one that cannot be read, or is empty, is
        // a usage error, not a session that silently does nothing.
        std::string script_text;
        if (!args->script.empty()) {
            try {
                script_text = read_input(args->script, FileKind::Script);
            } catch (const InputError& e) {
                const std::string why = e.what();
                std::cerr << argument_error("alp85 debug", args->script,
                                            why.rfind("no such file", 0) == 0 ? fmt::format("no such script '{}'", args->script)
                                                                               : why);
                status = kUsageError;
                return;
            }
            if (script_text.empty()) {
                std::cerr << argument_error("alp85 debug", args->script,
                                            fmt::format("the script '{}' is empty: no commands to run", args->script));
                status = kUsageError;
                return;
            }
        }
        const auto max_time = max_time_of("alp85 debug", args->max_time);
        if (!max_time) {
            status = kUsageError;
            return;
        }
        script::SessionOptions o;
        o.max_time = *max_time;
        o.board = board_of(args->board);
        o.base_dir = args->script.empty() ? std::filesystem::current_path()
                                          : std::filesystem::absolute(args->script).parent_path();
        if (firmware::have_monitor()) o.monitor_rom = firmware::monitor;
        script::DebugShell shell(o);
        if (!args->out_dir.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(args->out_dir, ec);
            shell.session().set_out_dir(std::filesystem::absolute(args->out_dir));
        }
        // The monitor first (the thesis firmware calls its routines), then the programs, then RESET.
        script::Session::Boot boot;
        boot.monitor = firmware::have_monitor() && board_of(args->board)->builtin_firmware;  // the built-in monitor is the ALP 85's
        boot.motor = motor_model_of(args->motor);
        for (const std::string& f : args->firmware) {
            if (firmware::find(f)) {
                boot.firmware.push_back(f);
                continue;
            }
            if (const std::string why = program_file_problem(f); !why.empty()) {
                std::cerr << argument_error(
                    "alp85 debug", f,
                    why.rfind("no such file", 0) == 0
                        ? fmt::format("'{}' is neither built-in firmware (thesis-fixed, thesis) nor a file", f)
                        : fmt::format("{} (nor built-in firmware: thesis-fixed, thesis)", why));
                status = kUsageError;
                return;
            }
            boot.images.push_back({std::filesystem::absolute(f), std::nullopt});
        }
        if (!args->script.empty()) shell.session().add_input(std::filesystem::absolute(args->script), "the script");
        if (!args->rom.empty()) {  // the board's ROM, before the programs and the RESET
            std::string why = board_of(args->board)->builtin_firmware ? "--rom is for --board sdk85 (the ALP 85's monitor is built in)"
                                                     : shell.session().check_rom(std::filesystem::absolute(args->rom));
            if (why.empty()) why = shell.session().load_rom(std::filesystem::absolute(args->rom)).message;
            if (!why.empty()) {
                std::cerr << argument_error("alp85 debug", args->rom, "--rom: " + why);
                status = kUsageError;
                return;
            }
        }
        if (const auto booted = shell.session().boot(boot); booted.status != script::Session::Status::Ok) {
            std::cerr << "alp85 debug: " << booted.message << '\n';
            status = kUsageError;
            return;
        }
        shell.debugger().set_history(!args->no_history);

        debug::Debugger* previous = g_debugger;
        g_debugger = &shell.debugger();
        struct sigaction sa {};
        sa.sa_handler = on_sigint;
        sigemptyset(&sa.sa_mask);
        // Reading commands from a file or a pipe, a Ctrl-C between commands must not end the
        // input (a read interrupted by it is resumed); at the prompt libedit needs the
        // interruption to start a fresh line.
        if (args->batch || !isatty(STDIN_FILENO)) sa.sa_flags = SA_RESTART;
        struct sigaction old {};
        sigaction(SIGINT, &sa, &old);

        bool ok = true;
        if (!args->script.empty()) {
            std::istringstream in(script_text);
            ok = run_lines(shell, in, args->script, true);
        }
        if (args->batch) {
            if (args->script.empty()) ok = run_lines(shell, std::cin, "<stdin>", true);
        } else if (!shell.console().quit_requested()) {
            if (isatty(STDIN_FILENO)) {
                std::cout << shell.console().banner() << std::flush;
                interactive(shell);
            } else {
                run_lines(shell, std::cin, "", true);
            }
        }
        sigaction(SIGINT, &old, nullptr);
        g_debugger = previous;
        status = args->batch && !ok ? 1 : 0;
    });
}

}  // namespace alp85::cli
