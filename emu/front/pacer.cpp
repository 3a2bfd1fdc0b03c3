#include "emu/front/pacer.h"

#include <limits>

namespace alp85::front {

void Pacer::set_speed(double speed, std::uint64_t machine_now, HostClock::time_point host) {
    speed_ = speed;
    rebase(machine_now, host);
}

void Pacer::rebase(std::uint64_t machine_now, HostClock::time_point host) {
    base_t_ = machine_now;
    base_host_ = host;
}

std::uint64_t Pacer::target(std::uint64_t machine_now, HostClock::time_point host) {
    if (max_speed()) return std::numeric_limits<std::uint64_t>::max();
    const double rate = kClockHz * speed_;
    const double elapsed = std::chrono::duration<double>(host - base_host_).count();
    auto goal = base_t_ + static_cast<std::uint64_t>(elapsed * rate);
    if (goal > machine_now && static_cast<double>(goal - machine_now) > kMaxLag * rate) {
        // Fallen behind: from here on, real time counts from where the machine is.
        rebase(machine_now, host);
        goal = machine_now + static_cast<std::uint64_t>(kMaxLag * rate);
    }
    return goal;
}

std::chrono::milliseconds Pacer::ahead(std::uint64_t machine_now, HostClock::time_point host) const {
    if (max_speed() || machine_now <= base_t_) return std::chrono::milliseconds{0};
    const double machine_s = static_cast<double>(machine_now - base_t_) / (kClockHz * speed_);
    const double lead = machine_s - std::chrono::duration<double>(host - base_host_).count();
    return std::chrono::milliseconds{lead > 0 ? static_cast<std::int64_t>(lead * 1000) : 0};
}

HostClock::time_point FrameClock::next(HostClock::time_point now, int every) {
    ++frame_;
    frame_ += (every - frame_ % every) % every;
    auto deadline = start_ + kPeriod * frame_;
    if (deadline <= now) {  // overran: skip to the next deadline still ahead
        frame_ = (now - start_) / kPeriod + 1;
        frame_ += (every - frame_ % every) % every;
        deadline = start_ + kPeriod * frame_;
    }
    return deadline;
}

}  // namespace alp85::front
