// MachineTool as a Part: the ideal model's counts, the transducer bits the firmware reads, end
// stops, snapshots (save -> load -> continue bit for bit), determinism, settled rotors.
// Expected values from the parameters: 0.05 mm per step, travel + 5 mm overtravel.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <numbers>
#include <tuple>
#include <vector>

#include "tests/machine/sim.h"

namespace alp85::test {
namespace {

using Model = MachineTool::MotorModel;
constexpr std::uint64_t kPeriod = 7680;  // 400 steps/s at 3.072 MHz

// n steps on one axis from t0 with the firmware's pulse shape; returns the next free T-state.
std::uint64_t steps(MachineTool& m, Axis a, int n, bool dir, std::uint64_t t0, std::uint64_t period = kPeriod) {
    for (int k = 0; k < n; ++k) {
        m.set_drive(a, false, dir, t0 + k * period);  // direction first
        m.set_drive(a, true, dir, t0 + k * period + 100);
        m.set_drive(a, false, dir, t0 + k * period + 100 + period / 2);
    }
    return t0 + n * period;
}

TEST(MachineToolIdeal, CountsStepsPositionAndTransducer) {
    MachineTool m(kClock);
    m.set_model(Model::Ideal);
    auto t = steps(m, Axis::X, 200, true, 1000);
    EXPECT_EQ(m.commanded_steps(Axis::X), 200);
    EXPECT_DOUBLE_EQ(m.table_mm(Axis::X), 10.0);  // 200 x 0.05 mm (thesis §3.2.2)
    EXPECT_DOUBLE_EQ(m.rotor_angle_deg(Axis::X), 360.0);
    EXPECT_EQ(m.transducer_count(Axis::X), 200);
    EXPECT_EQ(m.lost_steps(Axis::X), 0);
    t = steps(m, Axis::X, 30, false, t);
    EXPECT_EQ(m.commanded_steps(Axis::X), 170);
    EXPECT_EQ(m.transducer_count(Axis::X), 170);
    EXPECT_NEAR(m.table_mm(Axis::X), 8.5, 1e-12);
    EXPECT_EQ(m.commanded_steps(Axis::Y), 0);
    EXPECT_EQ(m.phase_pattern(Axis::X), periph::Sequencer::kPattern[170 % 4]);
}

TEST(MachineToolIdeal, SenseTogglesCountOncePerStepWithDirection) {
    MachineTool m(kClock);
    m.set_model(Model::Ideal);
    std::uint64_t t = 1000;
    bool last = m.sense(Axis::Y, t).count;
    for (int k = 0; k < 12; ++k) {
        const bool dir = k < 8;
        t = steps(m, Axis::Y, 1, dir, t);
        const auto s = m.sense(Axis::Y, t);
        EXPECT_NE(s.count, last) << k;
        EXPECT_EQ(s.direction, dir) << k;
        last = s.count;
    }
    EXPECT_EQ(m.transducer_count(Axis::Y), 4);
}

TEST(MachineToolIdeal, EndStopHoldsTheTableAndReports) {
    MachineTool m(kClock);
    m.set_model(Model::Ideal);
    std::vector<std::tuple<Axis, bool, std::uint64_t>> events;
    m.on_end_stop([&](Axis a, bool high, std::uint64_t t) { events.emplace_back(a, high, t); });
    // Z: 100 mm of travel + 5 mm overtravel = 105 mm = 2100 steps; ask for 2150.
    steps(m, Axis::Z, 2150, true, 1000);
    EXPECT_DOUBLE_EQ(m.table_mm(Axis::Z), 105.0);
    EXPECT_EQ(m.commanded_steps(Axis::Z), 2150);
    EXPECT_EQ(m.lost_steps(Axis::Z), 50);
    EXPECT_EQ(m.transducer_count(Axis::Z), 2100);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(std::get<0>(events[0]), Axis::Z);
    EXPECT_TRUE(std::get<1>(events[0]));
    EXPECT_EQ(std::get<2>(events[0]), 1000 + 2099 * kPeriod + 100);  // the 2100th pulse's rising edge
    EXPECT_EQ(m.end_stop(Axis::Z).at, 1);
    EXPECT_EQ(m.end_stop(Axis::Z).hits, 1u);
    steps(m, Axis::Z, 10, false, 1000 + 2150 * kPeriod);
    EXPECT_EQ(m.end_stop(Axis::Z).at, 0);
    EXPECT_DOUBLE_EQ(m.table_mm(Axis::Z), 104.5);
}

TEST(MachineToolPhysical, EndStopStallsTheMotor) {
    MachineTool m(kClock);
    int hits = 0;
    m.on_end_stop([&](Axis a, bool high, std::uint64_t) { hits += a == Axis::Y && !high; });
    // Y from 0 toward the low stop at -5 mm (-100 steps), 201 steps asked at 100 steps/s: the
    // last pattern's equilibrium is -101 steps, beyond the stop, so the motor stays pressed on it.
    double lowest = 0;
    std::uint64_t t = 1000;
    for (int k = 0; k < 201; ++k) {
        t = steps(m, Axis::Y, 1, false, t, 30720);
        for (int r = 0; r < 8; ++r) {
            m.advance(t - r * 3840);
            lowest = std::min(lowest, m.table_mm(Axis::Y));
        }
    }
    m.advance(t + tstates(0.5));
    EXPECT_GE(lowest, -5.0 - 1e-12);
    EXPECT_DOUBLE_EQ(m.table_mm(Axis::Y), -5.0);
    EXPECT_EQ(m.end_stop(Axis::Y).at, -1);
    EXPECT_TRUE(m.settled(Axis::Y));
    EXPECT_GE(hits, 1);
    EXPECT_EQ(m.lost_steps(Axis::Y), -101);
    EXPECT_EQ(m.transducer_count(Axis::Y), -100);
}

// Drives all three axes with a pattern, reading the transducers `reads` times per step.
void workload(MachineTool& m, std::uint64_t t0, int n, int reads) {
    for (int k = 0; k < n; ++k) {
        const std::uint64_t t = t0 + static_cast<std::uint64_t>(k) * 6000;
        for (int a = 0; a < 3; ++a) {
            const bool dir = (k / (7 + a)) % 2 == 0;
            m.set_drive(static_cast<Axis>(a), true, dir, t + 37 * a);
            for (int r = 1; r <= reads; ++r) m.sense(static_cast<Axis>(a), t + 37 * a + r * 1000 / (reads + 1));
            m.set_drive(static_cast<Axis>(a), false, dir, t + 37 * a + 3000);
        }
    }
}

std::vector<std::uint8_t> saved(const MachineTool& m) {
    std::vector<std::uint8_t> out;
    m.save(out);
    return out;
}

TEST(MachineToolPhysical, SameInputsSameResultWhateverTheReads) {
    MachineTool a(kClock), b(kClock);
    workload(a, 500, 120, 0);
    workload(b, 500, 120, 5);
    a.advance(2'000'000);
    b.advance(2'000'000);
    EXPECT_EQ(saved(a), saved(b));
    for (int ax = 0; ax < 3; ++ax)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a.table_mm(static_cast<Axis>(ax))),
                  std::bit_cast<std::uint64_t>(b.table_mm(static_cast<Axis>(ax))));
}

