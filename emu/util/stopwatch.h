// Host time for benchmarks and reports: wall-clock seconds and the process's CPU seconds (which
// other load on the machine does not inflate) since construction.
#pragma once

#include <chrono>
#include <ctime>

namespace alp85 {

class Stopwatch {
public:
    double wall_seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count(); }
    double cpu_seconds() const { return process_cpu() - cpu_; }

private:
    static double process_cpu() {
        timespec ts{};
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
    }
    std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
    double cpu_ = process_cpu();
};

}  // namespace alp85
