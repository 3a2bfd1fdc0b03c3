// The stepping motor of one axis, PH265-03 (thesis Table 3.2), on the unipolar voltage drive of
// thesis §3.2.2.1, with the table's load. Two models, chosen per run (MachineTool::set_model):
//
//   Ideal     each sequencer step turns the rotor exactly one step (1.8 deg) at that T-state.
//   Physical  a two-phase hybrid stepper, 50 rotor teeth (N = 50, 200 full steps per revolution):
//
//   Electrical, per half-winding j in {A, /A, B, /B} (centre-tapped windings, unipolar drive):
//     on  (transistor saturated):  L di/dt = Vs - Vce - (r + R) i - e_j                  (eq. 3.1)
//     off (freewheeling diode):    L di/dt = -Vd - (r + R + Rf) i - e_j,   i >= 0         (§3.2.2.1)
//   with back-EMF e_A = -Ke w sin x, e_/A = -e_A, e_B = Ke w cos x, e_/B = -e_B, where
//   x = N theta + pi/4 (theta = 0 is the equilibrium of the sequencer's index 0, A and B on).
//   Vs follows eq. 3.1 with the rated current: Vs = I (r + R).
//
//   Mechanical:  J dw/dt = Kt [ -(iA - i/A) sin x + (iB - i/B) cos x ]      (phase torques)
//                          - Td sin 4x                                     (detent, stable at
//                                                                           one-phase-on positions)
//                          - b w - Tc sgn w                                (viscous, Coulomb + stiction)
//                J = J_rotor + J_load (table mass reflected through 10 mm/rev, table.h).
//   Kt = Ke = T_hold / (sqrt 2 I_rated): two phases at rated current give the holding torque.
//   Small-signal stiffness about a two-phase-on equilibrium: k = N (T_hold I/I_rated - 4 Td);
//   the rotor rings at sqrt(k/J)/2pi, damped by the back-EMF (Kt^2/(r+R)) and friction.
//
// Integration (deterministic, in T-states of the clock its builder gives: the ALP 85's 3.072 MHz): a fixed grid of H T-states
// anchored at the last input change, split exactly at each phase change. Each step is a
// drift-kick-drift (position Verlet) step: the rotor drifts half a step; there the currents advance
// by the EXACT solution of their linear ODE with the back-EMF frozen at its midpoint value
// (i -> i_inf + (i - i_inf) exp(-h/tau), clamped at zero when a diode or transistor blocks; the
// torque uses the exponential's exact mean over the step); the rotor is kicked with that torque
// (Coulomb friction with stiction) and drifts the other half. Because the electrical part is solved
// exactly, the electrical time constant (L/R = 126 us on, 20 us freewheeling) bounds neither
// stability nor the step: the step only has to keep the EMF (the electro-mechanical coupling)
// nearly constant across it, so H is set to one electrical time constant, H = 384 T-states =
// 125 us ~ L/R. The mechanics are slow beside it (loaded ringing ~14 ms = 112 steps; rotor alone
// ~4.6 ms = 37 steps; at 500 steps/s the electrical angle moves 0.1 rad per step). Measured against
// H = 12 T-states: without friction the error falls as H^2 (0.001 step at H = 384, 400 steps/s);
// the Coulomb friction's stick/slip switching is located to the grid step (first order, at most
// 0.003 step); the start-stop limit is identical from H = 48 to 768 (docs/machine.md).
// Axes due at the same time are stepped side by side (step_grid): the same kernel as step(), so
// the same numbers bit for bit, with the independent chains interleaved for the host.
//
// Settling: a rotor whose velocity is zero and stuck (Coulomb friction or an end stop holds it), or
// whose residual motion is below 1e-6 rad in amplitude (energy test), with all currents within
// 1e-6 A of their steady values, is SETTLED: it is not integrated until its phases change again
// (1e-6 rad is 1.6 nm of table, 1/30000 of the scale pitch: it cannot move an edge of the
// transducer; 1e-6 A is 5e-6 of the rated current: the torque error is below the friction).
//
// Not emulated: the magnetic coupling of the two halves of a centre-tapped winding (each half is an
// independent L, r), saturation, the torque's higher harmonics other than the detent, eddy-current
// and hysteresis losses, the transistors' switching times, a drooping or poorly regulated supply
// (thesis §5.1 tested at reduced voltage: that is folded into the calibration), temperature.
#pragma once

#include <array>
#include <cstdint>

