// The calibration sweep of docs/machine.md and the doc's figures. Run by hand:
//   machine_calibrate [--mass KG] [--rf OHM] [--steps N] [--h TSTATES] [--rates LO HI INC]
//                     [--ramp ACC] [--mu MU] [--detent NM] [--viscous NMS]        -> CSV on stdout
//   machine_calibrate --sampled [--steps N] [--rates LO HI INC]                   -> CSV on stdout
//   machine_calibrate --replay FILE      -> lost steps of X and Y for the pulses in FILE, one a line:
//                                           "seconds axis(0 X, 1 Y) direction(1 +)" in time order
//                                           (tests/master/replay_samples.py writes the model's)
//   machine_calibrate --plot DIR                                                  -> DIR/*.svg
// A start-stop run: N pulses at a fixed rate from standstill (pulse high half the period, as a
// square-wave generator gives, thesis §5.1), then an abrupt stop and 0.5 s to settle; lost steps =
// commanded - actual (rounded). With --ramp ACC, a ramped run instead: from 250 steps/s up to the
// rate at ACC steps/s^2, N steps there and down again (§5.1: "any rotational speed between 0 and
// 500 steps/sec can be reached"). --rf sets the freewheel resistance Rf (ohm), --mu the slideway's
// friction, --detent and --viscous the motor's (docs/machine.md "Calibration"). --sampled: the master
// program's 2 ms sampling output ramped up to each rate (sim.h sampled_loss; docs/results.md).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "emu/plot/plot.h"
#include "tests/machine/sim.h"

using namespace alp85;
using namespace alp85::test;

namespace {

// A sweep's chart: lost steps against the step rate, one series per parameter value.
void lost_against_rate(const std::string& title, const std::vector<plot::Series>& series, const std::string& path) {
    plot::Chart c;
    c.title = title;
    c.x_label = "step rate (steps/s)";
    c.y_label = "lost steps";
    c.series = series;
    c.legend = plot::Chart::Legend::TopLeft;
    plot::write(c, path);
}

void figures(const std::string& dir, const std::string& ext) {
    // 1. Step response: one step from rest (pulse high for 1 ms), rotor angle every 0.1 ms.
    {
        MachineTool m(kClock);
        const std::uint64_t t0 = 1000;
        plot::Series rotor{"rotor (physical model)", {}}, ideal{"ideal model", {{-1, 0}, {0, 0}, {0, 1.8}, {40, 1.8}}, false, true};
        plot::Series current{"phase A current x 10 (A)", {}};
        for (int k = -10; k <= 400; ++k) {
            const double ms = k * 0.1;
            if (k == 0) m.set_drive(Axis::X, true, true, t0);
            if (k == 10) m.set_drive(Axis::X, false, true, t0 + 3072);
            if (k >= 0) m.advance(t0 + tstates(ms / 1000));
            rotor.points.push_back({ms, m.rotor_angle_deg(Axis::X)});
            const auto i = m.winding_currents(Axis::X);
            current.points.push_back({ms, 10 * (i[0] - i[1])});
        }
        plot::write_time_series(dir + "/step_response" + ext,
                                "One step from rest: the rotor's damped ringing (28 kg table, 24 V)",
                                {rotor, ideal, current}, "rotor angle (deg)", "t (ms)", plot::Chart::Legend::Right);
    }
    // 2. Start-stop sweep: lost steps against the rate, three table masses.
    {
        std::vector<plot::Series> series;
        for (double mass : {14.0, 28.0, 40.0}) {
            auto p = MachineTool::default_params();
            p.axes[0].table.mass_kg = mass;
            plot::Series s{"table " + std::to_string(static_cast<int>(mass)) + " kg" + (mass == 28.0 ? " (calibrated)" : ""),
                           {}};
            for (int rate = 50; rate <= 700; rate += 10)
                s.points.push_back({static_cast<double>(rate), static_cast<double>(start_stop_loss(p, 200, rate))});
            series.push_back(s);
        }
        lost_against_rate("Start-stop runs of 200 steps: lost steps against the step rate", series,
                          dir + "/start_stop_sweep" + ext);
    }
    // 3. Ramped runs: up from 250 steps/s at 1250 steps/s^2, 2000 steps at the rate, down again;
    // lost steps against the rate, for the freewheel resistance before (100 ohm) and calibrated.
    {
        std::vector<plot::Series> series;
        for (double rf : {100.0, 600.0}) {
            auto p = MachineTool::default_params();
            p.axes[0].motor.freewheel_ohm = rf;
            plot::Series s{"Rf " + std::to_string(static_cast<int>(rf)) + " ohm" + (rf == 600.0 ? " (calibrated)" : ""), {}};
            for (int rate = 300; rate <= 650; rate += 10) s.points.push_back({static_cast<double>(rate), static_cast<double>(ramped_loss(p, 2000, rate, 1250))});
            series.push_back(s);
        }
        lost_against_rate("Ramped runs (250 steps/s up at 1250 steps/s^2, 2000 steps at the rate): lost steps", series,
                          dir + "/ramp_sweep" + ext);
    }
}

}  // namespace

