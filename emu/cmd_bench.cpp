// alp85 bench cpu [--cpu 8080|8085] [--tstates N]
// Runs the fixed CPU workload (emu/bench_cpu.asm) and prints emulated T-states per host second.
#include <chrono>
#include <ctime>
#include <cstdio>
#include <memory>
#include <string>

#include "emu/bench_cpu.h"
#include "emu/commands.h"

namespace alp85::cli {

namespace {
struct BenchArgs {
    std::string cpu = "8085";
    std::uint64_t tstates = 3'000'000'000ULL;
};

int run_bench_cpu(const BenchArgs& args) {
    CpuBench bench(args.cpu == "8080" ? Variant::I8080 : Variant::I8085);
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    const std::uint64_t t = bench.run(args.tstates);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
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
}  // namespace

void add_bench_command(CLI::App& app, int& status) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* bench = app.add_subcommand("bench", "Benchmarks");
    bench->require_subcommand(1);
    CLI::App* cpu = bench->add_subcommand("cpu", "Emulated T-states per second on a fixed CPU-bound workload");
    cpu->add_option("--cpu", args->cpu, "processor variant")->check(CLI::IsMember({"8080", "8085"}))->capture_default_str();
    cpu->add_option("--tstates", args->tstates, "T-states to run")->check(CLI::Range(1ULL, 1ULL << 50))->capture_default_str();
    cpu->callback([args, &status] { status = run_bench_cpu(*args); });
}

}  // namespace alp85::cli
