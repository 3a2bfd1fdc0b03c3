// The interpolator, its reader and two servo axes run together; samples at each output pair.
#include "emu/pisa/run.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "peripherals/machine_tool.h"

namespace alp85::pisa {

RunParams::RunParams() {
    auto tool = periph::MachineTool::default_params();
    TapeLimits lim;
    x.table = tool.axes[0].table;
    y.table = tool.axes[1].table;
    x.start_mm = lim.start_x_mm;
    y.start_mm = lim.start_y_mm;
}

std::uint64_t tape_steps(const Tape& tape, const RunParams& p) {
    double motion_s = 0;
    for (const Element& e : tape.elements) {
        const double x0 = static_cast<double>(e.x0), y0 = static_cast<double>(e.y0);
        const double x1 = static_cast<double>(e.x1), y1 = static_cast<double>(e.y1);
        double um = std::hypot(x1 - x0, y1 - y0);
        if (e.arc()) {
            const double cx = static_cast<double>(e.cx), cy = static_cast<double>(e.cy);
            const double a0 = std::atan2(y0 - cy, x0 - cx), a1 = std::atan2(y1 - cy, x1 - cx);
            double sweep = e.kind == Element::Kind::Ccw ? a1 - a0 : a0 - a1;
            while (sweep <= 0) sweep += 2 * std::numbers::pi;
            if (e.x0 == e.x1 && e.y0 == e.y1) sweep = 2 * std::numbers::pi;
            um = sweep * std::hypot(x0 - cx, y0 - cy);
        }
        if (e.feed > 0) motion_s += um / 1000 / e.feed * 60;
    }
    std::uint64_t chars = 0;
    for (const TapeWord& w : tape.words) chars += static_cast<std::uint64_t>(w.chars);
    return static_cast<std::uint64_t>(std::llround(motion_s / kDigitStepSeconds)) + chars * p.reader.char_steps;
}

std::uint64_t guard_steps(const Tape& tape, const RunParams& p) {
    return 2 * tape_steps(tape, p) + static_cast<std::uint64_t>(std::llround(60 / kDigitStepSeconds));
}

RunResult run_tape(const std::vector<std::uint32_t>& rom, const Tape& tape, const RunParams& p) {
    Interpolator m(rom);
    m.reader() = TapeReader(p.reader);
    m.reader().load(tape.words);
    m.count_idle(p.idle_first, p.idle_last);
    ServoAxis ax(p.x), ay(p.y);
    RunResult r;
    m.on_output([&](int ch, const Word& w, std::uint64_t t) {
        auto v = to_int(w).value_or(0);
        if (ch == 1) ax.command(v, t);
        if (ch != 2) return;
        ay.command(v, t);
        ax.advance(t);
        r.samples.push_back({t, ax.command_um(), ay.command_um(), ax.position_mm(), ay.position_mm(), m.idle_steps()});
    });
    r.max_steps = p.max_steps ? p.max_steps : guard_steps(tape, p);
    r.stop = m.run(r.max_steps);
    r.output_samples = r.samples.size();
    r.instructions = m.instructions();
    r.steps = m.now();
    r.idle_steps = m.idle_steps();
    for (int s = 0; s < kIndicators; ++s) r.indicators[static_cast<std::size_t>(s)] = m.indicator(s);
    r.last_word_read = m.reader().last_fill();
    auto settle = static_cast<std::uint64_t>(p.settle_s / 100e-9);
    for (std::uint64_t t = m.now() + kClockSteps; t <= m.now() + settle; t += kClockSteps) {
        ax.advance(t);
        ay.advance(t);
        r.samples.push_back({t, ax.command_um(), ay.command_um(), ax.position_mm(), ay.position_mm()});
    }
    return r;
}

std::string samples_csv(const RunResult& r) {
    std::string out = "t_ms,x_cmd_mm,y_cmd_mm,x_mm,y_mm\n";
    for (const auto& s : r.samples)
        out += fmt::format("{:.4f},{:.3f},{:.3f},{:.4f},{:.4f}\n", static_cast<double>(s.t) * 1e-4,
                           static_cast<double>(s.cmd_x_um) / 1000, static_cast<double>(s.cmd_y_um) / 1000, s.x_mm, s.y_mm);
    return out;
}

}  // namespace alp85::pisa
