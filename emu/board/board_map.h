// The ALP 85's memory map, I/O map and interrupt wiring, declared once. The Machine builds its
// bus from these tables; the debugger and docs/board.md describe the board from them.
//
// Evidence (docs/board.md has the full argument): thesis Chapter II gives the parts (2 KB monitor
// EPROM, 2 KB user EPROM, 4 KB RAM, 8155, 8279); the listing in Appendix B fixes the rest:
// ORG 0800H, variables at 1B00H-1B54H, LXI SP,20B0H, IN 0FAH / OUT 0F9H, OUT 0E1H at MAIN.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "peripherals/machine_tool.h"

namespace alp85::board {

enum class Memory : std::uint8_t { MonitorEprom, UserEprom, Ram, Ram8155, ExpansionEprom };
enum class MemoryKind : std::uint8_t { Rom, Ram };

struct MemoryRegion {
    Memory id;
    std::uint16_t base;
    std::uint16_t size;
    MemoryKind kind;
    std::string_view name;   // short name for scripts and the debugger
    std::string_view part;   // what the thesis says sits there
};

inline constexpr std::array<MemoryRegion, 4> kMemoryMap{{
    {Memory::MonitorEprom, 0x0000, 0x0800, MemoryKind::Rom, "monitor", "2 KB monitor EPROM (2716)"},
    {Memory::UserEprom, 0x0800, 0x0800, MemoryKind::Rom, "user", "2 KB user EPROM (2716): the thesis firmware, ORG 0800H"},
    {Memory::Ram, 0x1000, 0x1000, MemoryKind::Ram, "ram", "4 KB static RAM (firmware variables at 1B00H)"},
    {Memory::Ram8155, 0x2000, 0x0100, MemoryKind::Ram, "ram8155", "8155 RAM, IO/M low (firmware stack below 20B0H)"},
}};

// The EPROM expansion of thesis 5.3 ("EPROM memory region of the ALP 85 microcomputer can be
// expanded with ease to store this master program"): an OPTION, off by default, so the machine
// as built stays the thesis machine. Where: the map above fills the address space in 4 KB blocks
// (0xxxH the two 2716s, 1xxxH the RAM, 2xxxH the 8155), so the next free block, 3000H-3FFFH,
// is where a 2732 (4 KB) on the next decoder output would sit. It holds the master program
// (3000H-3DCFH, firmware/master) and its path tables (3DD0H-3FFFH, alp85 gcode): docs/contours.md.
inline constexpr MemoryRegion kExpansionEprom{Memory::ExpansionEprom, 0x3000, 0x1000, MemoryKind::Rom, "expansion",
                                              "4 KB expansion EPROM (2732, optional): master program and path tables"};

// Board options a script or front end may switch on, by name (script `option NAME on|off`).
struct BoardOption {
    std::string_view name;
    std::string_view what;
};
inline constexpr std::array<BoardOption, 1> kBoardOptions{{
    {"expansion", "the 4 KB expansion EPROM at 3000H-3FFFH (thesis 5.3), off on the machine as built"},
}};

enum class Device : std::uint8_t { Kdc8279, Rio8155 };

// A device on ports first..last; the chip sees register (port - first) & offset_mask on its
// address lines (the board wires only the low address bits to the chip).
struct IoRegion {
    Device device;
    std::uint8_t first;
    std::uint8_t last;
    std::uint8_t offset_mask;
    std::string_view name;
    std::string_view registers;  // how the chip's address lines see the ports
    constexpr std::uint8_t offset(std::uint8_t port) const {
        return static_cast<std::uint8_t>((port - first) & offset_mask);
    }
};

// Unmapped ports and memory read FFH (a floating, pulled-up data bus).
inline constexpr std::array<IoRegion, 2> kIoMap{{
    {Device::Kdc8279, 0xE0, 0xE1, 0x01, "8279", "A0 = port bit 0: E0H data, E1H command/status"},
    {Device::Rio8155, 0xF8, 0xFD, 0x07, "8155",
     "AD0-AD2 = port - F8H: F8H command/status, F9H port A (motor outputs), FAH port B "
     "(transducer inputs), FBH port C, FCH timer low, FDH timer high"},
}};

enum class Source : std::uint8_t { Irq8279, TimerOut8155, VectIntrKey, ResetKey };
enum class CpuPin : std::uint8_t { Rst55, Trap, Rst75, ResetIn };

// Who drives which CPU input. The Machine connects exactly these (Machine::wire).
struct Wire {
    Source source;
    CpuPin pin;
    std::string_view why;
};

inline constexpr std::array<Wire, 4> kInterruptWiring{{
    {Source::Irq8279, CpuPin::Rst55, "key in the FIFO: the monitor may read keys by interrupt"},
    {Source::TimerOut8155, CpuPin::Trap, "the monitor's single step: a timer pulse traps after one instruction"},
    {Source::VectIntrKey, CpuPin::Rst75, "the VECT INTR key (rising edge latched by the 8085)"},
    {Source::ResetKey, CpuPin::ResetIn, "the RESET key resets the CPU, and RESET OUT the 8155 and 8279"},
}};

// The board's clock: a 6.144 MHz crystal on X1/X2; the 8085 divides by two. CLK OUT (3.072 MHz,
// one pulse per T-state) drives the 8155's TIMER IN and the 8279's CLK.
inline constexpr std::uint32_t kCrystalHz = 6'144'000;
inline constexpr std::uint32_t kCpuHz = kCrystalHz / 2;

// The machine tool on the 8155's ports (docs/machine.md, firmware/thesis/RECONSTRUCTION.md): per
// axis the sequencer's PULSE and DIRECTION on port A (F9H, output) and the transducer's COUNT bit
// (changes level at each increment) and DIRECTION bit (1 = moving +) on port B (FAH, input).
using ToolAxis = periph::MachineTool::Axis;

// One wire: its bit on the port and the evidence for it.
struct ToolBit {
    std::uint8_t bit;
    bool reconstructed;    // not in the surviving listing: a documented choice
    std::string_view why;  // the evidence
};

// One axis's four wires: to its sequencer on port A, from its transducer on port B.
struct AxisWiring {
    ToolAxis axis;
    ToolBit pulse, direction;        // port A (F9H), outputs
    ToolBit count, count_direction;  // port B (FAH), inputs
};

inline constexpr std::uint8_t kToolOutPort = 0xF9;  // OUT 0F9H in the listing
inline constexpr std::uint8_t kToolInPort = 0xFA;   // IN 0FAH in INPUT1
inline constexpr std::array<AxisWiring, 3> kToolWiring{{
    {ToolAxis::X,
     {0, false, "OUT writes 00H then 01H (X +) and 02H then 03H: bit 0 pulses X"},
     {1, false, "02H/03H: bit 1 set while X pulses, DELAY keeps it (ANI 0AH)"},
     {1, false, "INPUT: CPI 02H / JZ STEST - a change of bit 1 alone counts XAC"},
     {2, false, "INPUT1 passes bits 2-3 through (ANI 0CH); STEST: ANI 04H / JZ XDEC, so 1 = X moving +"}},
    {ToolAxis::Y,
     {2, false, "00H then 04H, 08H then 0CH: bit 2 pulses Y"},
     {3, false, "08H/0CH: bit 3 set while Y pulses, DELAY keeps it (ANI 0AH)"},
     {0, false, "INPUT1 keeps bits 0-1 as changes (XRA M / ANI 03H); a change of bit 0 counts YAC"},
     {3, false, "bit 3 (08H) chooses YINC or YDEC: 1 = Y moving + (RECONSTRUCTION.md, E10)"}},
    {ToolAxis::Z,
     {4, true, "Z is on the missing pages: the next free bit (firmware/thesis ZPUL)"},
     {5, true, "Z is on the missing pages: the next free bit (firmware/thesis ZDIR)"},
     {4, true, "Z is open loop in the firmware: its transducer on the next free bits"},
     {5, true, "as bit 4"}},
}};

// The undriven 8155 inputs (nothing on the board drives them): pulled up, so ports A and B read
// FFH and the six-bit port C reads 3FH.
inline constexpr std::uint8_t kUndrivenPortAB = 0xFF;
inline constexpr std::uint8_t kUndrivenPortC = 0x3F;

constexpr const IoRegion& io_region(Device d) {
    for (const auto& r : kIoMap)
        if (r.device == d) return r;
    return kIoMap[0];
}
constexpr CpuPin pin_of(Source s) {
    for (const auto& w : kInterruptWiring)
        if (w.source == s) return w.pin;
    return CpuPin::ResetIn;
}

// T-states of a duration on the board's clock, rounded to the nearest, and back: the one
// conversion between simulated time and milliseconds (scripts, reports, tests).
constexpr std::uint64_t tstates_from_ms(double ms) { return static_cast<std::uint64_t>(ms * kCpuHz / 1000.0 + 0.5); }
constexpr double ms_from_tstates(std::uint64_t t) { return static_cast<double>(t) * 1000.0 / kCpuHz; }

}  // namespace alp85::board
