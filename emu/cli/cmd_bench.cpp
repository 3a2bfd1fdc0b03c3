// alp85 bench cpu [--cpu 8080|8085] [--tstates N]: the fixed CPU workload (emu/bench_cpu.asm),
// emulated T-states per host second.
// alp85 bench board [--tstates N]: the board with idle peripherals against the bare core.
#include <cstdio>
#include <memory>
#include <string>

#include "emu/bench/bench_board.h"
#include "emu/bench/bench_cpu.h"
#include "emu/cli/commands.h"

namespace alp85::cli {

namespace {
struct BenchArgs {
    std::string cpu = "8085";
    std::uint64_t tstates = 3'000'000'000ULL;
};

int run_bench_cpu(const BenchArgs& args) {
    CpuBench bench(variant_of(args.cpu));
    const Stopwatch watch;
    const std::uint64_t t = bench.run(args.tstates);
    const double seconds = watch.wall_seconds(), cpu_seconds = watch.cpu_seconds();
    std::printf("workload:     delay loop, multiply, BCD add, CRC-16 (emu/bench_cpu.asm)\n");
    std::printf("cpu:          i%s\n", args.cpu.c_str());
    std::printf("instructions: %llu\n", static_cast<unsigned long long>(bench.cpu().instructions()));
    std::printf("T-states:     %llu\n", static_cast<unsigned long long>(t));
    std::printf("wall time:    %.3f s (process CPU time %.3f s)\n", seconds, cpu_seconds);
    if (seconds > 0)
        std::printf("T-states/s:   %.4g (%.0fx a 3.072 MHz 8085)\n", t / seconds, t / seconds / 3.072e6);
    if (cpu_seconds > 0) std::printf("per CPU second: %.4g T-states\n", t / cpu_seconds);
    return 0;
}
// Host CPU seconds taken by fn (the process's, so other load on the machine does not count).
template <class Fn>
double cpu_seconds(Fn&& fn) {
    const Stopwatch watch;
    fn();
    return watch.cpu_seconds();
}

int run_bench_board(std::uint64_t tstates) {
    BoardBench bench;
    std::uint64_t bare = 0, board = 0;
    const double bare_s = cpu_seconds([&] { bare = bench.run_bare(tstates); });
    const double board_s = cpu_seconds([&] { board = bench.run_board(tstates); });
    const double bare_rate = bare / bare_s, board_rate = board / board_s;
    std::printf("workload:     16-bit arithmetic through RAM, CRC-16, the thesis's DL delay (emu/bench_board.asm)\n");
    std::printf("bare core:    %llu T-states in %.3f s CPU time: %.4g T-states/s\n",
                static_cast<unsigned long long>(bare), bare_s, bare_rate);
    std::printf("board:        %llu T-states in %.3f s CPU time: %.4g T-states/s (8155 and 8279 idle)\n",
                static_cast<unsigned long long>(board), board_s, board_rate);
    std::printf("board / bare: %.1f %% (target: at least 90 %%)\n", 100.0 * board_rate / bare_rate);
    return 0;
}
}  // namespace

void add_bench_command(CLI::App& app, int& status) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* bench = app.add_subcommand("bench", "Benchmarks");
    bench->require_subcommand(1);
    bench->footer("Exit status: 0 success, 2 a usage error.");
    CLI::App* cpu = bench->add_subcommand("cpu", "Emulated T-states per second on a fixed CPU-bound workload");
    add_cpu_option(cpu, args->cpu, "processor variant");
    cpu->add_option("--tstates", args->tstates, "T-states to run")->check(CLI::Range(1ULL, 1ULL << 50))->capture_default_str();
    cpu->callback([args, &status] { status = run_bench_cpu(*args); });

    CLI::App* board = bench->add_subcommand("board", "The board with idle peripherals against the bare core, same workload");
    board->add_option("--tstates", args->tstates, "T-states to run on each")->check(CLI::Range(1ULL, 1ULL << 50))->capture_default_str();
    board->callback([args, &status] { status = run_bench_board(args->tstates); });
}

}  // namespace alp85::cli
