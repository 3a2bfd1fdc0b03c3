// One axis of the machine tool's table driven by a servomechanism from an output channel of the
// Pisa interpolator (paper §2.4: "Output data ... are transferred in real time from the RWM to the
// digital-analog converters of the servomechanisms").
//
// Model (docs/pisa.md "Servos"): the converter holds the last eight digits written to it (OUT),
// read as a ten's-complement position in µm, and turns it into a reference voltage at once (zero-
// order hold). The position loop is first order: the table's speed is Kv times the following
// error, dp/dt = Kv (c - p), solved exactly between writes: p(t) = c + (p0 - c) e^(-Kv t).
// Kv = 25 1/s (a following error of 0.4 mm at 600 mm/min, typical of 1960s contouring servos).
// The table is the machine tool's (peripherals/table.h): its travel from the start position and
// its hard stops, where the slide stands still.
//
// Not emulated: the converter's resolution and settling, velocity saturation, the motor's and
// the drive's own lags (a second-order loop), backlash, friction.
#pragma once

#include <cstdint>

#include "peripherals/table.h"

namespace alp85::pisa {

class ServoAxis {
public:
    struct Params {
        double kv_per_s = 25.0;
        double step_s = 100e-9;    // one digit step of the interpolator
        double start_mm = 0.0;     // where program zero stands on the table
        periph::Table::Params table{};
    };
    ServoAxis() : ServoAxis(Params()) {}
    explicit ServoAxis(Params p) : p_(p), table_(p.table) { reset(); }

    void reset();
    void command(std::int64_t um, std::uint64_t t);  // a converter write at digit step t
    void advance(std::uint64_t t);                   // exact solution up to t

    std::int64_t command_um() const { return command_um_; }
    double position_mm() const { return pos_mm_; }   // from program zero
    double table_mm() const { return pos_mm_ + p_.start_mm; }
    bool at_stop() const { return stop_ != 0; }
    const Params& params() const { return p_; }

private:
    Params p_;
    periph::Table table_;
    std::int64_t command_um_ = 0;
    double pos_mm_ = 0;
    std::uint64_t t_ = 0;
    int stop_ = 0;
    std::uint32_t hits_ = 0;
};

}  // namespace alp85::pisa
