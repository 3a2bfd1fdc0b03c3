// Drives a MachineTool the way a pulse generator would (thesis §5.1: "a square wave generator"):
// pulses at a fixed rate, high for half the period, from standstill to an abrupt stop.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "peripherals/machine_tool.h"

namespace alp85::test {

using periph::MachineTool;
using Axis = MachineTool::Axis;

constexpr double kClock = 3.072e6;  // T-states per second: the ALP 85's CPU clock (6.144 MHz crystal / 2), the tools' builder here
inline std::uint64_t tstates(double seconds) { return static_cast<std::uint64_t>(std::llround(seconds * kClock)); }

// n pulses at `rate` steps/s starting at t0, then 0.5 s to settle. Returns the T-state reached.
inline std::uint64_t pulse_train(MachineTool& m, Axis a, int n, double rate, bool dir, std::uint64_t t0) {
    const double period = kClock / rate;
    for (int k = 0; k < n; ++k) {
        const auto t = t0 + static_cast<std::uint64_t>(std::llround(k * period));
        m.set_drive(a, true, dir, t);
        m.set_drive(a, false, dir, t + static_cast<std::uint64_t>(std::llround(period / 2)));
    }
    const auto end = t0 + static_cast<std::uint64_t>(std::llround(n * period)) + tstates(0.5);
    m.advance(end);
    return end;
}

// A ramped run (thesis §5.1: the generator's frequency turned up, "any rotational speed between 0
// and 500 steps/sec can be reached"): from `r0` up to `r1` at `acc` steps/s^2 (v^2 = r0^2 + 2 acc s),
// `hold` steps at r1, down the same levels, then 0.5 s to settle. Returns the T-state reached.
inline std::uint64_t ramped_train(MachineTool& m, Axis a, double r0, double r1, double acc, int hold, std::uint64_t t0) {
    std::vector<double> up;
    for (int s = 0;; ++s) {
        const double r = std::sqrt(r0 * r0 + 2 * acc * s);
        if (r >= r1) break;
        up.push_back(r);
    }
    std::vector<double> rates = up;
    rates.insert(rates.end(), static_cast<std::size_t>(hold), r1);
    rates.insert(rates.end(), up.rbegin(), up.rend());
    double t = static_cast<double>(t0);
    for (double r : rates) {
        const double period = kClock / r;
        m.set_drive(a, true, true, static_cast<std::uint64_t>(std::llround(t)));
        m.set_drive(a, false, true, static_cast<std::uint64_t>(std::llround(t + period / 2)));
        t += period;
    }
    const auto end = static_cast<std::uint64_t>(std::llround(t)) + tstates(0.5);
    m.advance(end);
    return end;
}

// Lost steps of one start-stop run of n steps at `rate` on a fresh tool.
inline std::int64_t start_stop_loss(const MachineTool::Params& p, int n, double rate) {
    MachineTool m(kClock, p);
    m.set_model(MachineTool::MotorModel::Physical);
    pulse_train(m, Axis::X, n, rate, true, tstates(0.01));
    return m.lost_steps(Axis::X);
}

// The master program's sampling output on one axis (docs/contours.md "Sampling"): a pulse at the
// start of each 2 ms sample in which x* (advanced by f each sample) passes a whole step, f rising
// from 0.5 step a sample by 328/65536 a sample to `fs` (1.0 = 500 steps/s), n steps, then 0.5 s to
// settle. Returns the lost steps.
inline std::int64_t sampled_loss(const MachineTool::Params& p, int n, double fs) {
    MachineTool m(kClock, p);
    m.set_model(MachineTool::MotorModel::Physical);
    const std::uint64_t period = 6144, t0 = tstates(0.01);
    double f = 0.5, x = 0;
    long steps = 0;
    std::uint64_t t = t0;
    while (steps < n) {
        f = f + 328.0 / 65536 < fs ? f + 328.0 / 65536 : fs;
        x += f;
        if (static_cast<long>(x) > steps) {
            m.set_drive(Axis::X, true, true, t);
            m.set_drive(Axis::X, false, true, t + period / 2);
            steps = static_cast<long>(x);
        }
        t += period;
    }
    m.advance(t + tstates(0.5));
    return m.lost_steps(Axis::X);
}

// Lost steps of one ramped run (ramped_train from 250 steps/s at `acc`, n steps at `rate`).
inline std::int64_t ramped_loss(const MachineTool::Params& p, int n, double rate, double acc) {
    MachineTool m(kClock, p);
    m.set_model(MachineTool::MotorModel::Physical);
    ramped_train(m, Axis::X, 250.0, rate, acc, n, tstates(0.01));
    return m.lost_steps(Axis::X);
}

}  // namespace alp85::test
