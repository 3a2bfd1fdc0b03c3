// The machine tool's cost: 10 000 steps per axis on X, Y and Z at once at 400 steps/s (25 s of
// machine time), driven straight through set_drive at the T-states the firmware's pulse shape
// gives (direction, pulse high for half the period, low), in strokes of 1000 steps back and forth
// so every axis stays inside its travel; the transducers are read once per step as the firmware's
// INPUT subroutine does. Counter "machine_s/host_s": simulated seconds per host second.
// Targets (docs/machine.md): physical >= 100x real time, aim 500x.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "peripherals/machine_tool.h"

namespace {

using alp85::periph::MachineTool;

constexpr double kClock = 3.072e6;  // T-states per second: the ALP 85's CPU clock
constexpr std::uint64_t kPeriod = 7680;  // 400 steps/s
constexpr int kSteps = 10'000;

std::uint64_t run(MachineTool& m, std::uint64_t t0) {
    for (int k = 0; k < kSteps; ++k) {
        const bool dir = (k / 1000) % 2 == 0;
        const std::uint64_t t = t0 + static_cast<std::uint64_t>(k) * kPeriod;
        for (int a = 0; a < 3; ++a) m.set_drive(static_cast<MachineTool::Axis>(a), true, dir, t);
        for (int a = 0; a < 3; ++a) m.set_drive(static_cast<MachineTool::Axis>(a), false, dir, t + kPeriod / 2);
        for (int a = 0; a < 3; ++a) benchmark::DoNotOptimize(m.sense(static_cast<MachineTool::Axis>(a), t + kPeriod - 10));
    }
    const std::uint64_t end = t0 + kSteps * kPeriod;
    m.advance(end);
    return end;
}

void bench(benchmark::State& state, MachineTool::MotorModel model) {
    double machine_s = 0;
    for (auto _ : state) {
        MachineTool m(kClock);
        m.set_model(model);
        const std::uint64_t end = run(m, 1000);
        machine_s += static_cast<double>(end - 1000) / kClock;
        benchmark::DoNotOptimize(m.table_mm(MachineTool::Axis::X));
    }
    state.counters["machine_s/host_s"] = benchmark::Counter(machine_s, benchmark::Counter::kIsRate);
}

void BM_Physical(benchmark::State& state) { bench(state, MachineTool::MotorModel::Physical); }
void BM_Ideal(benchmark::State& state) { bench(state, MachineTool::MotorModel::Ideal); }

BENCHMARK(BM_Physical)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_Ideal)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
