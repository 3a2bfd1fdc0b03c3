// The path table the master program (firmware/master/master.asm) walks, as data: entries of 16
// bytes in the expansion EPROM from 3DD0H (docs/contours.md has the layout and why).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace alp85::gcode {

inline constexpr std::uint16_t kTableBase = 0x3DD0;  // the last 560 bytes of board::kExpansionEprom (35 entries)
inline constexpr std::uint16_t kTableSize = 0x0230;
inline constexpr std::size_t kEntrySize = 16;

// The machine tool's travel in steps of 0.05 mm (docs/machine.md: X 1500, Y 200, Z 100 mm),
// counted from the power-on position as the firmware counts.
inline constexpr double kMmPerStep = 0.05;
inline constexpr std::int32_t kTravel[3] = {30000, 4000, 2000};

// Sample: a sampling group's header (docs/contours.md "Sampling"): cr = flags (bit 0 ramp), feed =
// F_s (steps a 2 ms sample, 0.16), x, y = the group's length to its stop point (16.16: x the
// fraction, y whole steps), less a margin. A path that opens with one runs by sampling.
enum class Kind : std::uint8_t { End = 0, Rapid = 1, Line = 2, ArcCw = 3, ArcCcw = 4, Sample = 5 };

struct Entry {
    Kind kind = Kind::End;
    std::uint8_t cr = 0;          // arcs: C_R, the segment angle is 2^-C_R rad
    std::uint16_t feed = 0;       // mm/min (rapid: 1500, the firmware's fastest)
    std::uint16_t x = 0, y = 0, z = 0;  // end point, steps
    std::uint16_t cx = 0, cy = 0;       // arcs: centre, steps
    std::uint16_t n = 0;          // arcs: whole 2^-C_R segments before the last (shorter) one
    // Host side only (not in the table): the radius in steps, for the bounds.
    double radius = 0;
};

// The table's bytes: every path's entries followed by an End entry, paths one after another.
std::vector<std::uint8_t> table_bytes(const std::vector<std::vector<Entry>>& paths);
// Intel HEX of bytes placed at `base` (16 bytes a record, then the EOF record).
std::string intel_hex(std::uint16_t base, const std::vector<std::uint8_t>& bytes);

}  // namespace alp85::gcode
