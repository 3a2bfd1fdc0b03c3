// The RS-274 (G-code) subset a contour for the ALP 85 needs, to path-table entries
// (docs/contours.md): G00 G01 G02 G03 with X Y Z I J R, F, G20/G21, G90/G91, N line numbers,
// ( ) and ; comments, a % line. Anything else, or a point outside the table's travel, is an error
// with its line and column; the caller then writes nothing.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/gcode/path_table.h"

namespace alp85::gcode {

struct Error {
    int line = 0;
    int column = 0;  // 1-based, of the offending word or character
    std::string message;
};

// How the master draws a path's segments: the thesis's line routine (one axis at a time, the
// default) or Watanabe and Iwai's sampling interpolation. A file chooses with a comment
// (METHOD THESIS) / (METHOD SAMPLING), and (RAMP OFF) / (RAMP ON) for sampling's feed ramp.
enum class Method : std::uint8_t { Thesis, Sampling };

struct Parsed {
    std::vector<Entry> entries;
    std::optional<Error> error;
    std::optional<Method> method;  // from a (METHOD ...) comment
    std::optional<bool> ramp;      // from a (RAMP ...) comment
};

Parsed parse(std::string_view text);

// Watanabe and Iwai's eq. 9: the chord of a 2^-C_R rad segment strays at most
// eps_A = 2^(-2 C_R - 4) R from the arc (with the first point pushed out by eps_A).
double eps_a(int cr, double radius);
// The coarsest C_R (at least 1) whose eps_A is within one step, 0.05 mm: the fewest segments.
int choose_cr(double radius_steps);

// Sampling: a corner whose tangent turns by more than this stops the tool (the ramp down and up
// again). 0.5 rad is the turn between the chords of an arc at C_R = 1; at 1500 mm/min (500
// steps/s) an axis's speed then jumps by at most 2 . 500 . sin 0.25 = 247 steps/s, below the
// motor's start-stop limit (405 steps/s, docs/machine.md).
inline constexpr double kCornerRad = 0.5;
// A path's entries for the sampling method: a header (Kind::Sample) before the first entry and at
// every stop point (a Z move, a change of feed or between rapid and feed moves, a corner sharper
// than kCornerRad), each with its group's feed and length.
std::vector<Entry> sampling_path(const std::vector<Entry>& path, bool ramp);

}  // namespace alp85::gcode
