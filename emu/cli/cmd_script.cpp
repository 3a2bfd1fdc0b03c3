// alp85 script FILE... [-j N] [--junit OUT.xml] [--trace OUT.csv] [-v]: headless firmware tests
// (docs/scripting.md). Exit status: 0 all passed, 1 an expectation failed (or --max-time was
// reached), 2 a script error.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "asm/files/atomic_file.h"
#include "emu/util/input_file.h"
#include "emu/cli/commands.h"
#include "emu/program/firmware.h"
#include "emu/script/runner.h"

namespace alp85::cli {
namespace {

// The thesis and master firmware call the monitor's routines and are entered through its RST
// vectors: loaded alone, the CPU runs into empty EPROM and the display stays blank. A script that
// forgets `monitor` gets told so before it times out.
void warn_firmware_without_monitor(const std::vector<script::Command>& program) {
    bool monitor = false;
    for (const script::Command& c : program) {
        if (c.op == script::Op::Monitor || (c.op == script::Op::Firmware && c.text == "monitor")) monitor = true;
        if (c.op != script::Op::Firmware || c.text == "monitor" || monitor) continue;
        std::cerr << fmt::format("{}:{}:{}: warning: firmware {} calls the monitor's routines (display, keypad, RST "
                                 "vectors): put `monitor` before it, or the CPU runs into empty EPROM at RESET\n",
                                 c.where.file, c.where.line, c.where.col, c.text);
        return;
    }
}

}  // namespace

void add_script_command(CLI::App& app, int& status) {
    struct Args {
        std::vector<std::string> files;
        std::string junit, trace;
        bool verbose = false;
        std::string out_dir;
        std::string motor = "physical";
        std::string board = "alp85";
        std::string max_time = "1h";
        unsigned jobs = 1;
    };
    auto args = std::make_shared<Args>();
    std::vector<std::string> outputs;
    CLI::App* cmd = app.add_subcommand("script", "Run headless test scripts against the ALP 85 (docs/scripting.md)");
    cmd->add_option("files", args->files, "Script files (.alp)")->required();  // a missing one: runner::prepare
    add_output_option(cmd, outputs, "--junit", args->junit, "Write a JUnit XML report");
    add_output_option(cmd, outputs, "--trace", args->trace, "Write every executed instruction as CSV");
    cmd->add_flag("-v,--verbose", args->verbose, "Echo each command with the simulated time");
    add_motor_option(cmd, args->motor);
    add_board_option(cmd, args->board);
    add_max_time_option(cmd, args->max_time);
    cmd->add_option("-j,--jobs", args->jobs,
                    "Run up to N scripts at once (default 1); the output stays grouped per script, in file order")
        ->check(CLI::Range(1u, 1024u))
        ->option_text("N");
    cmd->add_option("--out-dir", args->out_dir,
                    "Folder for the files scripts write and read back (save, restore, record, plot); "
                    "created if missing. Default: each script's own folder, or the current folder when that one cannot "
                    "be written (a note says so)");
    cmd->footer(
        "Examples:\n"
        "  alp85 script scripts/monitor/*.alp\n"
        "  alp85 script test.alp --junit report.xml -v\n"
        "  alp85 script -j 2 scripts/*/*.alp --junit report.xml\n"
        "Exit status: 0 every script passed, 1 an expectation failed or an output (--trace, --junit)\n"
        "could not be written or a script's run reached --max-time, 2 a usage or script error (a script\n"
        "that is missing or a directory, an output that is a script, an included script, a file it\n"
        "loads or restores, or an empty name; --trace and --junit on one file; a save, record or plot\n"
        "onto any of those): then nothing runs.");
    on_run(cmd, status, outputs, [args] {
        script::RunnerOptions o;
        if (firmware::have_monitor()) o.monitor_rom = firmware::monitor;
        o.out = &std::cout;
        o.err = &std::cerr;
        o.verbose = args->verbose;
        o.motor = motor_model_of(args->motor);
        o.board = board_of(args->board);
        const auto max_time = max_time_of("alp85 script", args->max_time);
        if (!max_time) {
            return 2;
        }
        o.max_time = *max_time;
        if (!args->out_dir.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(args->out_dir, ec);
            if (ec) {
                std::cerr << fmt::format("alp85 script: --out-dir {}: {}\n", args->out_dir, ec.message());
                return 2;
            }
            o.out_dir = args->out_dir;
        }
        for (const std::string& f : args->files)  // a missing one: prepare() says so, with the others
            if (const std::string why = input_problem(f); !why.empty() && why.rfind("no such file", 0) != 0) {
                std::cerr << fmt::format("alp85 script: {}; nothing was run\n", why);
                return 2;
            }
        o.outputs = {{args->trace, "--trace"}, {args->junit, "--junit"}};
        // Every script is checked before any runs: a script error stops everything (status 2).
        std::vector<std::vector<script::Command>> programs(args->files.size());
        std::vector<script::ParseError> errors;
        std::vector<NamedPath> inputs;  // every file any script reads: no output may be one
        for (std::size_t i = 0; i < args->files.size(); ++i) {
            std::vector<NamedPath> read;
            script::prepare(args->files[i], programs[i], errors, o, &read);
            inputs.push_back({args->files[i], "the script"});
            inputs.insert(inputs.end(), read.begin(), read.end());
        }
        if (refuse_output_clash("script", inputs, o.outputs)) {
            return 2;
        }
        for (std::size_t i = 0; i < args->files.size(); ++i) warn_firmware_without_monitor(programs[i]);
        if (!errors.empty()) {
            for (const auto& e : errors) std::cerr << e.format();
            std::cerr << fmt::format("alp85 script: {} error(s); nothing was run\n", errors.size());
            return 2;
        }
        // The trace appears whole when the run ends (passed or failed), or not at all.
        std::unique_ptr<AtomicOutput> trace;
        if (!args->trace.empty()) {
            try {
                trace = std::make_unique<AtomicOutput>(args->trace);
            } catch (const std::exception& e) {
                std::cerr << "alp85 script: trace: " << e.what() << '\n';
                return 1;
            }
            o.trace = &trace->stream();
        }
        int failed = 0;
        const std::vector<std::filesystem::path> files(args->files.begin(), args->files.end());
        const auto results = script::execute_all(files, programs, o, args->jobs, [&](const script::ScriptResult& r, const std::string& output) {
            std::cout << output;
            if (r.passed) {
                std::cout << fmt::format("PASS {} ({} commands, {} simulated, {:.3f} s)\n", r.file, r.commands,
                                         script::Session::format_time(r.tstates), r.seconds);
            } else {
                ++failed;
                std::cout << fmt::format("FAIL {}\n{}\n", r.file, r.failure);
            }
        });
        std::cout << fmt::format("{} passed, {} failed\n", results.size() - failed, failed);
        if (trace) {
            try {
                trace->commit();
            } catch (const std::exception& e) {
                std::cerr << "alp85 script: trace: " << e.what() << '\n';
                return 1;
            }
        }
        if (!args->junit.empty()) {
            try {
                write_atomic(args->junit, script::junit_xml(results));
            } catch (const std::exception& e) {
                std::cerr << "alp85 script: " << e.what() << '\n';
                return 1;
            }
        }
        return failed ? 1 : 0;
    });
}

}  // namespace alp85::cli
