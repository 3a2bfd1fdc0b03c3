// alp85 run [PROGRAM...] [--keys "R 7 0800 EXEC"] [--boot TIME] [--for TIME] [--no-monitor] [--vcd FILE]
// [--serial BAUD[,FRAME] [--serial-gap TIME]]: the board, headless. It boots the monitor, shows the
// display after RESET, types the keys, runs, and shows the display again. With --serial a terminal
// sits on SID/SOD: standard input is sent to SID after the keys, what SOD sends is written to
// standard output as it is decoded, and the rest of the report goes to standard error. Built on the command language's Session, like every front end:
// the arguments become Commands directly (no script text is made, so a path may hold any
// character), and a report points at the argument on the command line.
#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "emu/cli/commands.h"
#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/script/session.h"

namespace alp85::cli {
namespace {

using script::Command;
using script::Op;
using script::ParseError;

// A command that stands for `argument` on the command line.
Command command(Op op, std::string_view argument = {}) {
    Command c;
    c.op = op;
    c.where = {"alp85 run", 1, argument.empty() ? 1 : column_of(argument)};
    c.line = command_line();
    return c;
}

ParseError argument_error(std::string_view argument, int offset, std::string message) {
    return {{"alp85 run", 1, column_of(argument) + offset}, std::move(message), command_line()};
}

// "R 7 0800 EXEC" -> R 7 0 8 0 0 EXEC (script::parse_key_list), a bad word pointed at.
std::vector<script::KeyRef> expand_keys(const std::string& text, std::vector<ParseError>& errors) {
    std::string why;
    std::size_t at = 0;
    auto keys = script::parse_key_list(text, why, at);
    if (!keys) {
        errors.push_back(argument_error(text, static_cast<int>(at), why + " in --keys"));
        return {};
    }
    return *keys;
}

std::optional<std::uint64_t> time_argument(const std::string& text, const char* option, std::vector<ParseError>& errors) {
    const auto t = script::parse_time(text);
    if (!t)
        errors.push_back(argument_error(text, 0, fmt::format("bad time '{}' in {} (a number with a unit: t, us, ms or s)",
                                                             text, option)));
    return t;
}

void add_display(std::vector<Command>& commands, bool text_only) {
    if (!text_only) commands.push_back(command(Op::PrintDisplay));
    Command c = command(Op::PrintDisplay);
    c.text = "text";
    commands.push_back(std::move(c));
}

void add_print(std::vector<Command>& commands, std::string text) {
    Command c = command(Op::Print);
    c.text = std::move(text);
    commands.push_back(std::move(c));
}

constexpr std::size_t kSerialInputCap = 1 << 20;  // 1 MiB

// A character the terminal took with an error: a line on standard error, the text stays clean.
void report_serial_error(const periph::UartChar& c) {
    const char* what = c.is_break() ? "break (SOD held at space through the stop bit)"
                       : c.error == periph::UartChar::Error::Framing ? "framing error (stop bit low)"
                                                                      : "parity error";
    std::cerr << fmt::format("alp85 run: serial: {} at {}, character {:02X}H as sampled\n", what,
                             script::Session::format_time(c.at), c.value);
}

}  // namespace

void add_run_command(CLI::App& app, int& status) {
    struct Args {
        std::vector<std::string> programs, firmware;
        std::string keys, boot = "500ms", run_for = "1s", motor = "physical", vcd, serial, serial_gap;
        std::vector<std::string> pins;
        bool no_monitor = false, text = false;
    };
    auto args = std::make_shared<Args>();
    std::vector<std::string> outputs;
    CLI::App* cmd = app.add_subcommand("run", "Run the ALP 85 headless: boot the monitor, type keys, show the display");
    cmd->add_option("programs", args->programs,
                    "Programs to load first (.asm, .hex; FILE.bin@ADDR, e.g. x.bin@0800H) or built-in firmware by name, "
                    "as with --firmware");
    cmd->add_option("--keys", args->keys, "Keys to type after booting, e.g. \"R 7 0800 EXEC\"");
    cmd->add_option("--boot", args->boot, "Time to run after RESET before typing (default 500ms)");
    auto* run_for = cmd->add_option("--for", args->run_for,
                                    "Time to run after the keys, and after the last character --serial sends (default 1s)");
    cmd->add_flag("--no-monitor", args->no_monitor, "Do not load the built-in monitor ROM");
    cmd->add_option("--firmware", args->firmware,
                    "Firmware built into alp85 to load (thesis, thesis-fixed, master), with its symbols, or a program "
                    "file as the positional arguments take it; may be repeated");
    add_motor_option(cmd, args->motor);
    cmd->add_flag("--text", args->text, "Show the display as text only (no seven-segment art)");
    auto* vcd = add_output_option(cmd, outputs, "--vcd", args->vcd,
                                  "Record the board's pins from RESET to the end as a VCD file (GTKWave, PulseView; "
                                  "docs/signals.md)");
    cmd->add_option("--pins", args->pins, "The pins --vcd records (default all), e.g. --pins PA0 X.PULSE 8279")
        ->needs(vcd);
    auto* serial = cmd->add_option(
        "--serial", args->serial,
        "A serial terminal on SID/SOD at BAUD[,FRAME] (50-115200; FRAME data bits 5-8, parity N/E/O, stop bits 1-2; "
        "default 8N1): standard input, read to its end first, is sent to SID after the keys; SOD's characters go to "
        "standard output as they come, the display and the rest of the report to standard error");
    cmd->add_option("--serial-gap", args->serial_gap,
                    "Idle line between the characters --serial sends (default one character's time, so a program "
                    "that echoes each one before listening again keeps up; 0t: back to back)")
        ->needs(serial);
    cmd->footer(
        "Addresses are read as in scripts: 0800H or 0x800 is hex, 2048 decimal; a bare number with a\n"
        "leading zero (0800) is refused as ambiguous.\n"
        "Examples:\n"
        "  alp85 run                                          # the monitor's sign-on\n"
        "  alp85 run firmware/demo/hello85.asm --keys \"R 7 0800 EXEC\"\n"
        "  alp85 run --firmware thesis-fixed --keys \"R 7 0800 EXEC 0012\"   # the thesis's Z prompt, Z = 12\n"
        "  alp85 run --firmware thesis-fixed --keys \"R 7 0800 EXEC\" --vcd pins.vcd --pins 8155 8279\n"
        "  echo hello | alp85 run firmware/demo/echo85.asm --keys \"R 7 0800 EXEC\" --serial 9600   # prints hello\n"
        "Exit status: 0 success, 1 a program could not be placed or run, 2 a usage error or a bad\n"
        "argument (a program that is missing or does not assemble, a bad time, key, baud rate or frame).\n"
        "A character --serial receives with a framing or parity error is reported on standard error, not\n"
        "written to standard output; the status stays 0.");
    on_run(cmd, status, outputs, [args, run_for] {
        if (run_for->count() && args->keys.empty() && args->serial.empty()) {
            std::cerr << "alp85 run: --for requires --keys or --serial\n";
            return kUsageError;
        }
        // One way to name firmware, as in gui, debug and dap: a built-in name among the programs
        // loads that firmware, a file given to --firmware loads as a program.
        std::vector<std::string> builtins, files;
        for (const std::string& f : args->firmware) (firmware::find(f) || !std::filesystem::exists(f) ? builtins : files).push_back(f);
        for (const std::string& p : args->programs) (firmware::find(p) ? builtins : files).push_back(p);
        args->firmware = std::move(builtins);
        args->programs = std::move(files);
        std::vector<ParseError> errors;
        std::optional<periph::UartFormat> line;
        std::uint64_t gap = 0;
        if (!args->serial.empty()) {
            std::string why;
            line = periph::parse_uart_format(args->serial, why);
            if (!line) errors.push_back(argument_error(args->serial, 0, why + " in --serial"));
            if (line) gap = line->frame_tstates(board::kCpuHz);
            if (!args->serial_gap.empty())
                if (const auto t = time_argument(args->serial_gap, "--serial-gap", errors)) gap = *t;
        }
        // With a serial line standard output is the line's; the report goes beside it.
        std::ostream& report = line ? std::cerr : std::cout;
        script::SessionOptions so;
        so.base_dir = "";  // paths as the user typed them
        so.out = &report;
        if (firmware::have_monitor()) so.monitor_rom = firmware::monitor;
        script::Session session(so);
        session.set_motor(motor_model_of(args->motor));
        if (line) {
            session.connect_serial(*line, gap);
            session.serial()->on_receive([](const periph::UartChar& c) {
                if (c.error != periph::UartChar::Error::None) return report_serial_error(c);
                std::cout.put(static_cast<char>(c.value));
                std::cout.flush();
            });
        }
        std::vector<Command> commands;
        if (!args->no_monitor) {
            if (!firmware::have_monitor()) {
                std::cerr << "alp85 run: this alp85 was built without the monitor ROM (use --no-monitor)\n";
                return 2;
            }
            commands.push_back(command(Op::Monitor));
        }
        for (const std::string& f : args->firmware) {
            Command c = command(Op::Firmware, f);
            c.text = f;
            commands.push_back(std::move(c));
        }
        for (const std::string& p : args->programs) {
            Command c = command(Op::Load, p);
            const auto at = p.rfind('@');
            c.text = p.substr(0, at);
            if (at != std::string::npos) {
                std::string why;
                int col = 1;
                auto v = script::parse_value(std::string_view(p).substr(at + 1), "an address", true, why, col);
                if (!v) {
                    errors.push_back(argument_error(p, static_cast<int>(at) + col, why));
                    continue;
                }
                v->col = column_of(p) + static_cast<int>(at) + 1;
                c.address = std::move(*v);
            }
            commands.push_back(std::move(c));
        }
        if (!args->vcd.empty()) {
            Command record = command(Op::Record, args->vcd);
            record.signals = true;
            record.text = args->vcd;
            record.period = script::kDefaultSignalPeriod;
            for (const std::string& p : args->pins) record.pins.push_back({{}, 0, column_of(p), p});
            commands.push_back(std::move(record));
        }
        commands.push_back(command(Op::Reset));
        Command boot = command(Op::Run, args->boot);
        if (const auto t = time_argument(args->boot, "--boot", errors)) boot.time = *t;
        commands.push_back(std::move(boot));
        add_print(commands, "after RESET:");
        add_display(commands, args->text);
        // The terminal starts sending before this command: after the keys, or after the boot.
        std::size_t send_before = commands.size();
        if (args->keys.empty() && line) {
            Command run = command(Op::Run, args->run_for);
            if (const auto t = time_argument(args->run_for, "--for", errors)) run.time = *t;
            commands.push_back(std::move(run));
            add_print(commands, "after the serial input:");
            add_display(commands, args->text);
        }
        if (!args->keys.empty()) {
            Command type = command(Op::Type, args->keys);
            type.keys = expand_keys(args->keys, errors);
            type.time = script::kDefaultHold;
            type.gap = script::kDefaultGap;
            commands.push_back(std::move(type));
            send_before = commands.size();
            Command run = command(Op::Run, args->run_for);
            if (const auto t = time_argument(args->run_for, "--for", errors)) run.time = *t;
            commands.push_back(std::move(run));
            add_print(commands, fmt::format("after {}:", args->keys));
            add_display(commands, args->text);
        }
        if (errors.empty()) session.check(commands, errors);
        for (const std::string& w : session.warnings()) std::cerr << w;
        if (!errors.empty()) {
            for (const auto& e : errors) std::cerr << e.format();
            return 2;
        }
        // Standard input is read to its end before the run, so the run is the same for a pipe, a
        // file or a terminal (Ctrl-D ends it there): only its bytes decide, never when they came.
        // At most kSerialInputCap bytes (36 minutes of machine time at 9600 baud with a character's
        // gap after each): /dev/zero is refused, not read for ever.
        std::string input;
        if (line) {
            input.resize(kSerialInputCap + 1);
            std::cin.read(input.data(), static_cast<std::streamsize>(input.size()));
            input.resize(static_cast<std::size_t>(std::cin.gcount()));
            if (input.size() > kSerialInputCap) {
                std::cerr << fmt::format("alp85 run: standard input is larger than {} bytes, the most --serial sends\n",
                                         kSerialInputCap);
                return kUsageError;
            }
        }
        for (std::size_t i = 0; i < commands.size(); ++i) {
            Command c = commands[i];
            if (line && i == send_before && !input.empty()) {
                // The run after the keys lasts until the last character's stop bits are out, then --for.
                const std::uint64_t n = input.size();
                c.time += n * line->frame_tstates(board::kCpuHz) + (n - 1) * gap;
                session.serial_type(input);
            }
            const auto o = session.execute(c);
            if (o.status != script::Session::Status::Ok) {
                std::cerr << o.message << '\n';
                return 1;
            }
        }
        if (!args->vcd.empty())
            if (const auto o = session.execute(command(Op::RecordStop)); o.status != script::Session::Status::Ok) {
                std::cerr << o.message << '\n';
                return 1;
            }
        report << fmt::format("{} simulated, PC={:04X}H\n", script::Session::format_time(session.now()),
                              session.machine().cpu().regs().pc);
        // Where the machine tool's tables are, after the display.
        if (const auto o = session.execute(command(Op::PrintAxes)); o.status != script::Session::Status::Ok) {
            std::cerr << o.message << '\n';
            return 1;
        }
        return 0;
    });
}

}  // namespace alp85::cli
