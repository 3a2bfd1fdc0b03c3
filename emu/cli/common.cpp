#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "emu/cli/commands.h"
#include "emu/board/board_map.h"
#include "emu/util/input_file.h"
#include "emu/script/parser.h"

namespace alp85::cli {
namespace {

struct Arg {
    std::string text;
    int col;  // 1-based column of text's first character in the line
};
std::string g_line;
std::vector<Arg> g_args;

}  // namespace

void set_command_line(int argc, const char* const* argv) {
    g_line = "alp85";
    g_args.clear();
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        g_line += ' ';
        const bool quote = a.empty() || a.find_first_of(" \t'\"") != std::string::npos;
        if (quote) g_line += '"';
        g_args.push_back({a, static_cast<int>(g_line.size()) + 1});
        g_line += a;
        if (quote) g_line += '"';
    }
}

const std::string& command_line() { return g_line; }

std::string argument_error(std::string_view who, std::string_view argument, const std::string& message) {
    const int col = column_of(argument);
    return std::string(who) + ":1:" + std::to_string(col) + ": error: " + message + "\n " + g_line + "\n " +
           std::string(static_cast<std::size_t>(col - 1), ' ') + "^\n";
}

bool refuse_output_clash(std::string_view command, const std::vector<NamedPath>& inputs,
                         const std::vector<NamedPath>& outputs) {
    const std::string clash = output_clash(inputs, outputs);
    if (clash.empty()) return false;
    std::cerr << "alp85 " << command << ": error: " << clash << "; nothing written\n";
    return true;
}

bool refuse_empty_outputs(std::string_view command, const CLI::App& cmd, const std::vector<std::string>& options) {
    for (const std::string& name : options) {
        const CLI::Option* opt = cmd.get_option_no_throw(name);
        if (!opt || opt->count() == 0) continue;
        for (const std::string& value : opt->results())
            if (value.empty()) {
                std::cerr << argument_error("alp85 " + std::string(command), "",
                                            name + " needs a file name; nothing was run or written");
                return true;
            }
    }
    return false;
}

CLI::Option* add_output_option(CLI::App* cmd, std::vector<std::string>& outputs, const std::string& name,
                               std::string& path, const std::string& help) {
    outputs.push_back(name.substr(name.rfind(',') + 1));  // "-o,--output": --output
    return cmd->add_option(name, path, help);
}

void on_run(CLI::App* cmd, int& status, std::vector<std::string> outputs, std::function<int()> run) {
    cmd->callback([cmd, &status, outputs = std::move(outputs), run = std::move(run)] {
        if (refuse_empty_outputs(cmd->get_name(), *cmd, outputs)) {
            status = kUsageError;
            return;
        }
        try {
            status = run();
        } catch (const CLI::Error&) {
            throw;  // CLI11's own (--help, a usage error), which main() reports
        } catch (const std::exception& e) {
            std::cerr << "alp85 " << cmd->get_name() << ": " << e.what() << '\n';
            status = 1;
        }
    });
}

std::string input_file_problem(const std::string& path) { return input_problem(path); }

CLI::Option* add_cpu_option(CLI::App* cmd, std::string& cpu, const std::string& help) {
    return cmd->add_option("--cpu", cpu, help)->check(CLI::IsMember({"8080", "8085"}))->capture_default_str();
}

Variant variant_of(const std::string& cpu) { return cpu == "8080" ? Variant::I8080 : Variant::I8085; }

CLI::Option* add_motor_option(CLI::App* cmd, std::string& motor) {
    return cmd
        ->add_option("--motor", motor,
                     "The machine tool's motors: ideal (1.8 degrees at each pulse) or physical (the hybrid stepper "
                     "with its currents and inertia, docs/machine.md)")
        ->check(CLI::IsMember({"ideal", "physical"}))
        ->capture_default_str();
}

periph::MachineTool::MotorModel motor_model_of(const std::string& motor) {
    return motor == "ideal" ? periph::MachineTool::MotorModel::Ideal : periph::MachineTool::MotorModel::Physical;
}

CLI::Option* add_board_option(CLI::App* cmd, std::string& board) {
    std::vector<std::string> names;
    for (const board::Board* b : board::kBoards) names.emplace_back(b->name);
    return cmd
        ->add_option("--board", board,
                     "The board to emulate: alp85 (the thesis machine) or sdk85 (Intel's SDK-85, docs/board.md)")
        ->check(CLI::IsMember(names))
        ->capture_default_str();
}

CLI::Option* add_rom_option(CLI::App* cmd, std::string& rom) {
    return cmd->add_option("--rom", rom,
                           "With --board sdk85: the ROM at 0000H-07FFH, a 2048-byte .bin dump, Intel HEX or asm85 source "
                           "(your own copy of Intel's monitor, or a program of yours; docs/sdk85.md). The ALP 85's monitor "
                           "is built in");
}

const board::Board* board_of(const std::string& board) {
    const board::Board* b = board::find_board(board);
    return b ? b : board::kBoards.front();
}

CLI::Option* add_max_time_option(CLI::App* cmd, std::string& text) {
    return cmd
        ->add_option("--max-time", text,
                     "Machine time the session may run at most (t, us, ms, s or h); a run that reaches it stops and "
                     "its command fails")
        ->capture_default_str();
}

std::optional<std::uint64_t> max_time_of(std::string_view who, const std::string& text) {
    std::optional<std::uint64_t> t;
    if (!text.empty() && (text.back() == 'h' || text.back() == 'H')) {  // hours: the script language stops at s
        const std::string num = text.substr(0, text.size() - 1);
        char* end = nullptr;
        const double h = std::strtod(num.c_str(), &end);
        if (!num.empty() && end == num.c_str() + num.size() && h > 0 && h < 1e5) t = script::parse_time(fmt::format("{}s", h * 3600));
    } else {
        t = script::parse_time(text);
    }
    if (!t || *t == 0) {
        std::cerr << argument_error(who, text,
                                    fmt::format("bad --max-time '{}' (a time above 0 with a unit: t, us, ms, s or h)", text));
        return std::nullopt;
    }
    return t;
}

int column_of(std::string_view argument) {
    for (const Arg& a : g_args)
        if (a.text == argument) return a.col;
    for (const Arg& a : g_args)  // --boot=5parsecs
        if (const auto eq = a.text.find('='); a.text.rfind("--", 0) == 0 && eq != std::string::npos &&
                                              std::string_view(a.text).substr(eq + 1) == argument)
            return a.col + static_cast<int>(eq) + 1;
    return 1;
}

}  // namespace alp85::cli
