// A board as data: what sits where on the bus, how the chips decode their addresses, who drives
// which CPU input, the keypad, the display, the clock and the options. The Machine is built from
// one description (Machine::Options::board); the debugger's `info board` and docs describe the board
// from it. Each board is a constexpr table in code (emu/board/alp85.h, emu/board/sdk85.h), not a
// file: it is checked when ALP85 is compiled, there is nothing to find or parse at run time, and
// the web build has no file system (docs/board.md).
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <string_view>

#include "peripherals/keypad.h"
#include "peripherals/machine_tool.h"

namespace alp85::board {

// What a memory region is for the Machine's storage (Machine::storage): its own EPROM or RAM, or
// the memory inside a chip (an 8155's 256 bytes of RAM, an 8355's 2 KB of ROM).
enum class Memory : std::uint8_t { MonitorEprom, UserEprom, Ram, Ram8155, ExpansionEprom, ExpansionRom, Ram8155Expansion, Rom8355 };
enum class MemoryKind : std::uint8_t { Rom, Ram };

struct MemoryRegion {
    Memory id;
    std::uint16_t base;
    std::uint16_t size;
    MemoryKind kind;
    std::string_view name;   // short name for scripts and the debugger
    std::string_view part;   // the part that sits there
    std::string_view tag = {};       // its snapshot section; empty: the RAM of a chip, saved with the chip
    std::uint16_t decoded = 0;       // the block the decoder selects (mirrors of the region); 0: size
    std::string_view option = {};    // fitted only with this board option; empty: always
    std::string_view evidence = {};  // why it is there
    constexpr std::uint32_t span() const { return decoded ? decoded : size; }
};

// The chips a board may carry; `unit` tells two of one kind apart (the SDK-85's second 8155).
enum class Device : std::uint8_t { Kdc8279, Rio8155, Rom8355 };
enum class Space : std::uint8_t { Io, Memory };

// A chip in I/O or memory space on addresses first..last: the chip sees as its register number
// the address lines in `select`, packed (0x0001: A0 alone; 0x0007: A0-A2; 0x0100: A8 alone).
struct DeviceRegion {
    Device device;
    std::uint8_t unit;
    Space space;
    std::uint16_t first;
    std::uint16_t last;
    std::uint16_t select;
    std::string_view name;
    std::string_view registers;     // how the chip's address lines see the addresses
    std::string_view option = {};   // fitted only with this board option; empty: always
    constexpr std::uint8_t offset(std::uint16_t address) const {
        if (select == 0) return 0;
        const unsigned low = static_cast<unsigned>(std::countr_zero(select));
        if (const unsigned run = select >> low; (run & (run + 1)) == 0)  // adjacent lines (every board so far)
            return static_cast<std::uint8_t>((address & select) >> low);
        unsigned out = 0, bit = 0;
        for (unsigned line = 0; line < 16; ++line)
            if (select >> line & 1u) out |= ((address >> line) & 1u) << bit++;
        return static_cast<std::uint8_t>(out);
    }
};

enum class Source : std::uint8_t { Irq8279, TimerOut8155, VectIntrKey, ResetKey };
enum class CpuPin : std::uint8_t { Rst55, Trap, Rst75, ResetIn };

// Who drives which CPU input. The Machine connects exactly these (Machine::wire).
struct Wire {
    Source source;
    CpuPin pin;
    std::string_view why;
};

// How a key reaches the CPU: through the 8279's matrix, or wired to a CPU pin.
enum class KeyWire : std::uint8_t { Matrix, ResetIn, VectIntr };

// One key of the keypad: where it is wired, what its cap says, where it sits on the front panel
// and which PC keys press it (the first is shown under the cap; "" ends the list).
struct BoardKey {
    KeyWire wire;
    periph::Key key;       // for KeyWire::Matrix
    std::string_view name;  // stable name for scripts and front ends
    std::string_view cap;   // the caption, '\n' between its lines
    std::uint8_t scan = 0, ret = 0;           // matrix: scan line (SL0-2 value) and return line RL0-7
    std::uint8_t panel_row = 0, panel_col = 0;  // front view, row 0 on top, column 0 on the left
    std::array<std::string_view, 3> pc = {};    // PC key names (browser names too)
    std::string_view pc_label = {};             // shown under the cap
};

// A key in the matrix, its PC keys' first name shown under the cap unless pc_label says otherwise.
constexpr BoardKey matrix_key(periph::Key k, std::string_view name, std::string_view cap, std::uint8_t scan,
                              std::uint8_t ret, std::uint8_t row, std::uint8_t col,
                              std::array<std::string_view, 3> pc = {}, std::string_view pc_label = {}) {
    return {KeyWire::Matrix, k, name, cap, scan, ret, row, col, pc, pc_label.empty() ? pc[0] : pc_label};
}

// RESET and VECT INTR, outside the matrix on both boards: wired to RESET IN and to RST 7.5, at the
// top left of the panel, pressed by Esc and V.
inline constexpr BoardKey kResetKey{KeyWire::ResetIn, periph::Key::K0, "RESET", "RESET", 0, 0, 0, 0, {"Esc", "Escape"}, "Esc"};
inline constexpr BoardKey kVectIntrKey{KeyWire::VectIntr, periph::Key::K0, "VECT", "VECT\nINTR", 0, 0, 0, 1, {"V"}, "V"};

// The sixteen hex keys as both boards have them, in the manner of Intel's SDK-85: key N on scan
// line N / 8 and return line N % 8 (FIFO code N, before SHIFT and CNTL), on the panel a 4 x 4 block
// from column `first_col`, 0-3 on the bottom row and C-F on the top; each pressed by the PC key of
// its own digit.
constexpr std::array<BoardKey, 16> hex_keys(std::uint8_t first_col) {
    constexpr std::array<std::string_view, 16> kDigit{"0", "1", "2", "3", "4", "5", "6", "7",
                                                      "8", "9", "A", "B", "C", "D", "E", "F"};
    std::array<BoardKey, 16> keys{};
    for (std::uint8_t n = 0; n < 16; ++n)
        keys[n] = matrix_key(static_cast<periph::Key>(n), kDigit[n], kDigit[n], n / 8, n % 8,
                             static_cast<std::uint8_t>(3 - n / 4), static_cast<std::uint8_t>(first_col + n % 4),
                             {kDigit[n]});
    return keys;
}

// A board's keypad: its own keys (RESET, VECT INTR, the function keys), then the hex keys.
template <std::size_t N>
constexpr std::array<BoardKey, N + 16> with_hex_keys(const std::array<BoardKey, N>& own, std::uint8_t first_col) {
    std::array<BoardKey, N + 16> keys{};
    const std::array<BoardKey, 16> hex = hex_keys(first_col);
    for (std::size_t i = 0; i < N; ++i) keys[i] = own[i];
    for (std::size_t i = 0; i < 16; ++i) keys[N + i] = hex[i];
    return keys;
}

// The display: which 8279 display position each digit shows (leftmost first), which display-RAM
// bit drives each segment (a, b, c, d, e, f, g, dp; RAM bits 7-4 = OUT A3-A0, 3-0 = OUT B3-B0)
// and whether a segment lights at 0 (drivers that invert).
struct DisplayWiring {
    std::uint8_t digits;
    std::array<std::uint8_t, 8> position;
    std::array<std::uint8_t, 8> segment_bit;
    bool active_low;
    std::string_view evidence;
};

// Board options a script or front end may switch on, by name (script `option NAME on|off`).
struct BoardOption {
    std::string_view name;
    std::string_view what;
};

// The machine tool on an 8155's ports (docs/machine.md): per axis the sequencer's PULSE and
// DIRECTION on port A (output) and the transducer's COUNT and DIRECTION bits on port B (input).
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
    ToolBit pulse, direction;        // port A, outputs
    ToolBit count, count_direction;  // port B, inputs
};

