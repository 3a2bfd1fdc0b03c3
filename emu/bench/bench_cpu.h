// The CPU benchmark workload (emu/bench/bench_cpu.asm, assembled at build time): one fixed program on a
// bare CPU with 64 KiB of RAM, run for a given number of T-states. Used by `alp85 bench cpu`
// and by the Google Benchmark target in tests/bench/cpu.
#pragma once

#include <cstdint>
#include <vector>

#include "emu/core/bus.h"
#include "emu/core/i8085.h"

namespace alp85 {

class CpuBench {
public:
    explicit CpuBench(Variant variant);
    // Runs the workload from its start for `tstates` T-states (whole instructions); returns the
    // T-states actually run.
    std::uint64_t run(std::uint64_t tstates);
    const I8085& cpu() const { return cpu_; }

private:
    std::vector<std::uint8_t> ram_;
    Bus bus_;
    I8085 cpu_;
};

}  // namespace alp85
