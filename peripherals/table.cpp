// The machine-tool table of one axis; see table.h.
#include "peripherals/table.h"

#include <numbers>

namespace alp85::periph {

namespace {
constexpr double kG = 9.80665;
}

double Table::mm_per_rad() const { return p_.lead_mm_per_rev / (2.0 * std::numbers::pi); }

double Table::reflected_inertia() const {
    const double r = p_.lead_mm_per_rev * 1e-3 / (2.0 * std::numbers::pi);  // m per rad
    return p_.mass_kg * r * r;
}

double Table::reflected_friction() const {
    const double r = p_.lead_mm_per_rev * 1e-3 / (2.0 * std::numbers::pi);
    return p_.friction_mu * p_.mass_kg * kG * r / p_.screw_efficiency;
}

bool Table::update_stop(State& s, std::int8_t at, std::uint64_t t) const {
    const bool arrival = at != 0 && s.at_stop != at;
    if (arrival) {
        ++s.hits;
        s.last_hit_t = t;
        s.last_hit_high = at > 0;
    }
    s.at_stop = at;
    return arrival;
}

}  // namespace alp85::periph
