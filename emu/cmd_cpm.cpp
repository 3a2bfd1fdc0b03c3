// alp85 cpm PROGRAM.COM [--cpu 8080|8085] [--max-cycles N] [--stats]
// Runs a CP/M .COM program (e.g. the period 8080/8085 CPU diagnostics) on the CP/M machine.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "emu/commands.h"
#include "emu/cpm.h"

namespace alp85::cli {

namespace {
struct CpmArgs {
    std::string program;
    std::string cpu = "8085";
    std::uint64_t max_cycles = 0;
    bool stats = false;
};

int run_cpm(const CpmArgs& args) {
    std::ifstream in(args.program, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "alp85 cpm: cannot open %s\n", args.program.c_str());
        return 1;
    }
    std::vector<std::uint8_t> image((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        std::fprintf(stderr, "alp85 cpm: cannot read %s\n", args.program.c_str());
        return 1;
    }
    const Variant variant = args.cpu == "8080" ? Variant::I8080 : Variant::I8085;
    CpmMachine machine(variant);
    if (const std::string err = machine.load_program(image); !err.empty()) {
        std::fprintf(stderr, "alp85 cpm: %s: %s\n", args.program.c_str(), err.c_str());
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    const CpmMachine::Result r = machine.run(args.max_cycles, [](char ch) {
        std::fputc(ch, stdout);
        if (ch == '\n') std::fflush(stdout);
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    std::fflush(stdout);
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
    auto args = std::make_shared<CpmArgs>();
    CLI::App* cmd = app.add_subcommand("cpm", "Run a CP/M .COM program (loaded at 0100H) with a small BDOS");
    cmd->add_option("program", args->program, "the .COM file")->required();
    cmd->add_option("--cpu", args->cpu, "processor variant")->check(CLI::IsMember({"8080", "8085"}))->capture_default_str();
    cmd->add_option("--max-cycles", args->max_cycles, "stop with an error after N T-states (0 = no limit)");
    cmd->add_flag("--stats", args->stats, "print instructions, T-states, wall time and T-states per second");
    cmd->callback([args, &status] { status = run_cpm(*args); });
}

}  // namespace alp85::cli
