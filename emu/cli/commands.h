// The alp85 subcommands; each lives in its own file (cmd_*.cpp) and registers itself on the app.
#pragma once

#include <CLI/CLI.hpp>

namespace alp85::cli {

// The exit status of every usage error (an unknown option, a missing or malformed argument).
inline constexpr int kUsageError = 2;

// Each add_* registers a subcommand whose callback stores the process exit status in `status`.
void add_cpm_command(CLI::App& app, int& status);
void add_bench_command(CLI::App& app, int& status);
void add_disasm_command(CLI::App& app, int& status);
void add_script_command(CLI::App& app, int& status);
void add_run_command(CLI::App& app, int& status);

}  // namespace alp85::cli
