// The machine tool: three axes of sequencer, motor, table and transducer; see machine_tool.h.
#include "peripherals/machine_tool.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace alp85::periph {

MachineTool::Params MachineTool::default_params() {
    Params p;
    p.axes[0].table.travel_mm = 1500.0;  // X: the workpiece's length (thesis §3.1)
    p.axes[1].table.travel_mm = 200.0;   // Y: its width
    p.axes[2].table.travel_mm = 100.0;   // Z: its height
    return p;
}

MachineTool::MachineTool(double clock_hz, const Params& p) : p_(p) {
    for (int a = 0; a < kAxes; ++a) {
        const AxisParams& ap = p.axes[a];
        AxisParts& x = ax_[a];
        x.sequencer = Sequencer(ap.sequencer);
        x.table = Table(ap.table);
        x.transducer = Transducer(ap.transducer);
        x.mm_per_rad = x.table.mm_per_rad();
        StepperMotor::Load load;
        load.inertia = x.table.reflected_inertia();
        load.coulomb = x.table.reflected_friction();
        load.theta_lo = x.table.low_stop_mm() / x.mm_per_rad;
        load.theta_hi = x.table.high_stop_mm() / x.mm_per_rad;
        x.motor.configure(ap.motor, load, clock_hz);
        x.step_mm = ap.table.lead_mm_per_rev / (4.0 * ap.motor.rotor_teeth);
        x.lo_steps = static_cast<std::int64_t>(std::ceil(x.table.low_stop_mm() / x.step_mm - 1e-9));
        x.hi_steps = static_cast<std::int64_t>(std::floor(x.table.high_stop_mm() / x.step_mm + 1e-9));
        init_axis(a);
    }
}

void MachineTool::init_axis(int a) {
    AxisState& st = s_.axes[a];
    st = AxisState{};
    ax_[a].motor.init_at_rest(st.motor, 0.0, Sequencer::phases(st.sequencer));
    ax_[a].transducer.init(st.transducer, 0.0);
}

// The rotor angle of a whole step count, kept inside the end stops: a step count at a stop,
// multiplied out, can land one rounding below the stop's own angle (found by input_fuzz).
double MachineTool::theta_of_steps(int a, std::int64_t steps) const {
    const StepperMotor::Load& load = ax_[a].motor.load();
    return std::clamp(static_cast<double>(steps) * ax_[a].motor.step_angle(), load.theta_lo, load.theta_hi);
}

double MachineTool::feedback_mm(int a, const StepperMotor::State& m) const {
    if (s_.feedback == Feedback::Commanded) return static_cast<double>(s_.axes[a].sequencer.count) * ax_[a].step_mm;
    return position_mm(a, m);
}

void MachineTool::set_feedback(Feedback f) {
    if (f == s_.feedback) return;
    s_.feedback = f;
    // The transducers walk (counting) to what they now read, as a scale would if moved there.
    for (int a = 0; a < kAxes; ++a) ax_[a].transducer.update(s_.axes[a].transducer, feedback_mm(a, motor_view(a)));
}

double MachineTool::position_mm(int a, const StepperMotor::State& m) const {
    if (s_.model == MotorModel::Ideal) return static_cast<double>(s_.axes[a].ideal_steps) * ax_[a].step_mm;
    return m.theta * ax_[a].mm_per_rad;
}

inline void MachineTool::after_step(int a, unsigned flags, std::uint64_t t) {
    AxisState& st = s_.axes[a];
    if (s_.feedback == Feedback::Scale) ax_[a].transducer.update(st.transducer, st.motor.theta * ax_[a].mm_per_rad);
    const std::int8_t at = (flags & StepperMotor::kStopHigh) ? 1 : (flags & StepperMotor::kStopLow) ? -1 : 0;
    if (at != st.table.at_stop && ax_[a].table.update_stop(st.table, at, t) && on_end_stop_)
        on_end_stop_(static_cast<Axis>(a), at > 0, t);
}

