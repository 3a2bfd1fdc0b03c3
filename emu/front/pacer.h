// The emulation's clock against the host's: at a speed s the machine should have reached
// base_t + (host - base_host) * 3.072 MHz * s. The base is absolute, so rounding never accumulates
// (no drift); it is set again when the speed changes, on pause/run, and when the machine has fallen
// more than kMaxLag behind (it cannot keep up: it then runs as fast as it can, and the clock does
// not try to catch up afterwards). Speed 0 means as fast as possible.
//
// The one pacer of every front end: the window's and the page's frames, DAP's slices between
// messages.
//
// Frames: next_frame() gives the deadline of the next frame (60 per second), from an absolute
// start as well; a frame that overran skips the deadlines it missed.
#pragma once

#include <chrono>
#include <cstdint>

#include "emu/script/session.h"

namespace alp85::front {

using HostClock = std::chrono::steady_clock;

class Pacer {
public:
    static constexpr double kClockHz = board::kCpuHz;
    static constexpr double kMaxLag = 0.25;  // host seconds of simulated time

    void set_speed(double speed, std::uint64_t machine_now, HostClock::time_point host);
    double speed() const { return speed_; }
    bool max_speed() const { return speed_ <= 0; }
    void rebase(std::uint64_t machine_now, HostClock::time_point host);
    // The machine time to reach by `host` (for max speed: no limit, the caller's budget decides).
    std::uint64_t target(std::uint64_t machine_now, HostClock::time_point host);
    // How far the machine is ahead of the host's clock, in host time (0 when behind or at max
    // speed): how long a front end between slices (DAP) waits before the next.
    std::chrono::milliseconds ahead(std::uint64_t machine_now, HostClock::time_point host) const;

private:
    double speed_ = 1;
    std::uint64_t base_t_ = 0;
    HostClock::time_point base_host_{};
};

class FrameClock {
public:
    static constexpr std::chrono::nanoseconds kPeriod{16'666'667};
    explicit FrameClock(HostClock::time_point start) : start_(start) {}
    // The deadline of the frame after the one that ends now; with `every` = 2, of the next frame
    // of a grid twice as coarse (30 frames a second).
    HostClock::time_point next(HostClock::time_point now, int every = 1);
    // A wait ended early (an event): the grid goes on from the first deadline after `now`.
    HostClock::time_point resume(HostClock::time_point now) {
        frame_ = (now - start_) / kPeriod + 1;
        return start_ + kPeriod * frame_;
    }

private:
    HostClock::time_point start_;
    std::int64_t frame_ = 0;
};

}  // namespace alp85::front