namespace alp85::periph {

class StepperMotor {
public:
    struct Params {
        // Thesis Table 3.2, PH265-03.
        double winding_ohm = 114.0;       // r, per phase (per half-winding in unipolar use)
        double inductance_h = 14.4e-3;    // L
        double rated_a = 0.21;            // I
        double holding_nm = 0.412;        // 41.2 N cm, two phases on at rated current
        double rotor_kgm2 = 110e-7;       // 110 g cm^2
        int rotor_teeth = 50;             // 1.8 deg full step (§3.2.1): 200 steps/rev
        // Drive, thesis §3.2.2.1 (values not given: assumed, docs/machine.md).
        double forcing_ohm = 0.0;         // R: Table 3.2's 24 V = 0.21 A x 114 ohm, so R = 0 at 24 V
        double freewheel_ohm = 600.0;     // Rf: calibrated (docs/machine.md); Vce,max = Vs + Rf I = 150 V (eq. 3.2)
        double vce_sat = 0.1;             // "typically 0.1 V" (§3.2.2.1)
        double diode_v = 0.7;             // freewheeling diode forward drop
        // Not in the thesis (assumed, docs/machine.md).
        double detent_nm = 0.02;          // ~5 % of the holding torque, typical for hybrids
        double viscous_nms = 1e-4;        // bearings and screw lubrication, N m s/rad
        // Integration.
        std::uint32_t step_tstates = 384; // H = 125 us at the ALP 85's 3.072 MHz, about L/R
    };

    // Per-axis dynamic state (the grid time is kept by the owner).
    struct State {
        double theta = 0.0;                 // rotor angle, rad, from the power-on equilibrium
        double omega = 0.0;                 // rad/s
        std::array<double, 4> i{};          // half-winding currents A, /A, B, /B (A)
        std::uint8_t phases = 0;            // drive pattern (Sequencer bits)
        bool settled = true;

        template <class S, class Io>
        static void fields(S& s, Io& io) {
            io(s.theta), io(s.omega), io(s.i), io(s.phases, 15), io(s.settled);
        }
    };

    // Where the table's end stops are, in rotor angle, and the load it adds.
    struct Load {
        double inertia = 0.0;     // kg m^2 reflected
        double coulomb = 0.0;     // N m reflected
        double theta_lo = -1e300;
        double theta_hi = 1e300;
    };

    enum StepFlags : unsigned { kNone = 0, kStopLow = 1, kStopHigh = 2 };

    StepperMotor() = default;  // configured by its builder before use
    // clock_hz: T-states per second of the times it is given (its builder's clock).
    void configure(const Params& p, const Load& load, double clock_hz);

    const Params& params() const { return p_; }
    const Load& load() const { return load_; }
    double step_angle() const { return step_angle_; }

    // A rotor at rest at `theta` with `phases` applied long ago.
    void init_at_rest(State& s, double theta, std::uint8_t phases) const;
    // Applies a new drive pattern (the rotor is no longer settled).
    static void set_phases(State& s, std::uint8_t phases) {
        s.phases = phases;
        s.settled = false;
    }
    // One step of h T-states (h == step_tstates uses the precomputed factors). Returns StepFlags
    // for an end stop in contact after the step.
    unsigned step(State& s, std::uint32_t h) const;
    // One grid step (step_tstates) each of n <= 3 motors (each with its own parameters and state):
    // flags[k] is what motors[k]->step(*states[k], step_tstates) returns, and the states end bit
    // for bit as after those calls; the independent integrations are interleaved for the host.
    static void step_grid(const StepperMotor* const* motors, State* const* states, unsigned* flags, int n);
    // The settling test (see the file's opening comment); a rotor with more kinetic energy than a
    // settled one may have fails at once (the test after every grid step of a moving rotor).
    bool is_settled(const State& s) const {
        return j_ * s.omega * s.omega < settle_energy_ && is_settled_at_low_speed(s);
    }
    // The equilibrium (rad) of the present pattern nearest the rotor.
    double equilibrium(const State& s) const;

private:
    Params p_;
    Load load_;
    double step_angle_ = 0, vs_ = 0, r_on_ = 0, r_off_ = 0, kt_ = 0, j_ = 0, i_on_ = 0;
    struct Drive {  // per drive pattern: each half-winding's steady current, conductance, on/off,
        double i0[4];  // and the grid step's decay and mean factors (a_on_/a_off_, m_on_/m_off_)
        double g[4];
        double a[4];
        double m[4];
        std::uint8_t on[4];
    };
    Drive drive_[16]{};
    // A step's constants for the integrator's kernel (half the step in s, the step over the
    // inertia and half that, the decay and mean factors per half-winding); a grid step's are members.
    struct Lane {
        double hh, h_j, hh_j;
        const double* a;
        const double* mf;
    };
    template <int N, bool Grid>
    static void kernel(const StepperMotor* const* motors, State* const* states, const Lane* split, unsigned* flags);
    bool is_settled_at_low_speed(const State& s) const;
    double clock_hz_ = 0;  // T-states per second (configure)
    double teeth_ = 0;  // rotor_teeth as a double
    double hh_ = 0, h_j_ = 0, hh_j_ = 0;  // the grid step's 0.5 h, h / J, 0.5 h / J
    double settle_energy_ = 0;            // k (1e-6 rad)^2: the settling test's energy bound
    double h_ = 0, a_on_ = 0, a_off_ = 0, m_on_ = 0, m_off_ = 0, stiffness_ = 0, inv_j_ = 0, g_on_ = 0, g_off_ = 0;
};

}  // namespace alp85::periph