TEST(MachineToolPhysical, SaveLoadContinueIsBitForBit) {
    MachineTool a(kClock);
    workload(a, 500, 60, 1);
    a.advance(500 + 60 * 6000 + 777);  // mid-ring, between grid points
    ASSERT_FALSE(a.all_settled());
    const auto snap = saved(a);
    MachineTool b(kClock);
    b.load(snap);
    EXPECT_EQ(saved(b), snap);
    workload(a, 500 + 61 * 6000, 60, 2);
    workload(b, 500 + 61 * 6000, 60, 2);
    for (std::uint64_t t : {800'000ull, 1'000'000ull, 3'000'000ull}) {
        a.advance(t);
        b.advance(t);
        for (int ax = 0; ax < 3; ++ax) {
            const auto x = static_cast<Axis>(ax);
            EXPECT_EQ(std::bit_cast<std::uint64_t>(a.table_mm(x)), std::bit_cast<std::uint64_t>(b.table_mm(x)));
            EXPECT_EQ(a.transducer_count(x), b.transducer_count(x));
        }
    }
    EXPECT_EQ(saved(a), saved(b));
}

TEST(MachineToolPhysical, LoadRejectsBadStateAndKeepsItsOwn) {
    MachineTool a(kClock);
    workload(a, 500, 10, 0);
    auto snap = saved(a);
    MachineTool b(kClock);
    const auto before = saved(b);
    auto truncated = snap;
    truncated.pop_back();
    EXPECT_THROW(b.load(truncated), SnapshotError);
    auto bad_model = snap;
    bad_model[3] = 7;  // the model byte follows the 3-byte header
    EXPECT_THROW(b.load(bad_model), SnapshotError);
    EXPECT_EQ(saved(b), before);
    EXPECT_EQ(b.tag(), "TOOL");
}

TEST(MachineToolPhysical, SettledRotorsAreNotIntegrated) {
    MachineTool m(kClock);
    auto t = steps(m, Axis::X, 3, true, 1000);
    EXPECT_FALSE(m.settled(Axis::X));
    m.advance(t + tstates(0.5));
    ASSERT_TRUE(m.all_settled());
    const auto snap = saved(m);
    const double x = m.table_mm(Axis::X);
    m.advance(t + tstates(100.0));  // 100 s later: nothing moves, nothing is integrated
    auto later = saved(m);
    // Only the part's clock (the last 8 bytes) differs.
    ASSERT_EQ(later.size(), snap.size());
    EXPECT_TRUE(std::equal(snap.begin(), snap.end() - 8, later.begin()));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(m.table_mm(Axis::X)), std::bit_cast<std::uint64_t>(x));
    // Within the slideway friction's band of 3 steps: T_c/k rad, T_c = mu m g lead/2pi (28 kg),
    // k = N (T_hold I_on/I - 4 T_d), at 10 mm/rev (0.0026 rad, 0.0042 mm, a twelfth of a step).
    const double tc = 0.1 * 28.0 * 9.80665 * 0.010 / (2 * std::numbers::pi);
    const double k = 50.0 * (0.412 * (0.21 - 0.1 / 114.0) / 0.21 - 4 * 0.02);
    EXPECT_NEAR(x, 0.15, tc / k * 10.0 / (2 * std::numbers::pi));
}

