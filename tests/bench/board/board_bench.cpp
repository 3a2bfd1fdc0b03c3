// The board's scheduler overhead: the same firmware-like workload (emu/bench/bench_board.asm) on the
// bare core and on the ALP 85 with its 8155 and 8279 idle. Target: the board at >= 90% of the bare
// core's T-states per second. Figures are reported (counter "Tstates/s"), never asserted; `alp85
// bench board` prints the same comparison.
#include <benchmark/benchmark.h>

#include "emu/bench/bench_board.h"

namespace {

constexpr std::uint64_t kSlice = 30'720'000;  // 10 emulated seconds per iteration

void BM_BareCore(benchmark::State& state) {
    alp85::BoardBench bench;
    std::uint64_t total = 0;
    for (auto _ : state) total += bench.run_bare(kSlice);
    state.counters["Tstates/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}

void BM_BoardIdlePeripherals(benchmark::State& state) {
    alp85::BoardBench bench;
    std::uint64_t total = 0;
    for (auto _ : state) total += bench.run_board(kSlice);
    state.counters["Tstates/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_BareCore)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_BoardIdlePeripherals)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
