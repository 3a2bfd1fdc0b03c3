// The first-order position loop, solved exactly between converter writes.
#include "emu/pisa/servo.h"

#include <cmath>

namespace alp85::pisa {

void ServoAxis::reset() {
    command_um_ = 0;
    pos_mm_ = 0;
    t_ = 0;
    stop_ = 0;
    hits_ = 0;
}

void ServoAxis::advance(std::uint64_t t) {
    if (t <= t_) return;
    double dt = static_cast<double>(t - t_) * p_.step_s;
    double c = static_cast<double>(command_um_) / 1000.0;
    double p = c + (pos_mm_ - c) * std::exp(-p_.kv_per_s * dt);
    // The hard stops (table.h): the slide stands there while the command lies beyond.
    double lo = table_.low_stop_mm() - p_.start_mm, hi = table_.high_stop_mm() - p_.start_mm;
    int at = 0;
    if (p <= lo) p = lo, at = -1;
    if (p >= hi) p = hi, at = 1;
    if (at != 0 && stop_ == 0) ++hits_;
    stop_ = at;
    pos_mm_ = p;
    t_ = t;
}

void ServoAxis::command(std::int64_t um, std::uint64_t t) {
    advance(t);
    command_um_ = um;
}

}  // namespace alp85::pisa
