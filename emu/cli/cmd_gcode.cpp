// alp85 gcode FILE.nc... -o PATH.hex: G-code (the subset of docs/contours.md) to the master
// program's path table in the expansion EPROM (3DD0H). Each file is one stored path, in order.
// Exit status: 0 written, 1 a file refused (nothing written), 2 a usage error.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "emu/cli/commands.h"
#include "emu/util/input_file.h"
#include "emu/gcode/gcode.h"
#include "emu/gcode/path_table.h"
#include "asm/files/atomic_file.h"

namespace alp85::cli {

void add_gcode_command(CLI::App& app, int& status) {
    struct Args {
        std::vector<std::string> files;
        std::string out;
        std::string method = "thesis";
        bool no_ramp = false;
    };
    auto args = std::make_shared<Args>();
    std::vector<std::string> outputs;
    CLI::App* cmd = app.add_subcommand("gcode", "G-code to the master program's path table (docs/contours.md)");
    cmd->add_option("files", args->files, "G-code files (.nc); each one is a path the keypad chooses (1, 2, ...)")
        ->required()
        ->check([](const std::string& f) { return input_problem(f); });  // a sentence for a link loop too
    add_output_option(cmd, outputs, "-o,--output", args->out, "The path table as Intel HEX (load it with the master program)")->required();
    cmd->add_option("--method", args->method,
                    "How the master draws segments: thesis (its line routine, the default) or sampling (Watanabe and "
                    "Iwai's interpolation, 2 ms samples); a file's (METHOD SAMPLING) or (METHOD THESIS) comment wins")
        ->check(CLI::IsMember({"thesis", "sampling"}));
    cmd->add_flag("--no-ramp", args->no_ramp,
                  "Sampling without the feed ramp (full feed from the first sample); a file's (RAMP ON) wins");
    cmd->footer(
        "Example:\n"
        "  alp85 gcode scripts/master/circle.nc -o circle.hex\n"
        "  alp85 gcode --method sampling scripts/master/circle.nc -o circle.hex\n"
        "Points are kept exactly and rounded to the 0.05 mm step once: under G91 the increments add up\n"
        "before rounding, so an incremental program gives the table of the absolute one through the same\n"
        "points. F is rounded to whole mm/min, which must be 6 to 1500 (docs/contours.md).\n"
        "Exit status: 0 the table was written, 1 a file was refused (its errors are shown as\n"
        "file:line:col: error: ...; nothing is written), 2 a usage error (a G-code file that is missing or\n"
        "no file, an empty -o, -o naming a G-code file: nothing is written).");
    on_run(cmd, status, outputs, [args] {
        std::vector<NamedPath> inputs;
        for (const std::string& f : args->files) inputs.push_back({f, "the G-code file"});
        if (refuse_output_clash("gcode", inputs, {{args->out, "-o"}})) {
            return kUsageError;
        }
        std::vector<std::vector<gcode::Entry>> paths;
        bool failed = false;
        for (const std::string& f : args->files) {
            std::string text;
            try {
                text = read_input(f, FileKind::GCode);
            } catch (const InputError& e) {
                std::cerr << fmt::format("alp85 gcode: {}\n", e.what());
                failed = true;
                continue;
            }
            gcode::Parsed p = gcode::parse(text);
            if (p.error) {
                std::cerr << fmt::format("{}:{}:{}: error: {}\n", f, p.error->line, p.error->column, p.error->message);
                failed = true;
                continue;
            }
            const bool sampling = p.method ? *p.method == gcode::Method::Sampling : args->method == "sampling";
            const bool ramp = p.ramp ? *p.ramp : !args->no_ramp;
            paths.push_back(sampling ? gcode::sampling_path(p.entries, ramp) : std::move(p.entries));
        }
        std::vector<std::uint8_t> bytes;
        if (!failed) {
            bytes = gcode::table_bytes(paths);
            if (bytes.size() > gcode::kTableSize) {
                std::cerr << fmt::format("alp85 gcode: the table needs {} bytes; the EPROM holds {} ({} entries of {})\n",
                                         bytes.size(), gcode::kTableSize, gcode::kTableSize / gcode::kEntrySize,
                                         gcode::kEntrySize);
                failed = true;
            }
        }
        if (failed) {
            std::cerr << fmt::format("alp85 gcode: nothing written to {}\n", args->out);
            return 1;
        }
        try {
            write_atomic(args->out, gcode::intel_hex(gcode::kTableBase, bytes));
        } catch (const std::exception& e) {
            std::cerr << fmt::format("alp85 gcode: {}\n", e.what());
            return 1;
        }
        return 0;
    });
}

}  // namespace alp85::cli
