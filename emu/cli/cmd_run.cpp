// alp85 run [PROGRAM...] [--keys "R 7 0800 EXEC"] [--boot TIME] [--for TIME] [--no-monitor] [--vcd FILE]
// [--serial BAUD[,FRAME] [--serial-gap TIME]]: the board, headless. It boots the monitor, shows the
// display after RESET, types the keys, runs, and shows the display again. With --serial a terminal
// sits on SID/SOD: standard input is sent to SID after the keys, what SOD sends is written to
// standard output as it is decoded, and the rest of the report goes to standard error. A client of the
// Session's typed API, like every front end: the arguments are checked first with the command
// language's parsing and the Session's checks (no script text is made, so a path may hold any
// character; a report points at the argument on the command line), then become typed calls.
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "emu/cli/commands.h"
#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/script/session.h"

namespace alp85::cli {
namespace {

using script::ParseError;

ParseError argument_error(std::string_view argument, int offset, std::string message) {
    return {{"alp85 run", 1, column_of(argument) + offset}, std::move(message), command_line()};
}

// A problem with `text`, found where it first stands on the command line (a path as part of
// FILE.bin@ADDR), else at `argument`.
ParseError error_at(const std::string& text, std::string_view argument, std::string message) {
    const auto p = command_line().find(text);
    const int col = p != std::string::npos ? static_cast<int>(p) + 1 : argument.empty() ? 1 : column_of(argument);
    return {{"alp85 run", 1, col}, std::move(message), command_line()};
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

// A program to load: FILE, or FILE.bin@ADDR with the address as the script writes one.
struct Program {
    std::string argument, path;
    std::optional<script::Value> address;
};

// A typed call that failed: the command line as the place, what went wrong, the machine's state
// (the form of a failed script line).
std::string failure(const script::Session& session, const std::string& what) {
    std::string line = command_line();
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return fmt::format("alp85 run:1: {}\n  {}\n  {}", line, what, session.where_now());
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
        std::string board = "alp85", rom;
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
    add_board_option(cmd, args->board);
    add_rom_option(cmd, args->rom);
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
        "  alp85 run --board sdk85 --rom sdk85.bin --keys \"MEM 2 0 0 0 NEXT\"   # Intel's SDK-85 with your ROM copy\n"
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
        so.board = board_of(args->board);
        // The built-in monitor is the ALP 85's; another board's ROM is the user's (--rom).
        if (!so.board->builtin_firmware) args->no_monitor = true;
        if (!args->rom.empty() && so.board->builtin_firmware)
            errors.push_back(argument_error(args->rom, 0, "--rom is for --board sdk85 (the ALP 85's monitor is built in; a program "
                                                          "of yours goes in as a positional argument)"));
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
        if (!args->no_monitor && !firmware::have_monitor()) {
            std::cerr << "alp85 run: this alp85 was built without the monitor ROM (use --no-monitor)\n";
            return 2;
        }
        // The arguments first, every bad one reported: addresses, times, keys.
        std::vector<Program> programs;
        for (const std::string& p : args->programs) {
            const auto at = p.rfind('@');
            Program program{p, p.substr(0, at), {}};
            if (at != std::string::npos) {
                std::string why;
                int col = 1;
                auto v = script::parse_value(std::string_view(p).substr(at + 1), "an address", true, why, col);
                if (!v) {
                    errors.push_back(argument_error(p, static_cast<int>(at) + col, why));
                    continue;
                }
                v->col = column_of(p) + static_cast<int>(at) + 1;
                program.address = std::move(*v);
            }
            programs.push_back(std::move(program));
        }
        const auto boot_time = time_argument(args->boot, "--boot", errors);
        std::optional<std::uint64_t> run_time;
        std::vector<script::KeyRef> keys;
        if (args->keys.empty() && line) run_time = time_argument(args->run_for, "--for", errors);
        if (!args->keys.empty()) {
            keys = expand_keys(args->keys, errors);
            for (const script::KeyRef& k : keys)
                if (std::string why = session.check_key(k); !why.empty()) errors.push_back(argument_error(args->keys, 0, why + " in --keys"));
            run_time = time_argument(args->run_for, "--for", errors);
        }
        // Then what the Session checks before anything runs, in the order the board is put
        // together: the programs (readable, assembled, on the board, their address's symbols
        // defined by what loads before them), the pins, and the recording's file.
        if (errors.empty()) {
            std::set<std::string> known;
            if (!args->rom.empty())  // the ROM loader's reasons (docs/sdk85.md): missing, short, not a ROM image
                if (std::string why = session.check_rom(args->rom); !why.empty())
                    errors.push_back(argument_error(args->rom, 0, "--rom: " + why));
            if (!args->no_monitor)
                if (std::string why = session.check_monitor(known); !why.empty())
                    errors.push_back(error_at("", "", std::move(why)));
            for (const std::string& f : args->firmware)
                if (std::string why = session.check_firmware(f, known); !why.empty())
                    errors.push_back(error_at(f, f, std::move(why)));
            for (const Program& p : programs) {
                if (std::string why = session.check_program(p.path, p.address.has_value()); !why.empty()) {
                    errors.push_back(error_at(p.path, p.argument, std::move(why)));
                    continue;
                }
                if (p.address)
                    for (auto& [col, why] : session.check_value(*p.address, 0, 0xFFFF, "address", known))
                        errors.push_back({{"alp85 run", 1, col}, std::move(why), command_line()});
                if (std::string why = session.check_image(p.path, p.address, known); !why.empty())
                    errors.push_back(error_at(p.path, p.argument, std::move(why)));
            }
            if (!args->vcd.empty())
                for (const std::string& pin : args->pins)
                    if (std::string why = session.check_pin(pin); !why.empty())
                        errors.push_back({{"alp85 run", 1, column_of(pin)}, std::move(why), command_line()});
            for (const Program& p : programs) session.add_input(p.path, "a program the script loads");
            if (!args->vcd.empty())
                if (std::string why = session.output_problem(args->vcd, "record"); !why.empty())
                    errors.push_back(error_at(args->vcd, args->vcd, std::move(why)));
        }
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
        // The board put together, reset and run, each step a typed call; the first that fails ends it.
        using Outcome = script::Session::Outcome;
        auto show = [&](const std::string& when) {
            session.print(when);
            if (!args->text) session.print_display(false);
            session.print_display(true);
        };
        // The run after the keys (or after the boot, with no keys): the terminal starts sending
        // first, and the run lasts until the last character's stop bits are out, then --for.
        auto run_after = [&]() -> Outcome {
            std::uint64_t t = *run_time;
            if (line && !input.empty()) {
                const std::uint64_t n = input.size();
                t += n * line->frame_tstates(board::kCpuHz) + (n - 1) * gap;
                session.serial_type(input);
            }
            return session.run(t);
        };
        const auto steps = std::vector<std::function<Outcome()>>{
            [&] { return args->no_monitor ? Outcome{} : session.load_monitor(); },
            [&] { return args->rom.empty() ? Outcome{} : session.load_rom(args->rom); },
            [&] {
                for (const std::string& f : args->firmware)
                    if (Outcome o = session.load_firmware(f); o.status != script::Session::Status::Ok) return o;
                return Outcome{};
            },
            [&] {
                for (const Program& p : programs) {
                    std::optional<std::uint16_t> at;
                    if (p.address) {
                        std::string why;
                        const auto v = session.value(*p.address, why);
                        if (!v) return Outcome{script::Session::Status::Failed, why};
                        at = static_cast<std::uint16_t>(*v);
                    }
                    if (Outcome o = session.load_image(p.path, at); o.status != script::Session::Status::Ok) return o;
                }
                return Outcome{};
            },
            [&] { return args->vcd.empty() ? Outcome{} : session.record_signals(args->vcd, args->pins); },
            [&] { return session.reset(); },
            [&] { return session.run(*boot_time); },
            [&] {
                show("after RESET:");
                if (!args->keys.empty() || !line) return Outcome{};
                const Outcome o = run_after();
                if (o.status == script::Session::Status::Ok) show("after the serial input:");
                return o;
            },
            [&] {
                if (args->keys.empty()) return Outcome{};
                if (Outcome o = session.type(keys); o.status != script::Session::Status::Ok) return o;
                const Outcome o = run_after();
                if (o.status == script::Session::Status::Ok) show(fmt::format("after {}:", args->keys));
                return o;
            },
            [&] { return args->vcd.empty() ? Outcome{} : session.record_stop(); },
        };
        for (const auto& step : steps)
            if (const Outcome o = step(); o.status != script::Session::Status::Ok) {
                std::cerr << failure(session, o.message) << '\n';
                return 1;
            }
        report << fmt::format("{} simulated, PC={:04X}H\n", script::Session::format_time(session.now()),
                              session.reg(*cpu::description().find("PC")));
        // Where the machine tool's tables are, after the display (a board with one).
        if (!session.board().tool.empty()) session.print_axes();
        return 0;
    });
}

}  // namespace alp85::cli
