// The machine tool of the ALP 85 (thesis Chapter III): three axes X, Y, Z, each a sequencer
// (sequencer.h), a PH265-03 stepping motor on a unipolar drive (stepper_motor.h), a table on a lead
// screw with end stops (table.h) and an incremental linear transducer (transducer.h). One Part.
//
// Pins as modelled, per axis (the board wires them to 8155 ports; no port numbers here):
//   PULSE, DIRECTION in          -> set_drive(axis, pulse, direction, t)
//   COUNT, DIRECTION out         -> sense(axis, t)
// RESET: the tool has no reset input (the sequencers are not on RESET OUT); reset() only catches up.
//
// Time: T-states of the clock its builder gives (the ALP 85's CPU clock, 3.072 MHz). The tool
// changes nothing the CPU sees unless the CPU reads it, so next_event() is kNever; it integrates
// lazily in advance(). The physical model runs on a fixed grid anchored at each phase change
// (stepper_motor.h), and a reading between grid points is computed from a copy: results depend
// only on the drive inputs and their T-states, never on when or how often the board calls
// advance() or sense(). Settled rotors are not integrated: with all three settled, advance() is
// three flag tests.
//
// Snapshot: tag "TOOL"; the model, and per axis the sequencer, motor, transducer and table state
// (doubles bit-exact) and the grid time. Parameters are configuration, not state: load a snapshot
// into a tool built with the same parameters.
//
// Not emulated: see the four parts' headers; also any coupling between axes (a common supply, the
// frame), and the tool spindle (the thesis controls the table only).
#pragma once

#include <array>
#include <cstdint>
#include <functional>

#include "peripherals/part.h"
#include "peripherals/sequencer.h"
#include "peripherals/stepper_motor.h"
#include "peripherals/table.h"
#include "peripherals/transducer.h"

namespace alp85::periph {

class MachineTool final : public Part {
public:
    enum class Axis : std::uint8_t { X, Y, Z };
    enum class MotorModel : std::uint8_t { Ideal, Physical };
    // What the transducers read: the scale on the table (closed loop, the thesis's machine), or
    // the commanded steps (the bits derived from the sequencer's pulses: an open loop, for
    // comparing with the thesis's open-loop results; the table itself still moves as the motor does).
    enum class Feedback : std::uint8_t { Scale, Commanded };
    static constexpr int kAxes = 3;

    struct Sense {
        bool count;
        bool direction;
    };

    struct AxisParams {
        Sequencer::Params sequencer;
        StepperMotor::Params motor;
        Table::Params table;
        Transducer::Params transducer;
    };
    struct Params {
        std::array<AxisParams, kAxes> axes;
    };
    // X 1500 mm, Y 200 mm, Z 100 mm of travel (table.h); everything else as the parts' defaults.
    static Params default_params();

    struct EndStop {
        std::int8_t at = 0;            // -1 low stop, +1 high stop, 0 free
        std::uint32_t hits = 0;        // arrivals so far
        std::uint64_t last_hit_t = 0;  // T-state of the last arrival
        bool last_hit_high = false;
    };
    using EndStopFn = std::function<void(Axis, bool high, std::uint64_t t)>;

    struct AxisState {
        Sequencer::State sequencer;
        StepperMotor::State motor;
        Transducer::State transducer;
        Table::State table;
        std::int64_t ideal_steps = 0;  // actual steps of the ideal model
        std::uint64_t grid_t = 0;      // T-state the motor state is at (physical, not settled)

        template <class S, class Io>
        static void fields(S& s, Io& io) {
            Sequencer::State::fields(s.sequencer, io);
            StepperMotor::State::fields(s.motor, io);
            Transducer::State::fields(s.transducer, io);
            Table::State::fields(s.table, io);
            io(s.ideal_steps), io(s.grid_t);
        }
    };
    struct State {
        MotorModel model = MotorModel::Physical;
        Feedback feedback = Feedback::Scale;
        std::array<AxisState, kAxes> axes{};
        std::uint64_t now = 0;

        template <class S, class Io>
        static void fields(S& s, Io& io) {
            io(s.model, MotorModel::Physical);
            io(s.feedback, Feedback::Commanded);
            for (auto& a : s.axes) AxisState::fields(a, io);
            io(s.now);
        }
    };

    // clock_hz: T-states per second of every time it is given (its builder's clock; the ALP 85's
    // is board::kCpuHz).
    explicit MachineTool(double clock_hz, const Params& p = default_params());

