// alp85 cpm PROGRAM.COM [--cpu 8080|8085] [--max-tstates N] [--stats] [--trace OUT.csv [--trace-last N]]
// Runs a CP/M .COM program (e.g. the period 8080/8085 CPU diagnostics) on the CP/M machine.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <charconv>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "asm/files/atomic_file.h"
#include "emu/cli/commands.h"
#include "emu/util/input_file.h"
#include "emu/cpm/cpm.h"
#include "emu/debug/trace_csv.h"

namespace alp85::cli {

namespace {
struct CpmArgs {
    std::string program;
    std::string cpu = "8085";
    std::string max_tstates = "0";  // checked by run_cpm: CLI11 would take -1 as 2^64 - 1
    bool stats = false;
    std::string trace;
    std::size_t trace_last = 0;  // 0: every instruction
};

// The CSV trace: streamed, or the last N lines kept in a ring (what a failing diagnostic did
// just before it stopped), written oldest first by finish().
class CsvTrace {
public:
    CsvTrace(std::ostream& out, std::size_t last) : out_(out), ring_(last) {}
    void add(std::string line) {
        if (ring_.empty())
            out_ << line;
        else
            ring_[count_ % ring_.size()] = std::move(line);
        ++count_;
    }
    void finish() {
        const std::size_t n = std::min<std::size_t>(count_, ring_.size());
        for (std::size_t i = 0; i < n; ++i) out_ << ring_[(count_ - n + i) % ring_.size()];
    }

private:
    std::ostream& out_;
    std::vector<std::string> ring_;
    std::size_t count_ = 0;
};

// A whole number of T-states, 0 to 2^64 - 1, in decimal.
std::optional<std::uint64_t> parse_tstates(const std::string& text) {
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [p, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || p != end || text.empty()) return std::nullopt;
    return v;
}

int run_cpm(const CpmArgs& args) {
    const auto max_tstates = parse_tstates(args.max_tstates);
    if (!max_tstates) {
        std::fprintf(stderr, "alp85 cpm: error: --max-tstates '%s' is not a number of T-states (0 to %llu; 0 = no limit)\n",
                     args.max_tstates.c_str(), static_cast<unsigned long long>(UINT64_MAX));
        return kUsageError;
    }
    if (refuse_output_clash("cpm", {{args.program, "the program"}}, {{args.trace, "--trace"}})) return kUsageError;
    std::vector<std::uint8_t> image;
    try {
        const std::string bytes = read_input(args.program, FileKind::Binary);
        image.assign(bytes.begin(), bytes.end());
    } catch (const InputError& e) {
        std::fprintf(stderr, "alp85 cpm: %s\n", e.what());
        return 1;
    }
    CpmMachine machine(variant_of(args.cpu));
    if (const std::string err = machine.load_program(image); !err.empty()) {
        std::fprintf(stderr, "alp85 cpm: %s: %s\n", args.program.c_str(), err.c_str());
        return 1;
    }
    std::unique_ptr<AtomicOutput> trace_file;
    std::unique_ptr<CsvTrace> trace;
    if (!args.trace.empty()) {
        try {
            trace_file = std::make_unique<AtomicOutput>(args.trace);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "alp85 cpm: trace: %s\n", e.what());
            return 1;
        }
        trace_file->stream() << trace_csv_header();
        trace = std::make_unique<CsvTrace>(trace_file->stream(), args.trace_last);
        machine.set_trace([&machine, &trace](const I8085& cpu) {
            trace->add(trace_csv_line(cpu, [&machine](std::uint16_t a) { return machine.bus().peek(a); }));
        });
    }
    const Stopwatch watch;
    const CpmMachine::Result r = machine.run(*max_tstates, [](char ch) {
        std::fputc(ch, stdout);
        if (ch == '\n') std::fflush(stdout);
    });
    const double seconds = watch.wall_seconds(), cpu_seconds = watch.cpu_seconds();
    std::fflush(stdout);
    if (trace) {  // written however the run ended: that is when a trace is wanted most
        trace->finish();
        try {
            trace_file->commit();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "alp85 cpm: trace: %s\n", e.what());
            return 1;
        }
    }
    if (!r.message.empty()) std::fprintf(stderr, "\nalp85 cpm: %s: %s\n", args.program.c_str(), r.message.c_str());
    if (args.stats) {
        std::fprintf(stderr,
                     "\ncpu:          i%s\ninstructions: %llu\nT-states:     %llu\nwall time:    %.3f s (process CPU "
                     "time %.3f s)\n",
                     args.cpu.c_str(), static_cast<unsigned long long>(r.instructions),
                     static_cast<unsigned long long>(r.tstates), seconds, cpu_seconds);
        if (seconds > 0)
            std::fprintf(stderr, "T-states/s:   %.4g (%.1f MHz equivalent)\n", r.tstates / seconds,
                         r.tstates / seconds / 1e6);
    }
    return r.exit_status;
}
}  // namespace

void add_cpm_command(CLI::App& app, int& status) {
    Subcommand<CpmArgs> cmd(app, "cpm", "Run a CP/M .COM program (loaded at 0100H) with a small BDOS");
    cmd->add_option("program", cmd.args->program, "the .COM file")->required();
    add_cpu_option(cmd.cmd, cmd.args->cpu, "processor variant");
    cmd->add_option("--max-tstates", cmd.args->max_tstates, "stop with an error after N T-states (0 = no limit)")->type_name("UINT");
    cmd->add_option("--max-cycles", cmd.args->max_tstates, "the old name of --max-tstates")->group("");  // hidden alias
    cmd->add_flag("--stats", cmd.args->stats, "print instructions, T-states, wall time and T-states per second");
    auto* trace = cmd.output("--trace", cmd.args->trace,
                                    "write every executed instruction as CSV (T-state, PC, opcode, disassembly, "
                                    "registers before it)");
    cmd->add_option("--trace-last", cmd.args->trace_last, "with --trace: only the last N instructions of the run")
        ->needs(trace)
        ->check(CLI::Range(std::size_t{1}, std::size_t{10'000'000}));  // the ring is kept in memory
    cmd->footer(
        "Exit status: 0 the program ended by warm boot (JMP 0 or BDOS 0), 1 the program or the trace\n"
        "file cannot be read or written, 2 a usage error (a bad number, a --trace that is the program)\n"
        "or a HLT outside the BDOS, 3 an undefined BDOS\n"
        "function, 4 the T-state limit was reached, 5 stopped by a debug hook.");
    cmd.run(status, run_cpm);
}

}  // namespace alp85::cli
