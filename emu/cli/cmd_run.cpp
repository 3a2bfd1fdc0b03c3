// alp85 run [PROGRAM...] [--keys "R 7 0800 EXEC"] [--boot TIME] [--for TIME] [--no-monitor]:
// the board, headless. It boots the monitor, shows the display after RESET, types the keys, runs,
// and shows the display again. Built on the command language's Session, like every front end.
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "emu/cli/commands.h"
#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/script/session.h"

namespace alp85::cli {
namespace {

// "R 7 0800 EXEC" -> R 7 0 8 0 0 EXEC: a word that is not a key name but is all hex digits is
// typed digit by digit.
std::vector<std::string> expand_keys(const std::string& text, std::string& error) {
    std::vector<std::string> keys;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && text[i] == ' ') ++i;
        std::size_t j = i;
        while (j < text.size() && text[j] != ' ') ++j;
        if (j == i) break;
        const std::string w = text.substr(i, j - i);
        i = j;
        if (script::parse_key(w)) {
            keys.push_back(w);
            continue;
        }
        for (char ch : w) {
            if (!std::isxdigit(static_cast<unsigned char>(ch))) {
                error = fmt::format("unknown key '{}' in --keys", w);
                return {};
            }
            keys.emplace_back(1, ch);
        }
    }
    return keys;
}

void add_display(std::vector<std::string>& lines, bool text_only) {
    if (!text_only) lines.push_back("print display");
    lines.push_back("print display text");
}

}  // namespace

void add_run_command(CLI::App& app, int& status) {
    struct Args {
        std::vector<std::string> programs;
        std::string keys, boot = "500ms", run_for = "1s";
        bool no_monitor = false, text = false;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("run", "Run the ALP 85 headless: boot the monitor, type keys, show the display");
    cmd->add_option("programs", args->programs, "Programs to load first (.asm, .hex; FILE.bin@ADDR)");
    auto* keys = cmd->add_option("--keys", args->keys, "Keys to type after booting, e.g. \"R 7 0800 EXEC\"");
    cmd->add_option("--boot", args->boot, "Time to run after RESET before typing (default 500ms)");
    cmd->add_option("--for", args->run_for, "Time to run after the keys (default 1s)")->needs(keys);
    cmd->add_flag("--no-monitor", args->no_monitor, "Do not load the built-in monitor ROM");
    cmd->add_flag("--text", args->text, "Show the display as text only (no seven-segment art)");
    cmd->footer(
        "Examples:\n"
        "  alp85 run                                          # the monitor's sign-on\n"
        "  alp85 run firmware/demo/hello85.asm --keys \"R 7 0800 EXEC\"\n"
        "Exit status: 0 success, 1 a program could not be placed or run, 2 a usage error or a bad\n"
        "argument (a program that is missing or does not assemble, a bad time or key).");
    cmd->callback([args, &status] {
        script::SessionOptions so;
        so.out = &std::cout;
        if (firmware::have_monitor()) so.monitor_rom = firmware::monitor;
        script::Session session(so);
        std::vector<script::ParseError> errors;
        std::vector<std::string> lines;
        if (!args->no_monitor) {
            if (!firmware::have_monitor()) {
                std::cerr << "alp85 run: this alp85 was built without the monitor ROM (use --no-monitor)\n";
                status = 2;
                return;
            }
            lines.push_back("monitor");
        }
        for (const std::string& p : args->programs) {
            const auto at = p.rfind('@');
            lines.push_back(at == std::string::npos ? fmt::format("load \"{}\"", p)
                                                    : fmt::format("load \"{}\" at {}", p.substr(0, at), p.substr(at + 1)));
        }
        lines.push_back("reset");
        lines.push_back("run " + args->boot);
        lines.push_back("print \"after RESET:\"");
        add_display(lines, args->text);
        std::string key_error;
        const auto keys = expand_keys(args->keys, key_error);
        if (!key_error.empty()) {
            std::cerr << "alp85 run: " << key_error << '\n';
            status = 2;
            return;
        }
        if (!keys.empty()) {
            std::string type = "type";
            for (const auto& k : keys) type += " " + k;
            lines.push_back(type);
            lines.push_back("run " + args->run_for);
            lines.push_back(fmt::format("print \"after {}:\"", args->keys));
            add_display(lines, args->text);
        }
        std::vector<script::Command> commands;
        int n = 0;
        for (const std::string& l : lines) {
            ++n;
            if (auto c = script::parse_line(l, "alp85 run", n, errors)) commands.push_back(std::move(*c));
        }
        session.check(commands, errors);
        if (!errors.empty()) {
            for (const auto& e : errors) std::cerr << e.format();
            status = 2;
            return;
        }
        for (const auto& c : commands) {
            const auto o = session.execute(c);
            if (o.status != script::Session::Status::Ok) {
                std::cerr << o.message << '\n';
                status = 1;
                return;
            }
        }
        std::cout << fmt::format("{} simulated, PC={:04X}H\n", script::Session::format_time(session.machine().now()),
                                 session.machine().cpu().regs().pc);
        status = 0;
    });
}

}  // namespace alp85::cli
