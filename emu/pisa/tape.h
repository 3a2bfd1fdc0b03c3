// Tapes for the Pisa interpolator: the word-address block format of the period (EIA RS-274 as
// used in the late 1960s) read from a text file, checked, and turned into the words the tape
// reader delivers (tape_reader.h) and the elements they describe.
//
//   N010 G01 X+050000 Y-012500 F0600     one block a line; words in any order, each at most once
//   N020 G02 X60.5 Y0 I10 J0              digits alone: µm (format 3.3, implied point); with a '.': mm
//   ( a comment )  ; a comment            lines starting with % (rewind stop) and blank ones are skipped
//
// N sequence number (3 digits); G 00 rapid line, 01 line, 02 clockwise arc, 03 counter-clockwise
// arc (modal); X Y the end point, absolute from program zero (where the tool stands at the start),
// modal; I J the arc's centre relative to its start point (0 when absent); F the feedrate in
// mm/min (4 digits, modal). On tape each word is punched in fixed format: the letter, a sign for
// X Y I J, then N 3, G 2, X Y I J 6, F 4 digits; a block ends with the end-of-block character.
//
// Refused, with the line and column, before anything runs: see TapeLimits and docs/pisa.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/pisa/tape_reader.h"

namespace alp85::pisa {

// What the ROM program can do (docs/pisa.md "Limits"): checked on the host so that a tape the
// program would misread is refused with its line and column instead.
struct TapeLimits {
    int f_min = 10;          // mm/min: one 6 ms step of 1 µm
    int f_max_line = 1500;   // mm/min: lines and rapids keep up with the 6 ms clock up to here
    int f_max_arc = 1000;    // mm/min: arcs (more instructions per unit step)
    int rapid = 1500;        // G00's feedrate (in the ROM program)
    std::int64_t min_radius_um = 1000;
    // Program zero on the tables and their travel (docs/machine.md): the path must stay in it.
    double start_x_mm = 750.0, start_y_mm = 100.0;
    double travel_x_mm = 1500.0, travel_y_mm = 200.0;
};

// The arc program's near-end window (µm, Manhattan) for a feedrate: 2 (F/10 + 1) + 4, as the ROM
// computes it; an arc whose end is not a full circle must start outside it.
std::int64_t near_limit_um(int feed);

struct Element {
    enum class Kind : std::uint8_t { Rapid, Line, Cw, Ccw };
    Kind kind = Kind::Line;
    std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // µm from program zero
    std::int64_t cx = 0, cy = 0;                  // arcs: the centre
    int feed = 0;                                 // mm/min (rapid: TapeLimits::rapid)
    int line = 0;                                 // block's line in the file
    bool arc() const { return kind == Kind::Cw || kind == Kind::Ccw; }
};

struct TapeError {
    int line = 0;
    int col = 0;
    std::string message;
};

struct Tape {
    std::vector<TapeWord> words;      // as the reader delivers them, blocks closed by end of block
    std::vector<Element> elements;    // the moves (zero-length lines included)
    int blocks = 0;
};

struct ParsedTape {
    Tape tape;
    std::optional<TapeError> error;
};

ParsedTape parse_tape(std::string_view text, const TapeLimits& limits = {});

// The exact path the elements describe, as points in mm from program zero (arcs at 1/200 turn at
// most): for plots.
struct PointMm {
    double x = 0, y = 0;
};
std::vector<PointMm> ideal_path_mm(const Tape& tape);

}  // namespace alp85::pisa