struct Clock {
    std::uint32_t crystal_hz;  // on X1/X2; the 8085 divides by two
    std::string_view evidence;
    constexpr std::uint32_t cpu_hz() const { return crystal_hz / 2; }
};

struct Board {
    std::string_view name;   // for --board and the script's `board`
    std::string_view title;
    Clock clock;
    std::span<const MemoryRegion> memory;   // every region, the optional ones too
    std::span<const DeviceRegion> devices;  // every chip's decoding, the optional ones too
    std::span<const Wire> wiring;
    std::span<const BoardKey> keys;
    DisplayWiring display;
    std::span<const BoardOption> options;
    bool shift_cntl_high;                  // the 8279's SHIFT and CNTL/STB pins: tied high, or grounded
    std::span<const AxisWiring> tool;      // the machine tool on the first 8155; empty: none
    std::uint8_t undriven_port_ab;         // what the 8155's undriven port A/B pins read
    std::uint8_t undriven_port_c;          // and its six port C pins
    // The serial terminal's line on SOD: true where the board's line driver inverts SOD (the line
    // is high, at mark, while SOD is low). SID always follows the line.
    bool sod_inverted = false;
    // The monitor ROM and the firmware alp85 carries built in (emu/program) are this board's: they
    // boot it by default and --rom is refused. Otherwise the ROM at reset is the user's (--rom).
    bool builtin_firmware = false;
};

// The ROM the 8085 starts in after RESET (at 0000H: the ALP 85's monitor EPROM, the SDK-85's 8355),
// where a user's ROM (--rom) goes; nullptr if the board has none there.
constexpr const MemoryRegion* rom_at_reset(const Board& b) {
    for (const MemoryRegion& r : b.memory)
        if (r.base == 0 && r.kind == MemoryKind::Rom) return &r;
    return nullptr;
}

constexpr bool has_option(const Board& b, std::string_view name) {
    for (const BoardOption& o : b.options)
        if (o.name == name) return true;
    return false;
}

}  // namespace alp85::board
