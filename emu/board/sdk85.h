// Intel's MCS-85 System Design Kit (SDK-85, 1977) as a board description: the same 8155 and 8279
// as the ALP 85, memory-mapped keyboard/display, six digits, a 24-key pad. Sources: the SDK-85
// User's Manual (Intel 9800451; [UM] below: its memory and I/O address assignment, the 8205
// chip-select decoder, the interrupt lines and the keyboard/display schematic) and the 8155, 8279
// and 8355 data sheets. The manual's pages were not at hand here: every [UM] fact below was checked
// against the behaviour of MAME's sdk85 driver, which runs Intel's monitor (its address map, its
// key matrix, its segment wiring); docs/board.md says which facts rest on that alone.
//
// Address decoding [UM]: an 8205 decodes A11-A13 into 2 KB blocks, one chip select each
// (0: 8355 monitor ROM, 1: 8755A expansion ROM, 3: 8279, 4: 8155, 5: the second 8155). For I/O the
// 8085 puts the port number on A8-A15 as well, so the same decoder selects the chips' ports: block
// 4 is ports 20H-27H, block 5 ports 28H-2FH. Inside a block the chips decode only their own lines:
// the 8155 AD0-AD7 (256 bytes of RAM, or AD0-AD2 as register number), the 8279 its A0 pin, which
// the SDK-85 wires to A8, so in block 3 every even page is the 8279's data and every odd page its
// command/status (1800H and 1900H are the addresses the manual gives; the rest are mirrors).
#pragma once

#include <array>
#include <cstdint>

#include "emu/board/board_description.h"