    // Part
    std::string_view name() const override { return "machine tool"; }
    void describe(Description& d) const override;
    // Per axis (scope "X", "Y", "Z"): PULSE and DIR (the sequencer's inputs), A, nA, B, nB (its
    // phase drives, 1 = transistor on), COUNT and CDIR (the transducer's outputs to port B), and as
    // quantities the four half-winding currents IA, InA, IB, InB (A) and the rotor angle ANGLE
    // (degrees from power-on), all at now(). The transducer's outputs and the quantities move with
    // the physics between the board's accesses: a recorder samples them.
    void pins(Pins& p, std::uint64_t now) const override;
    std::string_view tag() const override { return "TOOL"; }
    std::uint8_t state_version() const override { return 2; }
    void reset(std::uint64_t now) override { advance(now); }
    void advance(std::uint64_t now) override;
    std::uint64_t next_event() const override { return kNever; }
    std::uint64_t now() const override { return s_.now; }
    void save_state(StateWriter& w) const override { State::fields(s_, w); }
    void load_state(StateReader& r) override;

    // The run's motor model (switching puts every rotor at rest on its nearest step).
    void set_model(MotorModel m);
    MotorModel model() const { return s_.model; }
    // What the transducers read from now on (switching walks them to the new source's position).
    void set_feedback(Feedback f);
    Feedback feedback() const { return s_.feedback; }
    // Input levels at T-state t (advances to t first).
    void set_drive(Axis axis, bool pulse, bool direction, std::uint64_t t);
    // Transducer outputs at t (advances to t first).
    Sense sense(Axis axis, std::uint64_t t);
    // Called when a table arrives at an end stop.
    void on_end_stop(EndStopFn fn) { on_end_stop_ = std::move(fn); }
    // The operator sets up a new workpiece at T-state t (docs/machine.md, "Setting up a new
    // workpiece"): the drives switched off, each table wound back by its handwheel to where it
    // stood at power-on, the drives on again. Each axis's sequencer count, rotor, table and
    // transducer are then as at power-on (off its end stop); the PULSE and DIRECTION levels the
    // board drives, the motor model, the feedback, the end-stop arrivals counted so far and the
    // time stay. The board is not told: the firmware's own position counts stay as they were.
    void set_up_workpiece(std::uint64_t t);

    // Views at now() (no side effects).
    std::int64_t commanded_steps(Axis axis) const;   // the sequencer's count
    double rotor_angle_deg(Axis axis) const;         // from the power-on position
    double rotor_speed_rad_s(Axis axis) const;
    double table_mm(Axis axis) const;                // 0 = power-on position
    double table_steps(Axis axis) const;             // table_mm / 0.05 (not rounded)
    std::int64_t transducer_count(Axis axis) const;  // signed increments, as the firmware counts them
    std::int64_t lost_steps(Axis axis) const;        // commanded - actual, rounded to whole steps
    std::uint8_t phase_pattern(Axis axis) const;     // Sequencer bits: 8 A, 4 /A, 2 B, 1 /B
    std::array<double, 4> winding_currents(Axis axis) const;  // A, /A, B, /B (A)
    EndStop end_stop(Axis axis) const;
    bool settled(Axis axis) const;
    bool all_settled() const;

    const Params& params() const { return p_; }
    const StepperMotor& motor(Axis axis) const { return ax_[idx(axis)].motor; }
    const Table& table(Axis axis) const { return ax_[idx(axis)].table; }
    const Transducer& transducer(Axis axis) const { return ax_[idx(axis)].transducer; }
    const State& state() const { return s_; }

private:
    struct AxisParts {
        Sequencer sequencer;
        StepperMotor motor;
        Table table;
        Transducer transducer;
        double step_mm = 0.05;          // lead / steps per revolution
        double mm_per_rad = 0;
        std::int64_t lo_steps = 0, hi_steps = 0;  // the end stops in whole steps (ideal model)
    };
    static int idx(Axis a) { return static_cast<int>(a); }
    void after_step(int a, unsigned flags, std::uint64_t t);
    StepperMotor::State motor_view(int a) const;
    double position_mm(int a, const StepperMotor::State& m) const;
    double feedback_mm(int a, const StepperMotor::State& m) const;
    double theta_of_steps(int a, std::int64_t steps) const;
    void init_axis(int a);

    Params p_;
    std::array<AxisParts, kAxes> ax_;
    State s_;
    EndStopFn on_end_stop_;
};

}  // namespace alp85::periph
