// The incremental linear position transducer of one axis (thesis §3.2.4.1, §3.3): a scale of
// equally spaced opaque and transparent lines fixed to the table, scanned by two photocells a
// quarter pitch apart (Figure 3.12: outputs in quadrature), and the direction-discriminating logic
// that gives the microcomputer two bits per axis: COUNT, which changes at each increment of the
// scale, and DIRECTION, the direction of the last movement (§3.3: "It also gives the direction of
// the movement. The physical position values are determined by software counts").
//
// Pins as modelled: COUNT, DIRECTION -> outputs(); photocells A, B -> photocells() (for views).
// Input: the table's REAL position (mm), so a lost step or the rotor's ringing gives real edges,
// back and forth.
//
// The scale: pitch p (default 0.05 mm = one step: the thesis's resolution is 0.05 mm and the
// firmware counts one increment per step), lines offset `offset_mm` from the step positions.
// Photocell levels for u = (x - offset)/p: the quadrature state q = floor(4u) mod 4 gives
//   q:      0   1   2   3
//   (A,B): 11  01  00  10          (1 = illuminated)
// so moving in + (Table 3.3, "clockwise") both cells lit are followed by A dark while B is lit,
// exactly as the thesis describes; moving in - the sequence runs backwards. (Table 3.3's other
// column, 11 -> 00, belongs to the specially coded disc of Figure 3.13, not to a quadrature pair.)
//
// The logic: a transition to the next state latches DIRECTION = +, to the previous one DIRECTION =
// -; COUNT toggles at each crossing between states 3 and 0, i.e. once per pitch, at the scale lines
// x = offset + k p. Default offset p/2: the lines sit half-way between step positions, so a table
// at rest on a step is as far as it can be from an edge (no flicker at rest) and each step crosses
// exactly one line, in its middle. The rotor's overshoot after a step crosses back only if it
// exceeds half a step.
//
// Polarity (which level of DIRECTION means +) is a parameter until the firmware reconstruction
// settles it. COUNT starts at the parity of the line index of the power-on position.
//
// Not emulated: photocell analogue levels, thresholds and hysteresis, the Moire fringe variant,
// electrical noise, a limit on the counting rate (the logic follows any edge rate), a skipped
// quadrature state (two cells changing at once: ignored — cannot happen at the simulated speeds).
#pragma once

#include <cstdint>

namespace alp85::periph {

class Transducer {
public:
    struct Params {
        double pitch_mm = 0.05;
        double offset_mm = 0.025;               // scale lines relative to step positions (p/2)
        bool direction_high_is_positive = true; // DIRECTION level for a + move
    };

    struct State {
        std::int64_t q = 0;       // absolute quadrature state index floor(4 (x - offset) / p)
        std::int64_t count = 0;   // signed increments since power-on (+1 per + crossing of a line)
        bool positive = true;     // latched direction of the last transition

        template <class S, class Io>
        static void fields(S& s, Io& io) { io(s.q), io(s.count), io(s.positive); }
    };

    struct Outputs {
        bool count;
        bool direction;
    };

    Transducer() = default;
    explicit Transducer(Params p);

    const Params& params() const { return p_; }
    std::int64_t q_of(double x_mm) const {
        const double v = (x_mm - p_.offset_mm) * quads_per_mm_;
        const auto t = static_cast<std::int64_t>(v);  // toward zero; floor for negatives below
        return t - (v < static_cast<double>(t) ? 1 : 0);
    }
    void init(State& s, double x_mm) const;
    // Walks the discriminator through every quadrature state between the last position and x_mm.
    void update(State& s, double x_mm) const {
        const std::int64_t q = q_of(x_mm);
        if (q != s.q) walk(s, q);
    }
    Outputs outputs(const State& s) const {
        return {((s.q >> 2) & 1) != 0, s.positive == p_.direction_high_is_positive};
    }
    static bool photocell_a(const State& s) { const auto r = s.q & 3; return r == 0 || r == 3; }
    static bool photocell_b(const State& s) { const auto r = s.q & 3; return r == 0 || r == 1; }

private:
    void walk(State& s, std::int64_t q) const;

    Params p_;
    double quads_per_mm_ = 4.0 / 0.05;
};

}  // namespace alp85::periph