namespace alp85::board::sdk85 {

inline constexpr std::array<MemoryRegion, 4> kMemory{{
    // The 8355's own ROM; the board saves it with its memories (snapshot section MON).
    {Memory::Rom8355, 0x0000, 0x0800, MemoryKind::Rom, "monitor", "2 KB monitor ROM (8355, chip select 0)", "MON ", 0,
     {}, "[UM] 0000H-07FFH; the 8085 starts at 0000H"},
    {Memory::ExpansionRom, 0x0800, 0x0800, MemoryKind::Rom, "expansion", "2 KB expansion ROM socket (8755A, chip select 1)",
     "EXPR", 0, {}, "[UM] 0800H-0FFFH; an empty socket reads FFH, as an erased part does"},
    // The 8155 sees AD0-AD7 only: its 256 bytes repeat through the 2 KB block the 8205 selects.
    {Memory::Ram8155, 0x2000, 0x0100, MemoryKind::Ram, "ram8155", "8155 RAM, IO/M low (chip select 4)", {}, 0x0800, {},
     "[UM] 2000H-20FFH; mirrors through 27FFH (A8-A10 not decoded)"},
    {Memory::Ram8155Expansion, 0x2800, 0x0100, MemoryKind::Ram, "ram8155b", "second 8155's RAM (optional, chip select 5)",
     {}, 0x0800, "ram2", "[UM] 2800H-28FFH, the RAM expansion socket; mirrors through 2FFFH"},
}};

inline constexpr std::array<BoardOption, 1> kOptions{{
    {"ram2", "the second 8155 (RAM 2800H-28FFH, ports 28H-2DH) in the expansion socket, empty on the kit as sold"},
}};

inline constexpr std::array<DeviceRegion, 4> kDevices{{
    {Device::Kdc8279, 0, Space::Memory, 0x1800, 0x1FFF, 0x0100, "8279",
     "memory-mapped, A0 = A8: 1800H data, 1900H command/status (even/odd pages of 1800H-1FFFH mirror them)"},
    // Ports 26H/27H also select the chip (AD2-AD0 = 110/111), registers the data sheet does not
    // define; they are left unmapped (read FFH) rather than given behaviour no document describes.
    {Device::Rio8155, 0, Space::Io, 0x20, 0x25, 0x0007, "8155",
     "AD0-AD2 = port - 20H: 20H command/status, 21H port A, 22H port B, 23H port C, 24H timer low, 25H timer high"},
    {Device::Rio8155, 1, Space::Io, 0x28, 0x2D, 0x0007, "8155b",
     "the second 8155: 28H command/status, 29H-2BH ports A-C, 2CH-2DH timer", "ram2"},
    // The monitor ROM's 8355 decodes AD1-AD0 (8355 data sheet); the 8205's block 0 is ports
    // 00H-07H, so 04H-07H would mirror these: left unmapped, as the manual lists 00H-03H.
    {Device::Rom8355, 0, Space::Io, 0x00, 0x03, 0x0003, "8355",
     "AD1-AD0: 00H port A, 01H port B, 02H port A's direction, 03H port B's direction"},
}};

// The keypad [UM]: scan lines SL0-2 (encoded, decoded on the
// board) select three rows; row 0 carries 0-7 on RL0-7, row 1 8-F, row 2 EXEC, NEXT, GO, SUBST
// MEM, EXAM REG, SINGLE STEP on RL0-5. RESET and VECT INTR are wired to the CPU. The 8279's SHIFT
// and CNTL/STB inputs are tied high, so FIFO codes carry 1 in bits 7 and 6 (C0H | row * 8 + RL).
// The panel, front view (four rows of six keys, the function keys on the left):
//   RESET        VECT INTR  C D E F
//   SINGLE STEP  GO         8 9 A B
//   SUBST MEM    EXAM REG   4 5 6 7
//   NEXT ,       EXEC .     0 1 2 3
using periph::Key;
inline constexpr std::array<BoardKey, 24> kKeys = with_hex_keys<8>({{
    kResetKey,
    kVectIntrKey,
    matrix_key(Key::Step, "STEP", "SINGLE\nSTEP", 2, 5, 1, 0, {"S", "/"}),
    matrix_key(Key::Go, "GO", "GO", 2, 2, 1, 1, {"G"}),
    matrix_key(Key::Mem, "MEM", "SUBST\nMEM", 2, 3, 2, 0, {"M"}),
    matrix_key(Key::Reg, "REG", "EXAM\nREG", 2, 4, 2, 1, {"X"}),
    matrix_key(Key::Next, "NEXT", "NEXT\n,", 2, 1, 3, 0, {"Space", " ", ","}, "Space"),
    matrix_key(Key::Exec, "EXEC", "EXEC\n.", 2, 0, 3, 1, {"Enter", "."}),
}}, 2);  // the hex keys from column 2

// [UM]: the first 8155's TIMER OUT is the monitor's single step, on TRAP; the
// VECT INTR key on RST 7.5; the RESET key on RESET IN. The 8279's IRQ goes to RST 5.5, as on the
// ALP 85 (the monitor reads the keyboard by polling the 8279's status; MAME wires IRQ to RST 5.5).
inline constexpr std::array<Wire, 4> kWiring{{
    {Source::Irq8279, CpuPin::Rst55, "a key in the 8279's FIFO: RST 5.5 (masked by the monitor, which polls)"},
    {Source::TimerOut8155, CpuPin::Trap, "the monitor's single step: the 8155's timer traps after one user instruction"},
    {Source::VectIntrKey, CpuPin::Rst75, "the VECT INTR key (rising edge latched by the 8085)"},
    {Source::ResetKey, CpuPin::ResetIn, "the RESET key resets the CPU, and RESET OUT the 8155, 8279 and 8355"},
}};

// Six digits, 8279 display positions 0-5, leftmost first: four of address, two of data [UM].
// Segment wiring [UM schematic]: OUT A0-A3 (display RAM bits 4-7) drive segments a-d, OUT B0-B3
// (RAM bits 0-3) segments e, f, g and dp, through inverting drivers: a segment lights where its
// display-RAM bit is 0. MAME's driver, which shows Intel's monitor's digits, decodes the 8279's
// outputs (the display RAM as it is) so: inverted, then this bit order.
inline constexpr DisplayWiring kDisplay{
    6, {0, 1, 2, 3, 4, 5, 0, 0}, {4, 5, 6, 7, 0, 1, 2, 3}, true,
    "A0-A3 = a-d, B0-B3 = e, f, g, dp, lit at 0 in display RAM; digits 0-3 address, 4-5 data"};

// [UM]: a 6.144 MHz crystal; the 8085 runs at 3.072 MHz (325.5 ns per T-state),
// which is also the 8155's TIMER IN and the 8279's CLK (CLK OUT).
inline constexpr Clock kClock{6'144'000, "[UM] 6.144 MHz crystal, 3.072 MHz 8085"};
inline constexpr bool kShiftCntlHigh = true;  // SHIFT and CNTL/STB tied high
// The undriven 8155 inputs read as the ALP 85's (pulled up); no machine tool: the ports are the user's.
inline constexpr std::uint8_t kUndrivenPortAB = 0xFF, kUndrivenPortC = 0x3F;
// The TTY interface [UM, TTY interface; converter circuit for an RS-232C port]: SOD drives the
// 20 mA loop through one transistor, which inverts it; the receive side turns the loop's
// current into SID high (mark) without inverting. MAME's driver inverts SOD likewise.
inline constexpr bool kSodInverted = true;
// Its ROM is the user's (--rom: Intel's monitor, or a program of theirs), not alp85's built-in monitor.
inline constexpr bool kBuiltinFirmware = false;

}  // namespace alp85::board::sdk85

namespace alp85::board {

inline constexpr Board kSdk85{"sdk85", "SDK-85", sdk85::kClock, sdk85::kMemory, sdk85::kDevices, sdk85::kWiring,
                              sdk85::kKeys, sdk85::kDisplay, sdk85::kOptions, sdk85::kShiftCntlHigh, {},
                              sdk85::kUndrivenPortAB, sdk85::kUndrivenPortC, sdk85::kSodInverted,
                              sdk85::kBuiltinFirmware};

}  // namespace alp85::board
