// The PH265-03 stepping motor on the unipolar drive; equations and sources in stepper_motor.h.
#include "peripherals/stepper_motor.h"

#include <cmath>
#include <cstring>
#include <numbers>

#include "peripherals/sequencer.h"

namespace alp85::periph {

namespace {
constexpr double kSettleRad = 1e-6;         // residual amplitude of a settled rotor
constexpr double kSettleAmp = 1e-6;         // current error of a settled winding
constexpr std::uint8_t kBit[4] = {Sequencer::kA, Sequencer::kAbar, Sequencer::kB, Sequencer::kBbar};

// Two doubles side by side (GCC and Clang vector extensions; SSE2 on x86-64): each lane is rounded
// exactly as the same scalar operation would be.
using v2d = double __attribute__((vector_size(16)));
using v2i = long long __attribute__((vector_size(16)));
inline v2d load2(const double* p) {
    v2d v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
inline void store2(double* p, v2d v) { std::memcpy(p, &v, sizeof v); }
// v < 0 ? 0 : v, per lane.
inline v2d clamp_negative(v2d v) { return reinterpret_cast<v2d>(reinterpret_cast<v2i>(v) & ~(v < 0.0)); }

// sin and cos of x: reduction by k pi/2 with pi/2 split in three parts (the first two with 33
// significant bits, so k * part is exact for |k| < 2^20, i.e. |x| < 1.6e6 rad, far beyond the
// travel's 5e4 electrical radians), then Taylor polynomials on [-pi/4, pi/4] (truncation below
// 3e-14), sin's and cos's side by side. Only + and *: deterministic on any IEEE-754 machine, and
// cheaper than std::sin + std::cos.
inline void sin_cos(double x, double& s, double& c) {
    constexpr double kTwoOverPi = 0.63661977236758134308;
    constexpr double kP1 = 1.57079632673412561417e+00;
    constexpr double kP2 = 6.07710050630396597660e-11;
    constexpr double kP3 = 2.02226624879595063154e-21;
    const double q = x * kTwoOverPi;
    const long long ki = static_cast<long long>(q >= 0 ? q + 0.5 : q - 0.5);  // nearest (inline cvttsd2si)
    const double k = static_cast<double>(ki);
    const double r = ((x - k * kP1) - k * kP2) - k * kP3;
    // Estrin's scheme: short dependency chains (this is the integrator's hot path). Lane 0 is
    // sin(r)/r, lane 1 cos(r).
    const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    const v2d c2 = {1.0 / 6, 0.5}, c4 = {1.0 / 120, 1.0 / 24}, c6 = {1.0 / 5040, 1.0 / 720};
    const v2d c8 = {1.0 / 362880, 1.0 / 40320}, c10 = {1.0 / 39916800, 1.0 / 3628800};
    const v2d c12 = {1.0 / 6227020800.0, 1.0 / 479001600}, c14 = {1.0 / 1307674368000.0, 1.0 / 87178291200.0};
    const v2d v2 = {r2, r2}, v4 = {r4, r4}, v8 = {r8, r8}, one = {1.0, 1.0};
    const v2d p = (one - v2 * c2) + v4 * (c4 - v2 * c6) + v8 * ((c8 - v2 * c10) + v4 * (c12 - v2 * c14));
    const double sr = r * p[0], cr = p[1];
    // The quadrant: 0 (s, c), 1 (c, -s), 2 (-s, -c), 3 (-c, s).
    const bool odd = (ki & 1) != 0;
    const double s0 = odd ? cr : sr, c0 = odd ? sr : cr;
    s = (ki & 2) != 0 ? -s0 : s0;
    c = ((ki + 1) & 2) != 0 ? -c0 : c0;
}

// The speed after a kick of `h_j` (time over inertia) with torque t (without Coulomb friction) and
// Coulomb friction tc: a rotor at rest stays stuck while |t| <= tc; friction alone never reverses
// the motion (it stops it). One expression, as the kernel's interleaved lanes want.
inline double kick(double w, double t, double h_j, double tc) {
    const bool holds = std::fabs(t) <= tc;
    const bool up = w != 0.0 ? w > 0 : t > 0;
    const double n = w + h_j * (t - (up ? tc : -tc));  // tc x dir, dir = +-1
    return holds && (w == 0.0 || n * w < 0.0) ? 0.0 : n;
}

int pattern_index(std::uint8_t phases) {
    for (int k = 0; k < 4; ++k)
        if (Sequencer::kPattern[k] == phases) return k;
    return 0;
}
}  // namespace

void StepperMotor::configure(const Params& p, const Load& load, double clock_hz) {
    clock_hz_ = clock_hz;
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
    h_ = p.step_tstates / clock_hz_;
    a_on_ = std::exp(-h_ * r_on_ / p.inductance_h);
    a_off_ = std::exp(-h_ * r_off_ / p.inductance_h);
    m_on_ = (1.0 - a_on_) * p.inductance_h / (r_on_ * h_);
    m_off_ = (1.0 - a_off_) * p.inductance_h / (r_off_ * h_);
    hh_ = 0.5 * h_;
    h_j_ = h_ * inv_j_;
    hh_j_ = 0.5 * h_j_;
    for (auto& d : drive_)
        for (int j = 0; j < 4; ++j) {
            d.a[j] = d.on[j] ? a_on_ : a_off_;
            d.m[j] = d.on[j] ? m_on_ : m_off_;
        }
    teeth_ = p.rotor_teeth;
    stiffness_ = p.rotor_teeth * (p.holding_nm * i_on_ / p.rated_a - 4.0 * p.detent_nm);
    settle_energy_ = (stiffness_ > 0 ? stiffness_ : 1.0) * kSettleRad * kSettleRad;
}

void StepperMotor::init_at_rest(State& s, double theta, std::uint8_t phases) const {
    s.theta = theta;
    s.omega = 0.0;
    for (int j = 0; j < 4; ++j) s.i[j] = (phases & kBit[j]) ? i_on_ : 0.0;
    s.phases = phases;
    s.settled = true;
}

// The integrator's one step for N motors side by side (see the header's "Integration"). Each lane
// is an independent chain of dependent floating-point operations (angle -> sin, cos -> torque ->
// speed -> EMF -> currents -> torque -> speed -> angle), so the N chains are written stage by stage,
// with selects rather than early returns, and the host overlaps them. The arithmetic of a lane does not
// depend on N or on the other lanes: step() is kernel<1>, step_grid() kernel<2> or <3>, and a lane
// gets the same numbers, bit for bit, either way (no FMA contraction: CMakeLists.txt).
template <int N, bool Grid>
void StepperMotor::kernel(const StepperMotor* const* ms, State* const* ss, const Lane* split, unsigned* flags) {
    constexpr double kQuarterPi = std::numbers::pi / 4.0;
    double th_mid[N], sx[N], cx[N], sin4x[N], w_mid[N];
    // The step's constants: a grid step's from the motor, a split step's from `split` (N = 1).
    Lane ln[N];
#pragma GCC unroll 3
    for (int k = 0; k < N; ++k) {
        if constexpr (Grid) {
            const Drive& d = ms[k]->drive_[ss[k]->phases & 15];
            ln[k] = {ms[k]->hh_, ms[k]->h_j_, ms[k]->hh_j_, d.a, d.m};
        } else {
            ln[k] = split[k];
        }
    }
#pragma GCC unroll 3
    for (int k = 0; k < N; ++k) {
        // Drift half a step: the rotor angle at the step's midpoint, where the torque is evaluated.
        th_mid[k] = ss[k]->theta + ln[k].hh * ss[k]->omega;
        sin_cos(ms[k]->teeth_ * th_mid[k] + kQuarterPi, sx[k], cx[k]);
    }
#pragma GCC unroll 3
    for (int k = 0; k < N; ++k) {
        const StepperMotor& m = *ms[k];
        const State& s = *ss[k];
        sin4x[k] = 4.0 * sx[k] * cx[k] * (cx[k] * cx[k] - sx[k] * sx[k]);
        // The midpoint speed for the back-EMF, predicted with the step's starting currents.
        const double t_pred = m.kt_ * (-(s.i[0] - s.i[1]) * sx[k] + (s.i[2] - s.i[3]) * cx[k]) -
                              m.p_.detent_nm * sin4x[k] - m.p_.viscous_nms * s.omega;
        const double w = kick(s.omega, t_pred, ln[k].hh_j, m.load_.coulomb);
        const bool on_stop = (s.theta >= m.load_.theta_hi && w > 0) || (s.theta <= m.load_.theta_lo && w < 0);
        w_mid[k] = on_stop ? 0.0 : w;
    }
    double mean[N][4];
#pragma GCC unroll 3
    for (int k = 0; k < N; ++k) {
        // Electrical: exact exponential per half-winding with the EMF frozen at its midpoint value.
        // i_inf = (Vs - Vce - e)/(r+R) on, (-Vd - e)/(r+R+Rf) off; the step's mean current is the
        // exponential's exact mean, i_inf + (i - i_inf)(1 - a) tau/h. A blocked diode (i = 0, i_inf
        // < 0) gives n <= 0, clamped to 0 like any reverse current (mean clamped too).
        const StepperMotor& m = *ms[k];
        State& s = *ss[k];
        const Drive& d = m.drive_[s.phases & 15];
        const double ea = -m.kt_ * w_mid[k] * sx[k], eb = m.kt_ * w_mid[k] * cx[k];
        // Half-windings A, /A in one pair, B, /B in the other.
#pragma GCC unroll 2
        for (int j = 0; j < 4; j += 2) {
            const v2d e = j == 0 ? v2d{ea, -ea} : v2d{eb, -eb};
            const v2d inf = load2(d.i0 + j) - e * load2(d.g + j);
            const v2d di = load2(s.i.data() + j) - inf;
            store2(mean[k] + j, clamp_negative(inf + di * load2(ln[k].mf + j)));
            store2(s.i.data() + j, clamp_negative(inf + di * load2(ln[k].a + j)));
        }
    }
#pragma GCC unroll 3
    for (int k = 0; k < N; ++k) {
        // Mechanical: kick with the midpoint torque (Coulomb friction and stiction), drift the rest.
        const StepperMotor& m = *ms[k];
        State& s = *ss[k];
        const double* mk = mean[k];
        const double t_em = m.kt_ * (-(mk[0] - mk[1]) * sx[k] + (mk[2] - mk[3]) * cx[k]) - m.p_.detent_nm * sin4x[k];
        const double t_nc = t_em - m.p_.viscous_nms * w_mid[k];
        double w = kick(s.omega, t_nc, ln[k].h_j, m.load_.coulomb);
        double th = th_mid[k] + ln[k].hh * w;
        const bool hi = th >= m.load_.theta_hi;
        const bool lo = !hi && th <= m.load_.theta_lo;
        w = (hi && w > 0) || (lo && w < 0) ? 0.0 : w;
        th = hi ? m.load_.theta_hi : lo ? m.load_.theta_lo : th;
        flags[k] = hi ? kStopHigh : lo ? kStopLow : kNone;
        s.theta = th;
        s.omega = w;
    }
}

unsigned StepperMotor::step(State& s, std::uint32_t ht) const {
    const StepperMotor* const m = this;
    State* const st = &s;
    unsigned flags;
    if (ht == p_.step_tstates) {
        kernel<1, true>(&m, &st, nullptr, &flags);
        return flags;
    }
    // A split step: its own decay and mean factors.
    const double h = ht / clock_hz_;
    const double a_on = std::exp(-h * r_on_ / p_.inductance_h);
    const double a_off = std::exp(-h * r_off_ / p_.inductance_h);
    const double m_on = (1.0 - a_on) * p_.inductance_h / (r_on_ * h);
    const double m_off = (1.0 - a_off) * p_.inductance_h / (r_off_ * h);
    const Drive& d = drive_[s.phases & 15];
    double a[4], mf[4];
    for (int j = 0; j < 4; ++j) {
        a[j] = d.on[j] ? a_on : a_off;
        mf[j] = d.on[j] ? m_on : m_off;
    }
    const double h_j = h * inv_j_;
    const Lane lane{0.5 * h, h_j, 0.5 * h_j, a, mf};
    kernel<1, false>(&m, &st, &lane, &flags);
    return flags;
}

void StepperMotor::step_grid(const StepperMotor* const* motors, State* const* states, unsigned* flags, int n) {
    switch (n) {
        case 1: kernel<1, true>(motors, states, nullptr, flags); break;
        case 2: kernel<2, true>(motors, states, nullptr, flags); break;
        case 3: kernel<3, true>(motors, states, nullptr, flags); break;
        default: break;
    }
}

double StepperMotor::equilibrium(const State& s) const {
    const int k = pattern_index(s.phases);
    const double n = s.theta / step_angle_ - k;
    return step_angle_ * (k + 4.0 * std::round(n / 4.0));
}

bool StepperMotor::is_settled_at_low_speed(const State& s) const {
    const double k = stiffness_ > 0 ? stiffness_ : 1.0;
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