// The three axes' integrations run side by side (StepperMotor::step_grid) when they are due at the
// same time: each must get exactly the numbers its own step() gives, whatever runs beside it. The
// states cover motion both ways, a rotor at rest held by friction, pressing on either end stop,
// windings switching on and off, on three motors with different loads and stops.
TEST(MotorPhysical, StepsSideBySideAreBitForBitTheStepsAlone) {
    auto p = MachineTool::default_params();
    p.axes[1].table.mass_kg = 5.0;    // a lighter Y table
    p.axes[2].table.travel_mm = 1.0;  // Z between stops 1 mm + overtravel apart: hits them
    p.axes[2].table.friction_mu = 0.3;
    const MachineTool tool(kClock, p);
    const periph::StepperMotor* motors[3] = {&tool.motor(Axis::X), &tool.motor(Axis::Y), &tool.motor(Axis::Z)};
    using State = periph::StepperMotor::State;
    const auto bits = [](const State& s) {
        std::vector<std::uint64_t> b{std::bit_cast<std::uint64_t>(s.theta), std::bit_cast<std::uint64_t>(s.omega)};
        for (double i : s.i) b.push_back(std::bit_cast<std::uint64_t>(i));
        return b;
    };
    int stops = 0, at_rest = 0;
    for (int lanes = 1; lanes <= 3; ++lanes) {
        State side[3], alone[3];
        for (int k = 0; k < 3; ++k) motors[k]->init_at_rest(side[k], 0.0, periph::Sequencer::kPattern[0]);
        for (int n = 0; n < 20000; ++n) {
            // Each axis steps its sequence at its own rate, reversing now and then; Z runs into its stops.
            if (n % 15 == 0)
                for (int k = 0; k < 3; ++k) {
                    const int idx = (n / 15) * (k == 1 ? -1 : 1) / (k + 1) + (n / 3000) * k;
                    periph::StepperMotor::set_phases(side[k], periph::Sequencer::kPattern[((idx % 4) + 4) % 4]);
                }
            for (int k = 0; k < 3; ++k) alone[k] = side[k];
            unsigned f_side[3], f_alone[3];
            State* states[3] = {&side[0], &side[1], &side[2]};
            periph::StepperMotor::step_grid(motors, states, f_side, lanes);
            for (int k = 0; k < lanes; ++k) {
                f_alone[k] = motors[k]->step(alone[k], motors[k]->params().step_tstates);
                ASSERT_EQ(bits(side[k]), bits(alone[k])) << "lane " << k << " of " << lanes << ", step " << n;
                ASSERT_EQ(f_side[k], f_alone[k]);
                stops += f_side[k] != 0;
                at_rest += side[k].omega == 0.0;
            }
        }
    }
    EXPECT_GT(stops, 100);    // the end stops were exercised
    EXPECT_GT(at_rest, 100);  // so was stiction
}

TEST(MachineTool, IsAPartWithNoEvents) {
    MachineTool m(kClock);
    periph::Part& p = m;
    EXPECT_EQ(p.next_event(), periph::Part::kNever);
    p.advance(12345);
    EXPECT_EQ(p.now(), 12345u);
    p.reset(20000);
    EXPECT_EQ(p.now(), 20000u);
    EXPECT_EQ(p.name(), "machine tool");
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

// Found by input_fuzz: an ideal table driven onto its low stop (5 mm = 100 steps below the
// power-on position), then switched to the physical model, saved a rotor angle one rounding
// beyond the stop's, which its own load refused.
TEST(MachineToolIdeal, ARotorLeftAtAStopBySwitchingModelsSavesAndLoads) {
    MachineTool m(kClock);
    m.set_model(MachineTool::MotorModel::Ideal);
    std::uint64_t t = 1000;
    for (int k = 0; k < 110; ++k, t += 12'000) {
        m.set_drive(MachineTool::Axis::X, true, false, t);
        m.set_drive(MachineTool::Axis::X, false, false, t + 6'000);
    }
    ASSERT_EQ(m.table_steps(MachineTool::Axis::X), -100.0);
    m.set_model(MachineTool::MotorModel::Physical);
    m.advance(t + 3'072'000);
    std::vector<std::uint8_t> saved;
    m.save(saved);
    MachineTool copy(kClock);
    EXPECT_NO_THROW(copy.load(saved));
    EXPECT_NEAR(copy.table_mm(MachineTool::Axis::X), -5.0, 1e-9);
}

}  // namespace
}  // namespace alp85::test
