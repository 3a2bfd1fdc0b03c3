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

// sin and cos of x: reduction by k pi/2 with pi/2 split in three parts (the first two with 33
// significant bits, so k * part is exact for |k| < 2^20, i.e. |x| < 1.6e6 rad, far beyond the
// travel's 5e4 electrical radians), then Taylor polynomials on [-pi/4, pi/4] (truncation below
// 3e-14). Only + and *: deterministic on any IEEE-754 machine, and cheaper than std::sin + std::cos.
inline void sin_cos(double x, double& s, double& c) {
    constexpr double kTwoOverPi = 0.63661977236758134308;
    constexpr double kP1 = 1.57079632673412561417e+00;
    constexpr double kP2 = 6.07710050630396597660e-11;
    constexpr double kP3 = 2.02226624879595063154e-21;
    const double q = x * kTwoOverPi;
    const long long ki = static_cast<long long>(q >= 0 ? q + 0.5 : q - 0.5);  // nearest (inline cvttsd2si)
    const double k = static_cast<double>(ki);
    const double r = ((x - k * kP1) - k * kP2) - k * kP3;
    // Estrin's scheme: short dependency chains (this is the integrator's hot path).
    const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const double sp = (1.0 - r2 * (1.0 / 6)) + r4 * (1.0 / 120 - r2 * (1.0 / 5040)) +
                      r8 * ((1.0 / 362880 - r2 * (1.0 / 39916800)) + r4 * (1.0 / 6227020800.0 - r2 * (1.0 / 1307674368000.0)));
    const double cp = (1.0 - r2 * 0.5) + r4 * (1.0 / 24 - r2 * (1.0 / 720)) +
                      r8 * ((1.0 / 40320 - r2 * (1.0 / 3628800)) + r4 * (1.0 / 479001600 - r2 * (1.0 / 87178291200.0)));
    const double sr = r * sp, cr = cp;
    switch (ki & 3) {
        case 0: s = sr, c = cr; break;
        case 1: s = cr, c = -sr; break;
        case 2: s = -sr, c = -cr; break;
        default: s = -cr, c = sr; break;
    }
}

