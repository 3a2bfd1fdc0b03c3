// The board's scheduler overhead: the same CPU-bound workload on the bare core (a flat 64 KiB RAM
// bus) and on the ALP 85 board with its 8155 and 8279 idle. Target: the board at >= 90% of the
// bare core's T-states per second. Figures are reported (counter "Tstates/s"), never asserted.
#include <benchmark/benchmark.h>

#include <array>

#include "asm/asm85.h"
#include "emu/machine.h"

namespace {

constexpr std::uint64_t kSlice = 30'720'000;  // 10 emulated seconds per iteration

alp85::asm85::Result workload() {
    auto r = alp85::asm85::assemble_file(ALP85_BENCH_WORKLOAD);
    if (!r.ok()) throw std::runtime_error("workload.asm does not assemble");
    return r;
}

void BM_BareCore(benchmark::State& state) {
    static std::array<std::uint8_t, 0x10000> ram{};
    const auto r = workload();
    for (const auto& s : r.image.segments()) std::copy(s.bytes.begin(), s.bytes.end(), ram.begin() + s.start);
    alp85::Bus bus;
    bus.map_ram(0, 0x10000, ram.data());
    alp85::I8085 cpu(bus);
    cpu.reset();
    cpu.regs().pc = 0x0800;
    std::uint64_t total = 0;
    for (auto _ : state) total += cpu.run(cpu.cycles() + kSlice);
    state.counters["Tstates/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}

void BM_BoardIdlePeripherals(benchmark::State& state) {
    alp85::Machine m;
    const auto r = workload();
    for (const auto& s : r.image.segments()) m.load(s.start, s.bytes);
    m.reset();
    m.cpu().regs().pc = 0x0800;
    std::uint64_t total = 0;
    for (auto _ : state) {
        const std::uint64_t before = m.now();
        m.run_for(kSlice);
        total += m.now() - before;
    }
    state.counters["Tstates/s"] = benchmark::Counter(static_cast<double>(total), benchmark::Counter::kIsRate);
}

BENCHMARK(BM_BareCore)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_BoardIdlePeripherals)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
