#include "emu/bench/bench_cpu.h"

#include <algorithm>

#include "cpu_bench_program_embed.h"
#include "cpu_mem_bench_program_embed.h"

namespace alp85 {

BareCore::BareCore(Variant variant, std::span<const std::uint8_t> program, std::uint16_t origin)
    : ram(0x10000, 0), cpu(bus, variant) {
    std::copy(program.begin(), program.end(), ram.begin() + origin);
    bus.map_ram(0, 0x10000, ram.data());
    cpu.set_fast_loops(false);
}

namespace {
BareCore workload_core(Variant variant, CpuWorkload workload) {
    if (workload == CpuWorkload::Registers)
        return {variant, std::span(bench::kCpuBenchProgram, bench::kCpuBenchProgram_size), bench::kCpuBenchProgram_origin};
    return {variant, std::span(bench::kCpuMemBenchProgram, bench::kCpuMemBenchProgram_size),
            bench::kCpuMemBenchProgram_origin};
}
}  // namespace

CpuBench::CpuBench(Variant variant, CpuWorkload workload) : core_(workload_core(variant, workload)) {}

}  // namespace alp85