// The axes are independent: each pass steps every axis that is due by one grid step, side by side
// (StepperMotor::step_grid interleaves the three integrations, so the host overlaps them). Each
// axis goes through exactly the same steps, bit for bit, as when integrated alone.
void MachineTool::advance(std::uint64_t now) {
    if (now <= s_.now) return;
    if (s_.model == MotorModel::Physical) {
        // Grid steps due per axis.
        std::uint64_t due[kAxes];
        for (int a = 0; a < kAxes; ++a) {
            const AxisState& st = s_.axes[a];
            due[a] = st.motor.settled || st.grid_t >= now ? 0 : (now - st.grid_t) / ax_[a].motor.params().step_tstates;
        }
        for (;;) {
            const StepperMotor* motors[kAxes];
            StepperMotor::State* states[kAxes];
            int lane_axis[kAxes];
            int n = 0;
            for (int a = 0; a < kAxes; ++a) {
                if (due[a] == 0) continue;
                motors[n] = &ax_[a].motor;
                states[n] = &s_.axes[a].motor;
                lane_axis[n++] = a;
            }
            if (n == 0) break;
            // The same lanes until one of them is done or settles.
            std::uint64_t passes = due[lane_axis[0]];
            for (int k = 1; k < n; ++k) passes = std::min(passes, due[lane_axis[k]]);
            for (bool same = true; same && passes > 0; --passes) {
                unsigned flags[kAxes];
                StepperMotor::step_grid(motors, states, flags, n);
                for (int k = 0; k < n; ++k) {
                    const int a = lane_axis[k];
                    AxisState& st = s_.axes[a];
                    st.grid_t += motors[k]->params().step_tstates;
                    after_step(a, flags[k], st.grid_t);
                    --due[a];
                    if (motors[k]->is_settled(st.motor)) st.motor.settled = true, due[a] = 0, same = false;
                }
            }
        }
    }
    s_.now = now;
}

void MachineTool::set_model(MotorModel m) {
    if (m == s_.model) return;
    for (int a = 0; a < kAxes; ++a) {
        AxisState& st = s_.axes[a];
        const double theta = s_.model == MotorModel::Ideal
                                 ? static_cast<double>(st.ideal_steps) * ax_[a].motor.step_angle()
                                 : motor_view(a).theta;
        st.ideal_steps = static_cast<std::int64_t>(std::llround(theta / ax_[a].motor.step_angle()));
    }
    s_.model = m;
    for (int a = 0; a < kAxes; ++a) {
        AxisState& st = s_.axes[a];
        ax_[a].motor.init_at_rest(st.motor, theta_of_steps(a, st.ideal_steps),
                                  Sequencer::phases(st.sequencer));
        st.grid_t = s_.now;
        ax_[a].transducer.update(st.transducer, feedback_mm(a, st.motor));
    }
}

void MachineTool::set_up_workpiece(std::uint64_t t) {
    advance(t);
    for (int a = 0; a < kAxes; ++a) {
        AxisState& st = s_.axes[a];
        st.sequencer.count = 0;  // the flip-flops' power-on index; the input levels stay
        st.ideal_steps = 0;
        st.grid_t = s_.now;
        ax_[a].motor.init_at_rest(st.motor, 0.0, Sequencer::phases(st.sequencer));
        ax_[a].transducer.init(st.transducer, 0.0);
        st.table.at_stop = 0;
    }
}

void MachineTool::set_drive(Axis axis, bool pulse, bool direction, std::uint64_t t) {
    advance(t);
    t = s_.now;  // a late call acts at the part's present time (time never runs backwards)
    const int a = idx(axis);
    AxisState& st = s_.axes[a];
    const int d = ax_[a].sequencer.set_inputs(st.sequencer, pulse, direction);
    if (d == 0) return;
    if (s_.feedback == Feedback::Commanded)
        ax_[a].transducer.update(st.transducer, static_cast<double>(st.sequencer.count) * ax_[a].step_mm);
    const std::uint8_t ph = Sequencer::phases(st.sequencer);
    if (s_.model == MotorModel::Ideal) {
        const std::int64_t next = st.ideal_steps + d;
        const AxisParts& x = ax_[a];
        const Table& table = x.table;
        std::int8_t at = 0;
        if (next > x.hi_steps || next < x.lo_steps) {
            at = d > 0 ? 1 : -1;  // the screw stalls the motor: the step is lost
        } else {
            st.ideal_steps = next;
            if (next == x.hi_steps) at = 1;
            if (next == x.lo_steps) at = -1;
        }
        st.motor.phases = ph;
        st.motor.theta = theta_of_steps(a, st.ideal_steps);
        ax_[a].transducer.update(st.transducer, feedback_mm(a, st.motor));
        if (at != st.table.at_stop && table.update_stop(st.table, at, t) && on_end_stop_)
            on_end_stop_(axis, at > 0, t);
        return;
    }
    // Physical: split the integration exactly at t.
    if (!st.motor.settled && t > st.grid_t) {
        const unsigned flags = ax_[a].motor.step(st.motor, static_cast<std::uint32_t>(t - st.grid_t));
        after_step(a, flags, t);
    }
    st.grid_t = t;
    StepperMotor::set_phases(st.motor, ph);
}

