// The machine-tool table of one axis: the slide the lead screw moves, its travel, its end stops and
// the load it puts on the motor.
//
// Pins as modelled: none (mechanics). Inputs: the rotor angle of the axis motor; outputs: the table
// position in mm, the load the motor sees (reflected inertia, Coulomb friction), the end-stop state.
//
// Sources:
//   - thesis §3.1: one step = 0.05 mm ("accuracy tolerance"), gear box + lead screw chosen so that
//     200 steps (one motor revolution) = 10 mm: the lead seen by the motor is 10 mm/rev;
//   - thesis §3.1: the largest workpiece is 100 mm x 200 mm x 1500 mm. Travel: X = 1500 mm (the
//     longitudinal traverse of a knee-type milling table, the longest axis; X and Y are the
//     interpolated plane of §3.3), Y = 200 mm (cross traverse), Z = 100 mm (the height entered
//     first as "HI=", §4.4.1, independent of X and Y).
//   - end stops: not in the thesis. The work range is [0, travel] from the power-on position
//     (the firmware counts coordinates from where the table stood); hard stops sit `overtravel_mm`
//     beyond each end (default 5 mm, a typical allowance), the screw stalls the motor there;
//   - mass and friction: not in the thesis; `mass_kg` is calibrated to §5.1's start-stop limit
//     (with the motor's freewheel resistance, calibrated to §5.1's 500 steps/s reached by a ramp:
//     docs/machine.md, "Calibration"); mu is a typical lubricated slideway figure (0.1).
//
// Not emulated: backlash in the gears and the screw, screw and gear-box inertia (lumped into the
// equivalent mass), elasticity of the screw, a cutting load, limit switches (the thesis has none).
#pragma once

#include <cstdint>

namespace alp85::periph {

class Table {
public:
    struct Params {
        double lead_mm_per_rev = 10.0;   // thesis §3.2.2: 200 steps x 0.05 mm
        double travel_mm = 1500.0;       // work range [0, travel_mm] from the power-on position
        double overtravel_mm = 5.0;      // hard stops at -overtravel and travel + overtravel (assumed)
        double mass_kg = 28.0;           // equivalent moving mass (calibrated, docs/machine.md)
        double friction_mu = 0.1;        // Coulomb friction coefficient of the slideway (assumed)
        double screw_efficiency = 1.0;   // friction torque reflected at the motor = mu m g lead / (2 pi eta)
    };

    // End-stop bookkeeping: where the table stands and the last time it hit a stop.
    struct State {
        std::int8_t at_stop = 0;         // -1 at the low stop, +1 at the high stop, 0 free
        std::uint32_t hits = 0;          // number of arrivals at a stop
        std::uint64_t last_hit_t = 0;    // T-state of the last arrival
        bool last_hit_high = false;

        template <class S, class Io>
        static void fields(S& s, Io& io) { io(s.at_stop), io(s.hits), io(s.last_hit_t), io(s.last_hit_high); }
    };

    Table() = default;
    explicit Table(Params p) : p_(p) {}

    const Params& params() const { return p_; }
    double mm_per_rad() const;
    double low_stop_mm() const { return -p_.overtravel_mm; }
    double high_stop_mm() const { return p_.travel_mm + p_.overtravel_mm; }
    // The load at the motor shaft.
    double reflected_inertia() const;       // kg m^2
    double reflected_friction() const;      // N m (Coulomb)

    // Records the table's stop state after a move; returns true on an arrival at a stop.
    bool update_stop(State& s, std::int8_t at, std::uint64_t t) const;

private:
    Params p_;
};

}  // namespace alp85::periph
