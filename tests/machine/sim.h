// Drives a MachineTool the way a pulse generator would (thesis §5.1: "a square wave generator"):
// pulses at a fixed rate, high for half the period, from standstill to an abrupt stop.
#pragma once

#include <cmath>
#include <cstdint>

#include "peripherals/machine_tool.h"

namespace alp85::test {

using periph::MachineTool;
using Axis = MachineTool::Axis;

constexpr double kClock = 3.072e6;  // T-states per second
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

// Lost steps of one start-stop run of n steps at `rate` on a fresh tool.
inline std::int64_t start_stop_loss(const MachineTool::Params& p, int n, double rate) {
    MachineTool m(p);
    m.set_model(MachineTool::MotorModel::Physical);
    pulse_train(m, Axis::X, n, rate, true, tstates(0.01));
    return m.lost_steps(Axis::X);
}

}  // namespace alp85::test