StepperMotor::State MachineTool::motor_view(int a) const {
    const AxisState& st = s_.axes[a];
    StepperMotor::State m = st.motor;
    if (s_.model == MotorModel::Physical && !m.settled && s_.now > st.grid_t)
        ax_[a].motor.step(m, static_cast<std::uint32_t>(s_.now - st.grid_t));
    return m;
}

MachineTool::Sense MachineTool::sense(Axis axis, std::uint64_t t) {
    advance(t);
    const int a = idx(axis);
    Transducer::State tr = s_.axes[a].transducer;
    if (s_.model == MotorModel::Physical && s_.feedback == Feedback::Scale)
        ax_[a].transducer.update(tr, position_mm(a, motor_view(a)));
    const auto o = ax_[a].transducer.outputs(tr);
    return {o.count, o.direction};
}

std::int64_t MachineTool::commanded_steps(Axis axis) const { return s_.axes[idx(axis)].sequencer.count; }

void MachineTool::pins(Pins& p, std::uint64_t now) const {
    (void)now;  // the tool's views are at now(): the board advances it before reading
    static constexpr std::string_view kAxis[kAxes] = {"X", "Y", "Z"};
    for (int a = 0; a < kAxes; ++a) {
        p.scope(kAxis[a]);
        const AxisState& s = s_.axes[a];
        p.logic("PULSE", s.sequencer.pulse);
        p.logic("DIR", s.sequencer.direction);
        const std::uint8_t ph = Sequencer::phases(s.sequencer);
        p.logic("A", ph & Sequencer::kA);
        p.logic("nA", ph & Sequencer::kAbar);
        p.logic("B", ph & Sequencer::kB);
        p.logic("nB", ph & Sequencer::kBbar);
        // What sense() would give now, without its advance.
        Transducer::State tr = s.transducer;
        const bool physical = s_.model == MotorModel::Physical;
        const StepperMotor::State m = physical ? motor_view(a) : s.motor;
        if (physical && s_.feedback == Feedback::Scale) ax_[a].transducer.update(tr, position_mm(a, m));
        const auto o = ax_[a].transducer.outputs(tr);
        p.logic("COUNT", o.count, false);
        p.logic("CDIR", o.direction, false);
        p.real("IA", physical ? m.i[0] : 0.0);
        p.real("InA", physical ? m.i[1] : 0.0);
        p.real("IB", physical ? m.i[2] : 0.0);
        p.real("InB", physical ? m.i[3] : 0.0);
        p.real("ANGLE", physical ? m.theta * 180.0 / std::numbers::pi
                                 : static_cast<double>(s.ideal_steps) * 360.0 / (4.0 * p_.axes[a].motor.rotor_teeth));
    }
}

void MachineTool::describe(Description& d) const {
    d.title = "machine tool (3 axes: sequencer, stepping motor, table, transducer)";
    d.add(Field::note("motors", s_.model == MotorModel::Ideal ? "ideal" : "physical"));
    d.add(Field::note("feedback", s_.feedback == Feedback::Scale ? "scale" : "commanded steps"));
    for (int a = 0; a < kAxes; ++a) {
        const auto axis = static_cast<Axis>(a);
        const std::string n(1, "XYZ"[a]);
        const std::int64_t steps = std::llround(table_steps(axis));
        char mm[32], speed[32];
        std::snprintf(mm, sizeof mm, "%.3f mm", table_mm(axis));
        std::snprintf(speed, sizeof speed, "%.1f rad/s", rotor_speed_rad_s(axis));
        const EndStop stop = end_stop(axis);
        Field& f = d.add(Field::note(n, std::to_string(steps) + " steps, " + mm));
        f.add(Field::decimal("steps", steps));
        f.add(Field::note("table", mm));
        f.add(Field::decimal("count", transducer_count(axis)));
        f.add(Field::decimal("commanded", commanded_steps(axis)));
        f.add(Field::decimal("lost", lost_steps(axis)));
        f.add(Field::decimal("end stop", stop.at, 0, stop.at > 0 ? "high" : stop.at < 0 ? "low" : "free"));
        f.add(Field::bits("phases", phase_pattern(axis), 0, 4, "A /A B /B")).lsb = -1;
        f.add(Field::note("rotor", std::string(speed) + (settled(axis) ? ", settled" : "")));
    }
}