// The speed after a kick of `h_j` (time over inertia) with torque t (without Coulomb friction) and
// Coulomb friction tc: a rotor at rest stays stuck while |t| <= tc; friction alone never reverses
// the motion (it stops it).
inline double kick(double w, double t, double h_j, double tc) {
    if (w == 0.0 && std::fabs(t) <= tc) return 0.0;
    const double dir = w != 0.0 ? (w > 0 ? 1.0 : -1.0) : (t > 0 ? 1.0 : -1.0);
    const double n = w + h_j * (t - tc * dir);
    if (w != 0.0 && n * w < 0.0 && std::fabs(t) <= tc) return 0.0;
    return n;
}

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
    inv_j_ = 1.0 / j_;
    g_on_ = 1.0 / r_on_;
    g_off_ = 1.0 / r_off_;
    for (int ph = 0; ph < 16; ++ph) {
        for (int j = 0; j < 4; ++j) {
            const bool on = (ph & kBit[j]) != 0;
            drive_[ph].i0[j] = on ? i_on_ : -p.diode_v * g_off_;
            drive_[ph].g[j] = on ? g_on_ : g_off_;
            drive_[ph].on[j] = on ? 1 : 0;
        }
    }
    h_ = p.step_tstates / kClockHz;
    a_on_ = std::exp(-h_ * r_on_ / p.inductance_h);
    a_off_ = std::exp(-h_ * r_off_ / p.inductance_h);
    m_on_ = (1.0 - a_on_) * p.inductance_h / (r_on_ * h_);
    m_off_ = (1.0 - a_off_) * p.inductance_h / (r_off_ * h_);
    for (auto& d : drive_)
        for (int j = 0; j < 4; ++j) {
            d.a[j] = d.on[j] ? a_on_ : a_off_;
            d.m[j] = d.on[j] ? m_on_ : m_off_;
        }
    teeth_ = p.rotor_teeth;
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
    double h = h_, a_on = a_on_, a_off = a_off_, m_on = m_on_, m_off = m_off_;
    if (ht != p_.step_tstates) {
        h = ht / kClockHz;
        a_on = std::exp(-h * r_on_ / p_.inductance_h);
        a_off = std::exp(-h * r_off_ / p_.inductance_h);
        m_on = (1.0 - a_on) * p_.inductance_h / (r_on_ * h);
        m_off = (1.0 - a_off) * p_.inductance_h / (r_off_ * h);
    }
    // Drift half a step: the rotor angle at the step's midpoint, where the torque is evaluated.
    const double th_mid = s.theta + 0.5 * h * s.omega;
    const double x = teeth_ * th_mid + std::numbers::pi / 4.0;
    double sx, cx;
    sin_cos(x, sx, cx);
    const double sin4x = 4.0 * sx * cx * (cx * cx - sx * sx);
    const double tc = load_.coulomb;
    const double h_j = h * inv_j_;
    // The midpoint speed for the back-EMF, predicted with the step's starting currents.
    const double t_pred = kt_ * (-(s.i[0] - s.i[1]) * sx + (s.i[2] - s.i[3]) * cx) - p_.detent_nm * sin4x -
                          p_.viscous_nms * s.omega;
    double w_mid = kick(s.omega, t_pred, 0.5 * h_j, tc);
    if ((s.theta >= load_.theta_hi && w_mid > 0) || (s.theta <= load_.theta_lo && w_mid < 0)) w_mid = 0.0;  // on a stop

    // Electrical: exact exponential per half-winding with the EMF frozen at its midpoint value.
    const double ea = -kt_ * w_mid * sx, eb = kt_ * w_mid * cx;
    const double e[4] = {ea, -ea, eb, -eb};
    const Drive& d = drive_[s.phases & 15];
    // The grid step's decay and mean factors per half-winding come with the pattern (drive_);
    // a split step computes them.
    double a_split[4], m_split[4];
    const double* aj = d.a;
    const double* mj = d.m;
    if (ht != p_.step_tstates) {
        for (int j = 0; j < 4; ++j) {
            a_split[j] = d.on[j] ? a_on : a_off;
            m_split[j] = d.on[j] ? m_on : m_off;
        }
        aj = a_split;
        mj = m_split;
    }
    double mean[4];
    for (int j = 0; j < 4; ++j) {
        // i_inf = (Vs - Vce - e)/(r+R) on, (-Vd - e)/(r+R+Rf) off; the step's mean current is the
        // exponential's exact mean, i_inf + (i - i_inf)(1 - a) tau/h. A blocked diode (i = 0, i_inf
        // < 0) gives n <= 0, clamped to 0 like any reverse current (mean clamped too).
        const double inf = d.i0[j] - e[j] * d.g[j];
        const double di = s.i[j] - inf;
        double n = inf + di * aj[j];
        double m = inf + di * mj[j];
        n = n < 0.0 ? 0.0 : n;
        m = m < 0.0 ? 0.0 : m;
        mean[j] = m;
        s.i[j] = n;
    }

    // Mechanical: kick with the midpoint torque (Coulomb friction and stiction), drift the rest.
    const double t_em = kt_ * (-(mean[0] - mean[1]) * sx + (mean[2] - mean[3]) * cx) - p_.detent_nm * sin4x;
    const double t_nc = t_em - p_.viscous_nms * w_mid;
    double w = kick(s.omega, t_nc, h_j, tc);
    double th = th_mid + 0.5 * h * w;
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
    const double k = stiffness_ > 0 ? stiffness_ : 1.0;
    if (j_ * s.omega * s.omega >= k * kSettleRad * kSettleRad) return false;  // still moving
    for (int j = 0; j < 4; ++j) {
        const double target = (s.phases & kBit[j]) ? i_on_ : 0.0;
        if (std::fabs(s.i[j] - target) > kSettleAmp) return false;
    }
    if (s.omega == 0.0) {
        // Held by friction or pressed against an end stop by a torque the stop takes.
        const double x = p_.rotor_teeth * s.theta + std::numbers::pi / 4.0;
        double sx, cx;
        sin_cos(x, sx, cx);
        const double sin4x = 4.0 * sx * cx * (cx * cx - sx * sx);
        const double t = kt_ * (-(s.i[0] - s.i[1]) * sx + (s.i[2] - s.i[3]) * cx) - p_.detent_nm * sin4x;
        if (std::fabs(t) <= load_.coulomb) return true;
        if (s.theta >= load_.theta_hi && t > 0) return true;
        if (s.theta <= load_.theta_lo && t < 0) return true;
    }
    const double d = s.theta - equilibrium(s);
    return j_ * s.omega * s.omega + k * d * d < k * kSettleRad * kSettleRad;
}

}  // namespace alp85::periph
