// The CPU benchmark workloads (assembled at build time), each one fixed program on a bare CPU with
// a flat 64 KiB of RAM, run for a given number of T-states. Used by `alp85 bench cpu` and by the
// Google Benchmark target in tests/bench/cpu.
//   Registers  emu/bench/bench_cpu.asm: the firmware's delay loop, multiply, BCD add, CRC-16
//   Memory     emu/bench/bench_cpu_mem.asm: block copy, bubble sort, stack traffic, table lookup
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "emu/core/bus.h"
#include "emu/core/i8085.h"

namespace alp85 {

enum class CpuWorkload : std::uint8_t { Registers, Memory };

// A bare CPU on a flat 64 KiB of RAM holding one program, with the delay-loop shortcut off (the
// interpreter alone: every iteration executed): what each benchmark measures against.
struct BareCore {
    BareCore(Variant variant, std::span<const std::uint8_t> program, std::uint16_t origin);
    // Runs on for about `tstates` T-states (whole instructions); returns the T-states actually run.
    std::uint64_t run(std::uint64_t tstates) { return cpu.run(cpu.tstates() + tstates); }

    std::vector<std::uint8_t> ram;
    Bus bus;
    I8085 cpu;
};

class CpuBench {
public:
    explicit CpuBench(Variant variant, CpuWorkload workload = CpuWorkload::Registers);
    // Runs the workload from its start for `tstates` T-states (whole instructions); returns the
    // T-states actually run.
    std::uint64_t run(std::uint64_t tstates) { return core_.run(tstates); }
    const I8085& cpu() const { return core_.cpu; }

private:
    BareCore core_;
};

}  // namespace alp85
