// The interpolator, its reader and two servo axes run together; samples at each output pair.
#include "emu/pisa/run.h"

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
    r.stop = m.run(p.max_steps);
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
