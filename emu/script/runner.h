// Running script files: parse and check each completely, then execute it on a fresh machine.
// `alp85 script` is a thin CLI over this; tests call it directly.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "emu/script/session.h"

namespace alp85::script {

struct ScriptResult {
    std::string file;
    bool passed = false;
    std::string failure;       // the failed command's report (empty when passed)
    std::uint64_t tstates = 0; // simulated time the script took
    double seconds = 0;        // host time
    int commands = 0;          // commands executed
};

struct RunnerOptions {
    std::function<firmware::Firmware()> monitor_rom;
    std::ostream* out = nullptr;    // print output, -v echo, failure reports
    std::ostream* trace = nullptr;  // --trace CSV
    std::ostream* err = nullptr;    // warnings of loaded sources (asm85's, file:line:col)
    bool verbose = false;
    // --out-dir: where save, restore, record and plot files go. Empty: the script's folder, or the
    // current folder when the script writes files and its folder takes none (prepare() notes it on err).
    std::filesystem::path out_dir;
    periph::MachineTool::MotorModel motor = periph::MachineTool::MotorModel::Physical;  // --motor, until `motor`
    // The command line's outputs (--trace, --junit): no save, record or plot may write one.
    std::vector<NamedPath> outputs;
    std::uint64_t max_time = SessionOptions::kDefaultMaxTime;  // --max-time: each script's machine time at most
    const board::Board* board = &board::kAlp85;  // --board, unless the script's first command is `board NAME`
};

// Parses and checks a file. Returns false and fills `errors` when the script cannot run.
// `inputs`, when given, gets every file the script reads: itself, its includes, the programs it
// loads, the snapshots it restores (not those it saved itself first).
bool prepare(const std::filesystem::path& file, std::vector<Command>& commands, std::vector<ParseError>& errors,
             const RunnerOptions& options, std::vector<NamedPath>* inputs = nullptr);

// Executes prepared commands on a fresh session; stops at the first failure.
ScriptResult execute(const std::filesystem::path& file, const std::vector<Command>& commands,
                     const RunnerOptions& options);

// Executes prepared scripts (`files[i]` with `programs[i]`), up to `jobs` at once, each on a session
// of its own. Scripts that name one file (save, restore, record, plot) run one after another, in
// file order, so that none reads or overwrites another's file half-written. With more than one
// job each script's output (print, -v echo, the debugger's events) and its trace are held until
// every script before it is reported; `report` gets the results in file order, each with its
// held output (empty with one job: the output went straight to options.out), and the trace is
// written in file order too. Returns the results in file order.
std::vector<ScriptResult> execute_all(const std::vector<std::filesystem::path>& files,
                                      const std::vector<std::vector<Command>>& programs, const RunnerOptions& options,
                                      unsigned jobs,
                                      const std::function<void(const ScriptResult&, const std::string& output)>& report);

// How execute_all() groups scripts: groups that share no file (save, restore, record, plot, as the
// sessions resolve them), each in file order, ordered by their first script.
std::vector<std::vector<std::size_t>> script_groups(const std::vector<std::filesystem::path>& files,
                                                    const std::vector<std::vector<Command>>& programs,
                                                    const RunnerOptions& options);

// JUnit XML for CI systems: one testsuite, one testcase per script.
std::string junit_xml(const std::vector<ScriptResult>& results);

}  // namespace alp85::script
