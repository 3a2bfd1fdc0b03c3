// alp85 pisa TAPE [--rom PROGRAM.pasm] [--record FILE.csv] [--plot FILE.svg|png]: the Pisa
// multi-purpose interpolator (1969) runs a tape through its ROM program and drives the machine
// tool's X and Y tables through its servos (docs/pisa.md).
// Exit status: 0 the tape ran to its end; 1 a bad tape or program (file:line:col: error:, nothing
// written), a run that did not end, or an output that cannot be written; 2 a usage error.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "asm/pisa_asm.h"
#include "emu/cli/commands.h"
#include "emu/util/input_file.h"
#include "emu/pisa/run.h"
#include "emu/pisa/run_plot.h"
#include "emu/plot/plot.h"
#include "asm/files/atomic_file.h"

namespace alp85 {
extern const char pisa_interp_source[];  // firmware/pisa/interp.pasm, embedded at build time
}

namespace alp85::cli {
namespace {


// The plot drawn to a file of the same extension beside the target, then read back for the
// all-or-nothing write.
std::string plot_bytes(const std::string& target, const std::string& title, const pisa::Tape& tape,
                       const pisa::RunResult& r) {
    plot::Chart c = pisa::toolpath_chart(title, tape, r);
    const std::filesystem::path to(target);
    const std::string stem = "." + to.stem().string() + ".plot-tmp";
    const std::filesystem::path tmp = to.parent_path() / (stem + to.extension().string());
    // plot::write draws to its own ".STEM.partial.EXT" first: both are removed if a signal ends us.
    const TemporaryGuard guard(tmp), partial(to.parent_path() / ("." + stem + ".partial" + to.extension().string()));
    try {
        plot::write(c, tmp.string());
    } catch (const std::exception& e) {
        std::string msg = e.what();  // the plot the user asked for, not our temporary
        for (auto at = msg.find(tmp.string()); at != std::string::npos; at = msg.find(tmp.string(), at + target.size()))
            msg.replace(at, tmp.string().size(), target);
        throw std::runtime_error(msg);
    }
    // Our own temporary, just drawn: read back whole (a plot has no input cap).
    std::ifstream in(tmp, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    const bool read = in.good() || in.eof();
    in.close();
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    if (!read) throw std::runtime_error("cannot read back the plot " + target);
    return bytes.str();
}

}  // namespace

void add_pisa_command(CLI::App& app, int& status) {
    struct Args {
        std::string tape, rom, record, plot;
        double max_time_s = 0;  // 0: from the tape
    };
    auto args = std::make_shared<Args>();
    std::vector<std::string> outputs;
    CLI::App* cmd = app.add_subcommand("pisa", "The Pisa multi-purpose interpolator (1969) runs a tape (docs/pisa.md)");
    cmd->add_option("TAPE", args->tape, "Tape in block format: N G X Y I J F (docs/pisa.md)")->required();
    cmd->add_option("--rom", args->rom, "The ROM program, Pisa assembly (default: the built-in firmware/pisa/interp.pasm)");
    add_output_option(cmd, outputs, "--record", args->record, "Write the 6 ms outputs and the tables' positions as CSV");
    add_output_option(cmd, outputs, "--plot", args->plot, "Draw the toolpath (exact path, outputs, tables) to .svg or .png");
    cmd->add_option("--max-time", args->max_time_s,
                    "Stop with an error after this many seconds of machine time (default: twice the tape's own time, "
                    "its moves at their feedrates and its reading, and a minute)")
        ->type_name("SECONDS")
        ->check(CLI::Range(0.001, 1e7));
    cmd->footer(
        "Example:\n"
        "  alp85 pisa scripts/pisa/contour.tape --record contour.csv --plot contour.svg\n"
        "  alp85 pisa long.tape --max-time 7200\n"
        "A run that has not ended after --max-time seconds of machine time stops (a program that never\n"
        "ends); by default the limit is twice the tape's own time and a minute, so a valid tape, however\n"
        "long, runs to its end.\n"
        "Exit status: 0 the tape ran to its end; 1 a bad tape or program (file:line:col: error: ...,\n"
        "nothing written), a run that did not end, or an output that cannot be written; 2 a usage error\n"
        "(an output that is the tape or the program, --record and --plot on one file, a --max-time that\n"
        "is not 0.001 to 10000000 s: nothing written).");
    on_run(cmd, status, outputs, [args] {
        auto ext = std::filesystem::path(args->plot).extension().string();
        if (!args->plot.empty() && ext != ".svg" && ext != ".png") {
            std::cerr << fmt::format("alp85 pisa: --plot {}: the extension must be .svg or .png\n", args->plot);
            return kUsageError;
        }
        if (refuse_output_clash("pisa", {{args->tape, "the tape"}, {args->rom, "the ROM program"}},
                                {{args->record, "--record"}, {args->plot, "--plot"}})) {
            return kUsageError;
        }
        std::string text;
        try {
            text = read_input(args->tape, FileKind::Tape);
        } catch (const InputError& e) {
            std::cerr << fmt::format("alp85 pisa: {}\n", e.what());
            return 1;
        }
        auto parsed = pisa::parse_tape(text);
        if (parsed.error) {
            std::cerr << fmt::format("{}:{}:{}: error: {}\n", args->tape, parsed.error->line, parsed.error->col,
                                     parsed.error->message);
            std::cerr << "alp85 pisa: the tape was refused; nothing written\n";
            return 1;
        }
        auto program = args->rom.empty() ? pisa_asm::assemble_string(pisa_interp_source, {}, "interp.pasm")
                                         : pisa_asm::assemble_file(args->rom);
        for (auto& d : program.out.diagnostics) std::cerr << asm85::format_diagnostic(d);
        if (!program.ok()) {
            std::cerr << "alp85 pisa: the program does not assemble; nothing written\n";
            return 1;
        }
        pisa::RunParams params;
        if (args->max_time_s > 0)
            params.max_steps = static_cast<std::uint64_t>(std::llround(args->max_time_s / pisa::kDigitStepSeconds));
        auto r = pisa::run_tape(program.rom, parsed.tape, params);
        if (r.stop.reason != pisa::StopReason::End) {
            const double limit_s = static_cast<double>(r.max_steps) * pisa::kDigitStepSeconds;
            std::cerr << fmt::format(
                "alp85 pisa: the run did not end: {}; nothing written\n",
                r.stop.reason == pisa::StopReason::Fault
                    ? r.stop.message
                    : args->max_time_s > 0
                          ? fmt::format("{} s of machine time passed (--max-time)", limit_s)
                          : fmt::format("{:.1f} s of machine time passed, twice the tape's own time ({:.1f} s) and a "
                                        "minute (--max-time sets the limit)",
                                        limit_s, static_cast<double>(pisa::tape_steps(parsed.tape, params)) * pisa::kDigitStepSeconds));
            return 1;
        }
        auto flag = [&](const char* name) {
            const auto* s = program.out.find_symbol(name);
            return s && s->value < pisa::kIndicators && r.indicators[s->value];
        };
        if (r.output_samples == 0) {
            std::cerr << "alp85 pisa: the program ended without an output; nothing written\n";
            return 1;
        }
        const auto& last = r.samples[r.output_samples - 1];
        fmt::print("{} blocks, {} elements; {:.3f} s of machine time, {} instructions\n", parsed.tape.blocks,
                   parsed.tape.elements.size(), static_cast<double>(r.steps) * 1e-7, r.instructions);
        fmt::print("end point X{:.3f} Y{:.3f} mm (commanded), tables X{:.4f} Y{:.4f} mm\n",
                   static_cast<double>(last.cmd_x_um) / 1000, static_cast<double>(last.cmd_y_um) / 1000,
                   r.samples.back().x_mm, r.samples.back().y_mm);
        fmt::print("overran the 6 ms clock: {}; motion waited for the tape: {}\n", flag("LATE") ? "yes" : "no",
                   flag("STALL") ? "yes" : "no");
        try {
            AtomicFileGroup out;
            if (!args->record.empty()) out.add(args->record, pisa::samples_csv(r));
            if (!args->plot.empty())
                out.add(args->plot, plot_bytes(args->plot, std::filesystem::path(args->tape).filename().string(), parsed.tape, r));
            out.commit();
        } catch (const std::exception& e) {
            std::cerr << fmt::format("alp85 pisa: {}; nothing written\n", e.what());
            return 1;
        }
        return 0;
    });
}

}  // namespace alp85::cli
