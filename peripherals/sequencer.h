// The stepping-motor sequencer of one axis (thesis Figure 3.10, after [MA]): two inputs, PULSE and
// DIRECTION, and four outputs A, /A, B, /B that switch the four half-windings of the unipolar drive.
//
// Pins as modelled:
//   PULSE      -> set_inputs(pulse, direction): one full step on each ACTIVE edge of PULSE;
//   DIRECTION  -> sampled at that edge: which way the step goes (polarity a parameter);
//   A /A B /B  -> phases(): bit 3 = A, bit 2 = /A, bit 1 = B, bit 0 = /B (1 = transistor on).
//
// Sources: thesis §3.2.3 and Figure 3.10 (the text only: "two inputs and four outputs ... each
// pulse ... makes the motor rotate one step in the determined direction"; the figure itself is not
// legible in our copy) and §3.2.1 ("2-phase full-step hybrid motor").
//
// Full step, TWO phases on: the sequencer's four outputs are the true and complement outputs of two
// flip-flops (A = Q1, /A = /Q1, B = Q2, /B = /Q2), so at every moment exactly one half of each
// winding is on; a step toggles one flip-flop (a Gray sequence). Positive direction:
//   AB -> /A B -> /A /B -> A /B -> AB     (index 0, 1, 2, 3), negative: the reverse.
// With the torque law of stepper_motor.h the equilibrium of index k is k full steps (1.8 deg).
//
// Active edge: RISING by default. The firmware (thesis Appendix listing, OUT subroutine) writes the
// direction bit first, then direction|pulse, holds it one DL delay and drops the pulse for another
// DL: the direction is stable well before the rising edge and the step then starts at the start of
// the high period, which is how §4.4.5 describes it ("each pulse ... makes the motor take one step").
// Both edges see a stable direction, so the edge is a parameter (falling also supported).
//
// Not emulated: the flip-flops' power-up state (index 0 is assumed), propagation delays, set-up and
// hold times, noise on the lines; the half-step mode (the thesis motor is driven full step only).
#pragma once

#include <cstdint>

namespace alp85::periph {

class Sequencer {
public:
    enum class Edge : std::uint8_t { Rising, Falling };

    struct Params {
        Edge active_edge = Edge::Rising;
        bool direction_high_is_positive = true;  // DIRECTION = 1 steps toward +count
    };

    struct State {
        std::int64_t count = 0;  // signed steps commanded since power-on (the flip-flops' index = count mod 4)
        bool pulse = false;      // last PULSE level
        bool direction = false;  // last DIRECTION level

        template <class S, class Io>
        static void fields(S& s, Io& io) { io(s.count), io(s.pulse), io(s.direction); }
    };

    // Phase bits for each index (positive order).
    static constexpr std::uint8_t kA = 8, kAbar = 4, kB = 2, kBbar = 1;
    static constexpr std::uint8_t kPattern[4] = {kA | kB, kAbar | kB, kAbar | kBbar, kA | kBbar};

    Sequencer() = default;
    explicit Sequencer(Params p) : p_(p) {}

    // Applies new input levels; returns +1 or -1 when a step was taken, 0 otherwise.
    int set_inputs(State& s, bool pulse, bool direction) const;

    static int index(const State& s) { return static_cast<int>(s.count & 3); }
    static std::uint8_t phases(const State& s) { return kPattern[index(s)]; }

    const Params& params() const { return p_; }

private:
    Params p_;
};

}  // namespace alp85::periph
