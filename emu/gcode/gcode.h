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

struct Parsed {
    std::vector<Entry> entries;
    std::optional<Error> error;
};

Parsed parse(std::string_view text);

// Watanabe and Iwai's eq. 9: the chord of a 2^-C_R rad segment strays at most
// eps_A = 2^(-2 C_R - 4) R from the arc (with the first point pushed out by eps_A).
double eps_a(int cr, double radius);
// The coarsest C_R (at least 1) whose eps_A is within one step, 0.05 mm: the fewest segments.
int choose_cr(double radius_steps);

}  // namespace alp85::gcode
