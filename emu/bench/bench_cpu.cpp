#include "emu/bench/bench_cpu.h"

#include <algorithm>

#include "cpu_bench_program_embed.h"
#include "cpu_mem_bench_program_embed.h"

namespace alp85 {

CpuBench::CpuBench(Variant variant, CpuWorkload workload) : ram_(0x10000, 0), cpu_(bus_, variant) {
    if (workload == CpuWorkload::Registers)
        std::copy_n(bench::kCpuBenchProgram, bench::kCpuBenchProgram_size, ram_.begin() + bench::kCpuBenchProgram_origin);
    else
        std::copy_n(bench::kCpuMemBenchProgram, bench::kCpuMemBenchProgram_size,
                    ram_.begin() + bench::kCpuMemBenchProgram_origin);
    bus_.map_ram(0, 0x10000, ram_.data());
    cpu_.set_fast_loops(false);  // the interpreter alone: every DL iteration executed
}

std::uint64_t CpuBench::run(std::uint64_t tstates) { return cpu_.run(cpu_.tstates() + tstates); }

}  // namespace alp85