double MachineTool::rotor_angle_deg(Axis axis) const {
    const int a = idx(axis);
    if (s_.model == MotorModel::Ideal) return static_cast<double>(s_.axes[a].ideal_steps) * 360.0 / (4.0 * p_.axes[a].motor.rotor_teeth);
    return motor_view(a).theta * 180.0 / std::numbers::pi;
}

double MachineTool::rotor_speed_rad_s(Axis axis) const {
    return s_.model == MotorModel::Ideal ? 0.0 : motor_view(idx(axis)).omega;
}

double MachineTool::table_mm(Axis axis) const {
    const int a = idx(axis);
    return position_mm(a, motor_view(a));
}

double MachineTool::table_steps(Axis axis) const {
    const int a = idx(axis);
    if (s_.model == MotorModel::Ideal) return static_cast<double>(s_.axes[a].ideal_steps);
    return motor_view(a).theta / ax_[a].motor.step_angle();
}

std::int64_t MachineTool::transducer_count(Axis axis) const {
    const int a = idx(axis);
    Transducer::State tr = s_.axes[a].transducer;
    if (s_.model == MotorModel::Physical && s_.feedback == Feedback::Scale)
        ax_[a].transducer.update(tr, position_mm(a, motor_view(a)));
    return tr.count;
}

std::int64_t MachineTool::lost_steps(Axis axis) const {
    const int a = idx(axis);
    const std::int64_t actual = s_.model == MotorModel::Ideal
                                    ? s_.axes[a].ideal_steps
                                    : static_cast<std::int64_t>(std::llround(table_steps(axis)));
    return s_.axes[a].sequencer.count - actual;
}

std::uint8_t MachineTool::phase_pattern(Axis axis) const { return Sequencer::phases(s_.axes[idx(axis)].sequencer); }

std::array<double, 4> MachineTool::winding_currents(Axis axis) const { return motor_view(idx(axis)).i; }

MachineTool::EndStop MachineTool::end_stop(Axis axis) const {
    const Table::State& t = s_.axes[idx(axis)].table;
    return {t.at_stop, t.hits, t.last_hit_t, t.last_hit_high};
}

bool MachineTool::settled(Axis axis) const {
    return s_.model == MotorModel::Ideal || s_.axes[idx(axis)].motor.settled;
}

bool MachineTool::all_settled() const {
    for (int a = 0; a < kAxes; ++a)
        if (!settled(static_cast<Axis>(a))) return false;
    return true;
}

void MachineTool::load_state(StateReader& r) {
    State s;
    State::fields(s, r);
    r.expect_end();
    for (int a = 0; a < kAxes; ++a) {
        const AxisState& st = s.axes[a];
        const StepperMotor::Load& load = ax_[a].motor.load();
        r.check(std::isfinite(st.motor.theta) && std::isfinite(st.motor.omega), "non-finite rotor state");
        r.check(st.motor.theta >= load.theta_lo && st.motor.theta <= load.theta_hi, "rotor beyond the end stops");
        for (double i : st.motor.i) r.check(std::isfinite(i) && i >= 0.0, "invalid winding current");
        r.check(st.motor.phases == Sequencer::phases(st.sequencer), "phases disagree with the sequencer");
        r.check(st.motor.settled || st.grid_t <= s.now, "motor state ahead of the clock");
        r.check(st.table.at_stop >= -1 && st.table.at_stop <= 1, "invalid end-stop state");
        const double x = s.feedback == Feedback::Commanded ? static_cast<double>(st.sequencer.count) * ax_[a].step_mm
                         : s.model == MotorModel::Ideal    ? static_cast<double>(st.ideal_steps) * ax_[a].step_mm
                                                           : st.motor.theta * ax_[a].mm_per_rad;
        r.check(ax_[a].transducer.q_of(x) == st.transducer.q, "transducer disagrees with the table");
    }
    s_ = s;
}

}  // namespace alp85::periph