// The pulses of a file on the physical motors (X and Y), then 0.5 s to settle.
int replay(const char* file) {
    std::FILE* f = std::fopen(file, "r");
    if (!f) {
        std::fprintf(stderr, "machine_calibrate: cannot open %s\n", file);
        return 2;
    }
    MachineTool m(kClock);
    m.set_model(MachineTool::MotorModel::Physical);
    double t = 0, last = 0;
    int axis = 0, dir = 0, line = 0;
    bool behind[2] = {false, false};
    while (std::fscanf(f, "%lf %d %d", &t, &axis, &dir) == 3) {
        ++line;
        if (t < last || (axis != 0 && axis != 1)) {
            std::fprintf(stderr, "machine_calibrate: %s:%d: pulses out of order or axis not 0/1\n", file, line);
            std::fclose(f);
            return 2;
        }
        last = t;
        const Axis a = axis ? Axis::Y : Axis::X;
        m.set_drive(a, true, dir != 0, tstates(t));
        m.set_drive(a, false, dir != 0, tstates(t + 0.001));
        for (Axis b : {Axis::X, Axis::Y}) {  // where each motor first falls 2.5 steps behind or ahead
            const int k = b == Axis::X ? 0 : 1;
            if (!behind[k] && std::fabs(static_cast<double>(m.commanded_steps(b)) - m.table_steps(b)) > 2.5) {
                behind[k] = true;
                std::printf("%c out of step at %.3f s, commanded X %lld Y %lld\n", k ? 'Y' : 'X', t,
                            static_cast<long long>(m.commanded_steps(Axis::X)), static_cast<long long>(m.commanded_steps(Axis::Y)));
            }
        }
    }
    std::fclose(f);
    m.advance(tstates(last + 0.5));
    std::printf("lost X %lld, lost Y %lld (of %lld, %lld net commanded)\n", static_cast<long long>(m.lost_steps(Axis::X)),
                static_cast<long long>(m.lost_steps(Axis::Y)), static_cast<long long>(m.commanded_steps(Axis::X)),
                static_cast<long long>(m.commanded_steps(Axis::Y)));
    return 0;
}

int main(int argc, char** argv) {
    std::vector<double> masses = {14, 20, 24, 26, 28, 30, 35, 40};
    int n = 200, lo = 50, hi = 700, inc = 10;
    unsigned h = 0;
    double rf = -1, ramp = 0, mu = -1, detent = -1, viscous = -1;
    bool sampled = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--plot") && i + 1 < argc) {
            const std::string dir = argv[++i];
            figures(dir, i + 1 < argc && !std::strcmp(argv[i + 1], "--png") ? ".png" : ".svg");
            return 0;
        }
        if (!std::strcmp(argv[i], "--mass") && i + 1 < argc) masses = {std::atof(argv[++i])};
        if (!std::strcmp(argv[i], "--rf") && i + 1 < argc) rf = std::atof(argv[++i]);
        if (!std::strcmp(argv[i], "--ramp") && i + 1 < argc) ramp = std::atof(argv[++i]);
        if (!std::strcmp(argv[i], "--mu") && i + 1 < argc) mu = std::atof(argv[++i]);
        if (!std::strcmp(argv[i], "--sampled")) sampled = true;
        if (!std::strcmp(argv[i], "--replay") && i + 1 < argc) return replay(argv[i + 1]);
        if (!std::strcmp(argv[i], "--detent") && i + 1 < argc) detent = std::atof(argv[++i]);
        if (!std::strcmp(argv[i], "--viscous") && i + 1 < argc) viscous = std::atof(argv[++i]);
        if (!std::strcmp(argv[i], "--steps") && i + 1 < argc) n = std::atoi(argv[++i]);
        if (!std::strcmp(argv[i], "--h") && i + 1 < argc) h = static_cast<unsigned>(std::atoi(argv[++i]));
        if (!std::strcmp(argv[i], "--rates") && i + 3 < argc) {
            lo = std::atoi(argv[++i]);
            hi = std::atoi(argv[++i]);
            inc = std::atoi(argv[++i]);
        }
    }
    std::printf("mass_kg,rf_ohm,rate,lost\n");
    for (double mass : masses) {
        auto p = MachineTool::default_params();
        p.axes[0].table.mass_kg = mass;
        if (h) p.axes[0].motor.step_tstates = h;
        if (rf >= 0) p.axes[0].motor.freewheel_ohm = rf;
        if (mu >= 0) p.axes[0].table.friction_mu = mu;
        if (detent >= 0) p.axes[0].motor.detent_nm = detent;
        if (viscous >= 0) p.axes[0].motor.viscous_nms = viscous;
        for (int rate = lo; rate <= hi; rate += inc) {
            const auto lost = sampled    ? sampled_loss(p, n, rate / 500.0)
                              : ramp > 0 ? ramped_loss(p, n, rate, ramp)
                                         : start_stop_loss(p, n, rate);
            std::printf("%g,%g,%d,%lld\n", mass, p.axes[0].motor.freewheel_ohm, rate, static_cast<long long>(lost));
            std::fflush(stdout);
        }
    }
}
