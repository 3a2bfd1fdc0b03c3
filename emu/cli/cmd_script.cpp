// alp85 script FILE... [-j N] [--junit OUT.xml] [--trace OUT.csv] [-v]: headless firmware tests
// (docs/scripting.md). Exit status: 0 all passed, 1 an expectation failed, 2 a script error.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "emu/util/atomic_file.h"
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
        unsigned jobs = 1;
    };
    auto args = std::make_shared<Args>();
    CLI::App* cmd = app.add_subcommand("script", "Run headless test scripts against the ALP 85 (docs/scripting.md)");
    cmd->add_option("files", args->files, "Script files (.alp)")->required();  // a missing one: runner::prepare
    cmd->add_option("--junit", args->junit, "Write a JUnit XML report");
    cmd->add_option("--trace", args->trace, "Write every executed instruction as CSV");
    cmd->add_flag("-v,--verbose", args->verbose, "Echo each command with the simulated time");
    add_motor_option(cmd, args->motor);
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
        "could not be written, 2 a usage or script error (a script that is missing or a directory, an\n"
        "output that is a script or a file it loads, --trace and --junit on one file): then nothing runs.");
    cmd->callback([args, &status] {
        script::RunnerOptions o;
        if (firmware::have_monitor()) o.monitor_rom = firmware::monitor;
        o.out = &std::cout;
        o.err = &std::cerr;
        o.verbose = args->verbose;
        o.motor = motor_model_of(args->motor);
        if (!args->out_dir.empty()) {
            std::error_code ec;
            std::filesystem::create_directories(args->out_dir, ec);
            if (ec) {
                std::cerr << fmt::format("alp85 script: --out-dir {}: {}\n", args->out_dir, ec.message());
                status = 2;
                return;
            }
            o.out_dir = args->out_dir;
        }
        for (const std::string& f : args->files)  // a missing one: prepare() says so, with the others
            if (std::filesystem::is_directory(f)) {
                std::cerr << fmt::format("alp85 script: {}; nothing was run\n", input_file_problem(f));
                status = 2;
                return;
            }
        // Every script is checked before any runs: a script error stops everything (status 2).
        std::vector<std::vector<script::Command>> programs(args->files.size());
        std::vector<script::ParseError> errors;
        for (std::size_t i = 0; i < args->files.size(); ++i) script::prepare(args->files[i], programs[i], errors, o);
        std::vector<NamedPath> inputs;
        for (std::size_t i = 0; i < args->files.size(); ++i) {
            inputs.push_back({args->files[i], "the script"});
            const std::filesystem::path dir = std::filesystem::path(args->files[i]).parent_path();
            for (const script::Command& c : programs[i])
                if (c.op == script::Op::Load && !c.text.empty())
                    inputs.push_back({(std::filesystem::path(c.text).is_absolute() ? std::filesystem::path(c.text) : dir / c.text).string(),
                                      "a program the script loads"});
        }
        if (refuse_output_clash("script", inputs, {{args->trace, "--trace"}, {args->junit, "--junit"}})) {
            status = 2;
            return;
        }
        for (std::size_t i = 0; i < args->files.size(); ++i) warn_firmware_without_monitor(programs[i]);
        if (!errors.empty()) {
            for (const auto& e : errors) std::cerr << e.format();
            std::cerr << fmt::format("alp85 script: {} error(s); nothing was run\n", errors.size());
            status = 2;
            return;
        }
        // The trace appears whole when the run ends (passed or failed), or not at all.
        std::unique_ptr<AtomicOutput> trace;
        if (!args->trace.empty()) {
            try {
                trace = std::make_unique<AtomicOutput>(args->trace);
            } catch (const std::exception& e) {
                std::cerr << "alp85 script: trace: " << e.what() << '\n';
                status = 1;
                return;
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
                status = 1;
                return;
            }
        }
        if (!args->junit.empty()) {
            try {
                write_atomic(args->junit, script::junit_xml(results));
            } catch (const std::exception& e) {
                std::cerr << "alp85 script: " << e.what() << '\n';
                status = 1;
                return;
            }
        }
        status = failed ? 1 : 0;
    });
}

}  // namespace alp85::cli
