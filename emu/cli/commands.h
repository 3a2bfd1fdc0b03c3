// The alp85 subcommands; each lives in its own file (cmd_*.cpp) and registers itself on the app.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "asm/files/output_paths.h"
#include "emu/util/stopwatch.h"

#include "peripherals/machine_tool.h"

#include "emu/core/i8085.h"

namespace alp85::board {
struct Board;
}

namespace alp85::cli {

// The exit status of every usage error (an unknown option, a missing or malformed argument).
inline constexpr int kUsageError = 2;

// The command line as the user typed it ("alp85 run prog.asm --boot 1s"), so that a report can
// point at an argument as a compiler points at a column: `alp85 run:1:COL: error: ...`, the line
// and a caret. main() sets it before parsing.
void set_command_line(int argc, const char* const* argv);
const std::string& command_line();
// 1-based column of `argument` in command_line() (also as the value of --option=argument); 1 if
// it is not there.
int column_of(std::string_view argument);

// An output that is one of the inputs, or two outputs on one file: reported as
// `alp85 COMMAND: error: ...; nothing written` and true (the caller exits with kUsageError before
// it writes anything).
bool refuse_output_clash(std::string_view command, const std::vector<NamedPath>& inputs,
                         const std::vector<NamedPath>& outputs);
// An output option given an empty name (`--junit ''`: an unset shell variable, not a request for
// no file or the default name): reported as a usage error naming the option, and true.
bool refuse_empty_outputs(std::string_view command, const CLI::App& cmd, const std::vector<std::string>& options);
// An option naming a file the command writes (--output, --trace, --svg, ...), its long name kept
// in `outputs` for on_run.
CLI::Option* add_output_option(CLI::App* cmd, std::vector<std::string>& outputs, const std::string& name,
                               std::string& path, const std::string& help);
// What the command runs: a usage error when one of `outputs` was given an empty name
// (refuse_empty_outputs), else the exit status `run` gives, into `status`.
// An exception out of `run` (an output that cannot be written, an input gone since it was checked)
// is reported as `alp85 COMMAND: WHAT` with status 1.
void on_run(CLI::App* cmd, int& status, std::vector<std::string> outputs, std::function<int()> run);

// A subcommand being declared: its CLI11 node (`cmd->add_option(...)`), the arguments its options
// fill (kept alive by its callback), and the output options it names, which on_run checks.
template <class Args>
struct Subcommand {
    Subcommand(CLI::App& app, const std::string& name, const std::string& summary)
        : cmd(app.add_subcommand(name, summary)) {}
    CLI::App* operator->() const { return cmd; }
    CLI::Option* output(const std::string& name, std::string& path, const std::string& help) {
        return add_output_option(cmd, outputs, name, path, help);
    }
    // What the command runs once its options are parsed: `run(args)` gives the exit status.
    void run(int& status, std::function<int(const Args&)> run) {
        on_run(cmd, status, outputs, [a = args, run = std::move(run)] { return run(*a); });
    }

    CLI::App* cmd;
    std::shared_ptr<Args> args = std::make_shared<Args>();
    std::vector<std::string> outputs;
};
// "" when `path` can be opened as an input file; else why not, naming it ("'x.com' is a
// directory", "no such file 'x.com'").
std::string input_file_problem(const std::string& path);

// A report on one argument, as `alp85 run` gives it: "WHO:1:COL: error: MESSAGE", the command
// line, and a caret under the argument.
std::string argument_error(std::string_view who, std::string_view argument, const std::string& message);

// --cpu 8080|8085 on a command (the processor to emulate or decode as), into `cpu`, which keeps
// its default; variant_of() gives the Variant it names.
CLI::Option* add_cpu_option(CLI::App* cmd, std::string& cpu, const std::string& help);
Variant variant_of(const std::string& cpu);
// --motor ideal|physical (the machine tool's motor model), default physical; motor_model_of()
// gives the model it names.
CLI::Option* add_motor_option(CLI::App* cmd, std::string& motor);
periph::MachineTool::MotorModel motor_model_of(const std::string& motor);

// --board NAME (run, script, debug, gui, dap): the board to build, alp85 (the default) or sdk85;
// an unknown name is a usage error listing the boards. board_of() gives the description it names.
CLI::Option* add_board_option(CLI::App* cmd, std::string& board);
// --rom FILE (run, debug, gui): the ROM at 0000H of a board whose ROM is the user's (--board sdk85).
CLI::Option* add_rom_option(CLI::App* cmd, std::string& rom);
const board::Board* board_of(const std::string& board);

// --max-time TIME (script, debug): the machine time a session may run, "1h" by default (a number
// with a unit: t, us, ms, s or h), into `text`; max_time_of() gives the T-states, or prints why
// the text is no time (argument_error) and gives nullopt.
CLI::Option* add_max_time_option(CLI::App* cmd, std::string& text);
std::optional<std::uint64_t> max_time_of(std::string_view who, const std::string& text);

// Host time of a run: wall clock and this process's CPU time, from construction.
using alp85::Stopwatch;  // emu/util/stopwatch.h

// Each add_* registers a subcommand whose callback stores the process exit status in `status`.
void add_cpm_command(CLI::App& app, int& status);
void add_bench_command(CLI::App& app, int& status);
void add_disasm_command(CLI::App& app, int& status);
void add_script_command(CLI::App& app, int& status);
void add_run_command(CLI::App& app, int& status);
void add_gcode_command(CLI::App& app, int& status);
void add_pisa_command(CLI::App& app, int& status);
void add_gui_command(CLI::App& app, int& status);
void add_debug_command(CLI::App& app, int& status);
void add_dap_command(CLI::App& app, int& status);
void add_timing_command(CLI::App& app, int& status);

}  // namespace alp85::cli
