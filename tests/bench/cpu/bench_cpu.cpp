// CPU core throughput on the two fixed workloads (registers, memory), per variant. The counter "Tstates/s" is the figure
// to compare with `alp85 bench cpu`.
#include <benchmark/benchmark.h>

#include "emu/bench/bench_cpu.h"

namespace {

void run_workload(benchmark::State& state, alp85::Variant variant,
                  alp85::CpuWorkload workload = alp85::CpuWorkload::Registers) {
    constexpr std::uint64_t kSlice = 50'000'000;  // T-states per iteration
    alp85::CpuBench bench(variant, workload);
    std::uint64_t total = 0;
    for (auto _ : state) total += bench.run(kSlice);
    state.counters["Tstates/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
    state.counters["instr/s"] =
        benchmark::Counter(static_cast<double>(bench.cpu().instructions()), benchmark::Counter::kIsRate);
}

void BM_Cpu8085(benchmark::State& state) { run_workload(state, alp85::Variant::I8085); }
void BM_Cpu8080(benchmark::State& state) { run_workload(state, alp85::Variant::I8080); }

void BM_CpuMemory8085(benchmark::State& state) { run_workload(state, alp85::Variant::I8085, alp85::CpuWorkload::Memory); }
void BM_CpuMemory8080(benchmark::State& state) { run_workload(state, alp85::Variant::I8080, alp85::CpuWorkload::Memory); }

BENCHMARK(BM_Cpu8085)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Cpu8080)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuMemory8085)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CpuMemory8080)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
