// alp85 gui [FIRMWARE...]: the ALP 85 and its machine tool in a window (emu/gui). Exit status: 0,
// 1 the script (--script) or --expect-display failed or the screenshot cannot be written, 2 a
// usage error (a --rom the ROM loader refuses) or no display, 128 + the signal when SIGTERM or SIGINT closed it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include <unistd.h>

#include <fmt/format.h>

#include "emu/board/machine.h"
#include "emu/cli/commands.h"
#include "emu/debug/pin_tap.h"
#include "emu/gui/app.h"
#include "emu/gui/controls.h"
#include "emu/gui/test_hooks.h"
#include "emu/script/session.h"

namespace alp85::cli {
namespace {

// "" when `spec` is FILE:LINE with LINE a line number (1 to 10^7, far past any source), given with --debug.
std::string click_line_problem(const std::string& spec, bool debug) {
    if (!debug) return "needs --debug (the source rows it clicks are in the debugger's panes)";
    const auto colon = spec.rfind(':');
    if (colon == std::string::npos || colon == 0) return "expected FILE:LINE";
    const std::string line = spec.substr(colon + 1);
    if (line.empty() || line.size() > 8 || !std::all_of(line.begin(), line.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return "LINE must be a line number from 1 to 10000000";
    const long n = std::stol(line);
    if (n < 1 || n > 10'000'000) return "LINE must be a line number from 1 to 10000000";
    return {};
}

}  // namespace

void add_gui_command(CLI::App& app, int& status) {
    struct Args {
        gui::GuiOptions o;
        gui::TestHookOptions hooks;
        std::vector<std::string> firmware;  // --firmware, added to the positional ones
        std::string motor = "physical";
        std::string board = "alp85";
        std::string speed = "1";
        std::string serial;
        long frames = 0;
        double seconds = 0;
    };
    auto args = std::make_shared<Args>();
    std::vector<std::string> outputs;
    CLI::App* cmd = app.add_subcommand("gui", "The ALP 85 and its machine tool in a window, run from the keypad");
    cmd->add_option("firmware", args->o.firmware,
                    "Built-in firmware (thesis, thesis-fixed, master, monitor) or .asm/.hex files, loaded after the monitor "
                    "(default: thesis-fixed)");
    cmd->add_option("--firmware", args->firmware,
                    "Firmware to load, named as the positional arguments are (a built-in name or a file); may be repeated");
    cmd->add_option("--script", args->o.script, "Run this script (docs/scripting.md) in the window first");
    // The test hooks (tests/gui) are in no group, so --help, the man page and completion, all made
    // from --help, do not offer them; they work all the same.
    cmd->add_option("--click", args->hooks.clicks,
                    "Then click these keypad buttons (R, 0-F, EXEC, NEXT, ..., RESET, VECT) with synthesized mouse "
                    "events (a test hook)")
        ->group("");
    CLI::Option* debug = cmd->add_flag("--debug", args->o.debug,
                  "The debugger's panes (source, registers, disassembly, memory, chips, watches, steps and reverse "
                  "steps, the command line: docs/debugging.md) in place of the machine tool's views");
    cmd->add_option("--click-line", args->hooks.click_lines,
                    "With --debug: then click the source rows of these FILE:LINE (sets breakpoints; a test hook)")
        ->needs(debug)
        ->group("");
    cmd->add_option("--debug-command", args->hooks.debug_commands,
                    "Then run these debugger command lines, or click:BUTTON, frames:N, status, toolpath (a test hook)")
        ->group("");
    add_output_option(cmd, outputs, "--screenshot", args->o.screenshot,
                      "Save the window as PNG when the script and the clicks are done, then quit");
    cmd->add_option("--expect-display", args->o.expect_display, "At exit the display must read this (else status 1)");
    cmd->add_option("--frames", args->frames, "Quit after this many frames")->check(CLI::PositiveNumber);
    cmd->add_option("--seconds", args->seconds, "Quit after this many seconds")->check(CLI::PositiveNumber);
    cmd->add_option("--scale", args->o.scale,
                    "The window's first size as a multiple of 1280x800 (2 on a HiDPI screen); default: as large as the "
                    "screen allows, at most 1 (the window can be resized)")
        ->check(CLI::Range(0.25, 4.0));
    cmd->add_flag("--key-map", args->o.key_map, "Show the key map (F1 or ? toggles it)");
    cmd->add_option("--signals", args->o.signals,
                    "Open the Signals pane (a logic analyzer: docs/signals.md) on these pins, named as record signals "
                    "names them: PA0, 8155.PA0, X.PULSE, or a whole part (8155, X)");
    cmd->add_option("--signals-ms", args->o.signals_ms, "The Signals pane shows the last this many ms of machine time (1 to 1000)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_flag("--stats", args->o.stats, "Print frames per second and the process's CPU use at exit");
    cmd->add_option("--speed", args->speed,
                    "0.1, 1 (real time), 10, 100 or max; a --script runs at it too, so that its moves are seen (max to hurry)")
        ->check(CLI::IsMember({"0.1", "1", "10", "100", "max"}))
        ->capture_default_str();
    add_motor_option(cmd, args->motor);
    add_board_option(cmd, args->board);
    add_rom_option(cmd, args->o.rom);
    cmd->add_option("--serial", args->serial,
                    "A serial terminal on SID/SOD at BAUD[,FRAME] (as alp85 run --serial: 9600, 1200,7E1) and its Terminal "
                    "pane: what SOD sends is shown, what is typed there goes to SID");
    cmd->add_option("--out-dir", args->o.out_dir, "Folder for the files the script writes (as alp85 script --out-dir); created if missing");
    cmd->footer(
        "Examples:\n"
        "  alp85 gui                       the monitor and thesis-fixed; type R 7 0800 EXEC\n"
        "  alp85 gui --script scripts/demo/thesis.alp                 the walk-through at real time\n"
        "  alp85 gui --script scripts/demo/thesis.alp --speed max --screenshot gui.png\n"
        "  alp85 gui firmware/demo/echo85.asm --serial 9600   type R 7 0800 EXEC, then type in the Terminal pane\n"
        "  alp85 gui --signals PA0 PA1 X.A X.B --signals-ms 20   port A and a sequencer on a logic analyzer\n"
        "  alp85 gui --board sdk85 --rom build/firmware/sdk85/sdk85test.hex   Intel's SDK-85 with a ROM of yours\n"
        "Without a display it exits with status 2; use `alp85 run` or `alp85 script` there.\n"
        "Exit status: 0, 1 the script or --expect-display failed or the screenshot cannot be written,\n"
        "2 a usage error (a bad number or --serial rate, a --screenshot that is an input) or no display; SIGTERM or\n"
        "Ctrl-C close the window within a second whatever it is doing: 128 + the signal (143, 130).");
    on_run(cmd, status, outputs, [args] {
        // CLI11's range checks let NaN through (every comparison with it is false): a --seconds
        // of NaN never ends the window.
        if (!std::isfinite(args->seconds) || !std::isfinite(args->o.scale)) {
            const bool seconds = !std::isfinite(args->seconds);
            std::cerr << argument_error("alp85 gui", seconds ? fmt::format("{}", args->seconds) : fmt::format("{}", args->o.scale),
                                        fmt::format("{} needs a finite number", seconds ? "--seconds" : "--scale"));
            return kUsageError;
        }
        if (!args->serial.empty()) {
            std::string why;
            args->o.serial = periph::parse_uart_format(args->serial, why);
            if (!args->o.serial) {
                std::cerr << argument_error("alp85 gui", args->serial, why + " in --serial");
                return kUsageError;
            }
        }
        for (const std::string& spec : args->hooks.click_lines)
            if (const std::string why = click_line_problem(spec, args->o.debug); !why.empty()) {
                std::cerr << argument_error("alp85 gui", spec, "--click-line " + spec + ": " + why);
                return kUsageError;
            }
        // Pins the board does not have: refused before a window opens.
        if (const std::string why = debug::PinTap::check_selection(Machine{}, args->o.signals); !why.empty()) {
            std::cerr << "alp85 gui: --signals: " << why << '\n';
            return kUsageError;
        }
        args->o.firmware.insert(args->o.firmware.begin(), args->firmware.begin(), args->firmware.end());
        std::vector<NamedPath> inputs = {{args->o.script, "the script"}};
        for (const std::string& f : args->o.firmware)  // a file, not a built-in name
            if (std::error_code ec; std::filesystem::exists(f, ec)) inputs.push_back({f, "the firmware source"});
        if (!args->o.rom.empty()) inputs.push_back({args->o.rom, "the ROM (--rom)"});
        if (refuse_output_clash("gui", inputs, {{args->o.screenshot, "--screenshot"}})) {
            return kUsageError;
        }
        if (!args->o.screenshot.empty()) {  // found out now, not after the whole script has run
            const std::filesystem::path dir = std::filesystem::absolute(args->o.screenshot).parent_path();
            std::error_code ec;
            if (!std::filesystem::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0 ||
                std::filesystem::is_directory(args->o.screenshot, ec)) {
                std::cerr << "alp85 gui: cannot write the screenshot '" << args->o.screenshot << "'\n";
                return 1;
            }
        }
        args->o.motor = motor_model_of(args->motor);
        args->o.board = args->board;
        if (!args->o.rom.empty()) {  // refused before a window opens, by the loader every --rom goes through
            if (board_of(args->board)->builtin_firmware) {
                std::cerr << argument_error("alp85 gui", args->o.rom,
                                            "--rom is for --board sdk85 (the ALP 85's monitor is built in; a program of "
                                            "yours goes in as a positional argument)");
                return kUsageError;
            }
            script::SessionOptions so;
            so.board = board_of(args->board);
            if (const std::string why = script::Session(so).check_rom(args->o.rom); !why.empty()) {
                std::cerr << "alp85 gui: --rom: " << why << '\n';
                return kUsageError;
            }
        }
        if (!args->o.out_dir.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(args->o.out_dir, ec);
            if (ec) {
                std::cerr << "alp85 gui: --out-dir " << args->o.out_dir << ": " << ec.message() << '\n';
                return 2;
            }
        }
        const std::string s = args->speed;
        args->o.speed = s == "0.1" ? 0 : s == "1" ? 1 : s == "10" ? 2 : s == "100" ? 3 : 4;
        if (args->frames > 0) args->o.frames = args->frames;
        if (args->seconds > 0) args->o.seconds = args->seconds;
        if (args->hooks.empty()) return gui::run(args->o);
        gui::TestHooks hooks(args->hooks);  // only when a test asked for them
        return gui::run(args->o, &hooks);
    });
}

}  // namespace alp85::cli
