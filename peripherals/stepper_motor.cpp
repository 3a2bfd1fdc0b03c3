// The PH265-03 stepping motor on the unipolar drive; equations and sources in stepper_motor.h.
#include "peripherals/stepper_motor.h"

#include <cmath>
#include <numbers>

#include "peripherals/sequencer.h"

namespace alp85::periph {

namespace {
constexpr double kClockHz = 3.072e6;        // CPU T-states per second
constexpr double kSettleRad = 1e-6;         // residual amplitude of a settled rotor
constexpr double kSettleAmp = 1e-6;         // current error of a settled winding
constexpr std::uint8_t kBit[4] = {Sequencer::kA, Sequencer::kAbar, Sequencer::kB, Sequencer::kBbar};

int pattern_index(std::uint8_t phases) {
    for (int k = 0; k < 4; ++k)
        if (Sequencer::kPattern[k] == phases) return k;
    return 0;
}
}  // namespace

void StepperMotor::configure(const Params& p, const Load& load) {
    p_ = p;
    load_ = load;
    step_angle_ = 2.0 * std::numbers::pi / (4.0 * p.rotor_teeth);
    r_on_ = p.winding_ohm + p.forcing_ohm;
    r_off_ = p.winding_ohm + p.forcing_ohm + p.freewheel_ohm;
    vs_ = p.rated_a * r_on_;  // eq. 3.1
    i_on_ = (vs_ - p.vce_sat) / r_on_;
    kt_ = p.holding_nm / (std::numbers::sqrt2 * p.rated_a);
    j_ = p.rotor_kgm2 + load.inertia;
    h_ = p.step_tstates / kClockHz;
    a_on_ = std::exp(-h_ * r_on_ / p.inductance_h);
    a_off_ = std::exp(-h_ * r_off_ / p.inductance_h);
    stiffness_ = p.rotor_teeth * (p.holding_nm * i_on_ / p.rated_a - 4.0 * p.detent_nm);
}

double StepperMotor::stiffness() const { return stiffness_; }

void StepperMotor::init_at_rest(State& s, double theta, std::uint8_t phases) const {
    s.theta = theta;
    s.omega = 0.0;
    for (int j = 0; j < 4; ++j) s.i[j] = (phases & kBit[j]) ? i_on_ : 0.0;
    s.phases = phases;
    s.settled = true;
}

unsigned StepperMotor::step(State& s, std::uint32_t ht) const {
    double h = h_, a_on = a_on_, a_off = a_off_;
    if (ht != p_.step_tstates) {
        h = ht / kClockHz;
        a_on = std::exp(-h * r_on_ / p_.inductance_h);
        a_off = std::exp(-h * r_off_ / p_.inductance_h);
    }
    const double x = p_.rotor_teeth * s.theta + std::numbers::pi / 4.0;
    const double sx = std::sin(x), cx = std::cos(x);

    // Electrical: exact exponential per half-winding with the EMF frozen over the step.
    const double ea = -kt_ * s.omega * sx, eb = kt_ * s.omega * cx;
    const double e[4] = {ea, -ea, eb, -eb};
    double mean[4];
    for (int j = 0; j < 4; ++j) {
        const bool on = (s.phases & kBit[j]) != 0;
        const double inf = on ? (vs_ - p_.vce_sat - e[j]) / r_on_ : (-p_.diode_v - e[j]) / r_off_;
        double n = inf + (s.i[j] - inf) * (on ? a_on : a_off);
        if (n < 0.0) n = 0.0;  // the diode (off) or the transistor (on) conducts one way only
        mean[j] = 0.5 * (s.i[j] + n);
        s.i[j] = n;
    }

    // Mechanical: semi-implicit Euler with Coulomb friction and stiction.
    const double sin4x = 4.0 * sx * cx * (cx * cx - sx * sx);
    const double t_em = kt_ * (-(mean[0] - mean[1]) * sx + (mean[2] - mean[3]) * cx) - p_.detent_nm * sin4x;
    const double t_nc = t_em - p_.viscous_nms * s.omega;
    const double tc = load_.coulomb;
    double w;
    if (s.omega == 0.0 && std::fabs(t_nc) <= tc) {
        w = 0.0;  // stuck
    } else {
        const double dir = s.omega != 0.0 ? (s.omega > 0 ? 1.0 : -1.0) : (t_nc > 0 ? 1.0 : -1.0);
        w = s.omega + h * (t_nc - tc * dir) / j_;
        if (s.omega != 0.0 && w * s.omega < 0.0 && std::fabs(t_nc) <= tc) w = 0.0;  // friction stops it
    }
    double th = s.theta + h * w;
    unsigned flags = kNone;
    if (th >= load_.theta_hi) {
        th = load_.theta_hi;
        if (w > 0) w = 0.0;
        flags = kStopHigh;
    } else if (th <= load_.theta_lo) {
        th = load_.theta_lo;
        if (w < 0) w = 0.0;
        flags = kStopLow;
    }
    s.theta = th;
    s.omega = w;
    return flags;
}

double StepperMotor::equilibrium(const State& s) const {
    const int k = pattern_index(s.phases);
    const double n = s.theta / step_angle_ - k;
    return step_angle_ * (k + 4.0 * std::round(n / 4.0));
}

bool StepperMotor::is_settled(const State& s) const {
    for (int j = 0; j < 4; ++j) {
        const double target = (s.phases & kBit[j]) ? i_on_ : 0.0;
        if (std::fabs(s.i[j] - target) > kSettleAmp) return false;
    }
    if (s.omega == 0.0) {
        // Held by friction or pressed against an end stop by a torque the stop takes.
        const double x = p_.rotor_teeth * s.theta + std::numbers::pi / 4.0;
        const double sx = std::sin(x), cx = std::cos(x);
        const double sin4x = 4.0 * sx * cx * (cx * cx - sx * sx);
        const double t = kt_ * (-(s.i[0] - s.i[1]) * sx + (s.i[2] - s.i[3]) * cx) - p_.detent_nm * sin4x;
        if (std::fabs(t) <= load_.coulomb) return true;
        if (s.theta >= load_.theta_hi && t > 0) return true;
        if (s.theta <= load_.theta_lo && t < 0) return true;
    }
    const double d = s.theta - equilibrium(s);
    const double k = stiffness_ > 0 ? stiffness_ : 1.0;
    return j_ * s.omega * s.omega + k * d * d < k * kSettleRad * kSettleRad;
}

}  // namespace alp85::periph
