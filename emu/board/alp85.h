// The ALP 85 as a board description (emu/board/board_description.h): the thesis machine.
//
// Evidence (docs/board.md has the full argument): thesis Chapter II gives the parts (2 KB monitor
// EPROM, 2 KB user EPROM, 4 KB RAM, 8155, 8279); the listing in Appendix B fixes the rest:
// ORG 0800H, variables at 1B00H-1B54H, LXI SP,20B0H, IN 0FAH / OUT 0F9H, OUT 0E1H at MAIN.
#pragma once

#include <array>
#include <cstdint>

#include "emu/board/board_description.h"

namespace alp85::board::alp85 {

inline constexpr std::array<MemoryRegion, 5> kMemory{{
    {Memory::MonitorEprom, 0x0000, 0x0800, MemoryKind::Rom, "monitor", "2 KB monitor EPROM (2716)", "MON ", 0, {},
     "the 8085 starts at 0000H; the firmware calls monitor routines at 05A8H-07C7H"},
    {Memory::UserEprom, 0x0800, 0x0800, MemoryKind::Rom, "user", "2 KB user EPROM (2716): the thesis firmware, ORG 0800H",
     "USER", 0, {}, "listing line 4 ORG 0800H; Appendix C S.2.1 (0800H)"},
    {Memory::Ram, 0x1000, 0x1000, MemoryKind::Ram, "ram", "4 KB static RAM (firmware variables at 1B00H)", "RAM ", 0, {},
     "every LDA/STA/LHLD/SHLD of the listing falls in 1B00H-1B54H"},
    {Memory::Ram8155, 0x2000, 0x0100, MemoryKind::Ram, "ram8155", "8155 RAM, IO/M low (firmware stack below 20B0H)", {}, 0,
     {}, "listing line 10 LXI SP,20B0H"},
    // The EPROM expansion of thesis 5.3 ("EPROM memory region of the ALP 85 microcomputer can be
    // expanded with ease to store this master program"): an OPTION, off by default, so the machine
    // as built stays the thesis machine. Where: the map above fills the address space in 4 KB blocks
    // (0xxxH the two 2716s, 1xxxH the RAM, 2xxxH the 8155), so the next free block, 3000H-3FFFH,
    // is where a 2732 (4 KB) on the next decoder output would sit. It holds the master program
    // (3000H-3DCFH, firmware/master) and its path tables (3DD0H-3FFFH, alp85 gcode): docs/contours.md.
    {Memory::ExpansionEprom, 0x3000, 0x1000, MemoryKind::Rom, "expansion",
     "4 KB expansion EPROM (2732, optional): master program and path tables", "EXP ", 0, "expansion",
     "thesis 5.3: the next free 4 KB block"},
}};

inline constexpr std::array<BoardOption, 1> kOptions{{
    {"expansion", "the 4 KB expansion EPROM at 3000H-3FFFH (thesis 5.3), off on the machine as built"},
}};

// Unmapped ports and memory read FFH (a floating, pulled-up data bus).
inline constexpr std::array<DeviceRegion, 2> kDevices{{
    {Device::Kdc8279, 0, Space::Io, 0xE0, 0xE1, 0x0001, "8279", "A0 = port bit 0: E0H data, E1H command/status"},
    {Device::Rio8155, 0, Space::Io, 0xF8, 0xFD, 0x0007, "8155",
     "AD0-AD2 = port - F8H: F8H command/status, F9H port A (motor outputs), FAH port B "
     "(transducer inputs), FBH port C, FCH timer low, FDH timer high"},
}};

inline constexpr std::array<Wire, 4> kWiring{{
    {Source::Irq8279, CpuPin::Rst55, "key in the FIFO: the monitor may read keys by interrupt"},
    {Source::TimerOut8155, CpuPin::Trap, "the monitor's single step: a timer pulse traps after one instruction"},
    {Source::VectIntrKey, CpuPin::Rst75, "the VECT INTR key (rising edge latched by the 8085)"},
    {Source::ResetKey, CpuPin::ResetIn, "the RESET key resets the CPU, and RESET OUT the 8155 and 8279"},
}};

// The keypad. The ALP 85's real key matrix is not documented; this one is a design in the manner
// of Intel's SDK-85: SL0-2 are decoded into eight row lines; rows 0 and 1 carry the hex keys 0-F
// on RL0-7, row 2 the function keys. SHIFT and CNTL are grounded on the board, so a key's 8279
// FIFO code is row * 8 + return line (hex keys 00H-0FH, function keys 10H-17H). RESET and VECT
// INTR are not in the matrix: the board wires them to RESET IN and RST 7.5. The panel, front view
// (docs/peripherals.md):
//   RESET VECT  R    C D E F
//   REG   MEM   GO   8 9 A B
//   STEP  PREV  NEXT 4 5 6 7
//               EXEC 0 1 2 3
using periph::Key;
inline constexpr std::array<BoardKey, 26> kKeys = with_hex_keys<10>({{
    kResetKey,
    kVectIntrKey,
    matrix_key(Key::R, "R", "R", 2, 7, 0, 2, {"R"}),
    matrix_key(Key::Reg, "REG", "EXAM\nREG", 2, 4, 1, 0, {"X"}),
    matrix_key(Key::Mem, "MEM", "SUBST\nMEM", 2, 3, 1, 1, {"M"}),
    matrix_key(Key::Go, "GO", "GO", 2, 2, 1, 2, {"G"}),
    matrix_key(Key::Step, "STEP", "SINGLE\nSTEP", 2, 5, 2, 0, {"S"}),
    matrix_key(Key::Prev, "PREV", "PREV", 2, 6, 2, 1, {"Backspace"}, "Bksp"),
    matrix_key(Key::Next, "NEXT", "NEXT", 2, 1, 2, 2, {"Space", " "}, "Space"),
    matrix_key(Key::Exec, "EXEC", "EXEC", 2, 0, 3, 2, {"Enter"}),
}}, 3);  // the hex keys from column 3

// Eight digits on the 8279's display positions 0-7, leftmost first. Segment wiring inferred from
// the thesis's segment codes (76H = H, 6EH = y, 78H = t, 7FH = B/8): bit0 = a, bit1 = b, bit2 = c,
// bit3 = d, bit4 = e, bit5 = f, bit6 = g, bit7 = dp, active high.
inline constexpr DisplayWiring kDisplay{
    8, {0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}, false,
    "thesis segment codes 76H = H, 6EH = y, 78H = t, 7FH = B/8: bit0 = a ... bit6 = g, bit7 = dp, lit at 1"};

// The machine tool on the 8155's ports (docs/machine.md, firmware/thesis/RECONSTRUCTION.md): per
// axis the sequencer's PULSE and DIRECTION on port A (F9H, output) and the transducer's COUNT bit
// (changes level at each increment) and DIRECTION bit (1 = moving +) on port B (FAH, input).
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

// The board's clock: a 6.144 MHz crystal on X1/X2; the 8085 divides by two. CLK OUT (3.072 MHz,
// one pulse per T-state) drives the 8155's TIMER IN and the 8279's CLK. The firmware's DL loop
// takes 3070 T-states: 0.999 ms at 3.072 MHz, the millisecond its arithmetic assumes.
inline constexpr Clock kClock{6'144'000, "thesis firmware's DL loop: 3070 T-states = 0.999 ms at 3.072 MHz"};
// SHIFT and CNTL/STB grounded (docs/peripherals.md): key codes carry 0 there.
inline constexpr bool kShiftCntlHigh = false;
// The ALP 85's SOD drives no inverting line driver; the monitor and firmware alp85 carries are its own.
inline constexpr bool kSodInverted = false;
inline constexpr bool kBuiltinFirmware = true;
// The undriven 8155 inputs (nothing on the board drives them): pulled up, so ports A and B read
// FFH and the six-bit port C reads 3FH.
inline constexpr std::uint8_t kUndrivenPortAB = 0xFF, kUndrivenPortC = 0x3F;

}  // namespace alp85::board::alp85

namespace alp85::board {

inline constexpr Board kAlp85{"alp85", "ALP 85 (METU 1985 thesis machine)", alp85::kClock, alp85::kMemory,
                              alp85::kDevices, alp85::kWiring, alp85::kKeys, alp85::kDisplay, alp85::kOptions,
                              alp85::kShiftCntlHigh, alp85::kToolWiring, alp85::kUndrivenPortAB, alp85::kUndrivenPortC,
                              alp85::kSodInverted, alp85::kBuiltinFirmware};

}  // namespace alp85::board
