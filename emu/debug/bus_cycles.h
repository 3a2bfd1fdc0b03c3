// The 8085's bus, machine cycle by machine cycle, as the data sheet draws it: for the instruction
// at the PC (or an interrupt acknowledge) the cycles of asm/isa_cycles.h, each with its status
// lines (IO/M, S1, S0), strobes (ALE, RD, WR, INTA) and the address and data on A15-A8 and
// AD7-AD0, worked out from the registers and memory (read without side effects). For `alp85
// timing` and the debugger's `timing` (docs/signals.md).
//
// The core runs whole instructions (emu/core/i8085.h): these cycles are what the data sheet says
// the chip does for that instruction, not a record of the core's accesses; the T-states agree with
// the core's (tests/cpu/isa_cycles_test.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "asm/isa_cycles.h"
#include "emu/core/i8085.h"

namespace alp85::debug {

struct BusCycle {
    isa::MachineCycle type = isa::MachineCycle::Fetch4;
    int tstates = 4;
    bool has_address = false;   // false: A15-A8 and AD7-AD0 carry no address (bus idle, halt)
    std::uint16_t address = 0;  // in T1; an I/O cycle: the port on both halves
    bool has_data = false;      // false: not known here (an input port's answer)
    std::uint8_t data = 0;      // on AD7-AD0 in T2-T3
    std::string what;           // "opcode 3EH", "operand", "store A", "push PCH"
};

struct BusStatus {
    char io_m, s1, s0;  // '0', '1' or 'z' (HALT floats IO/M)
    bool rd, wr, inta;  // strobes asserted (the pins are active low)
    bool ale;           // ALE pulses in T1
};

// The data sheet's name of a cycle ("opcode fetch", "memory read", "bus idle") and its lines.
std::string_view cycle_name(isa::MachineCycle c);
BusStatus bus_status(isa::MachineCycle c);

using Peek = std::function<std::uint8_t(std::uint16_t)>;

// Whether the conditional instruction `opcode` is taken with flags `f` (unconditional: true).
bool condition_taken(std::uint8_t opcode, std::uint8_t f);
// The cycles of the instruction at r.pc.
std::vector<BusCycle> instruction_cycles(const Registers& r, const Peek& peek);
// An acknowledge of RST 5.5, 6.5, 7.5 or TRAP before the instruction at r.pc: the 6 T idle cycle
// and the push of the PC, then the jump to `vector`.
std::vector<BusCycle> restart_ack_cycles(const Registers& r);

// One line per cycle: "M1  opcode fetch   T1-T4  IO/M=0 S1,S0=1,1  RD   0800H  3EH (opcode MVI A,32H)".
std::string cycles_text(const std::vector<BusCycle>& cycles);

// The waveforms of the cycles, half a T-state at a time: per signal (CLK, ALE, IO/M, S1, S0, RD,
// WR, INTA, A15-A8, AD7-AD0) one level per half T-state: '0', '1', 'z' (floating), 'x'
// (unspecified); the buses' values in `bus_high` / `bus_low` where they hold one.
struct Waveforms {
    int half_tstates = 0;
    std::vector<std::string> names;     // wires, in the order drawn
    std::vector<std::string> levels;    // per wire: a character per half T-state
    std::vector<int> bus_high, bus_low; // per half T-state: the byte, -1 floating, -2 unspecified
};
Waveforms waveforms(const std::vector<BusCycle>& cycles);

// The waveforms as a VCD (1 ns units; each wire and each bus bit its own 1-bit variable so that
// sigrok-cli reads them). Throws std::runtime_error; the file is whole or absent.
void write_cycles_vcd(const std::vector<BusCycle>& cycles, const std::string& path, const std::string& title);

}  // namespace alp85::debug
