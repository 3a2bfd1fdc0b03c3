// The toolpath chart of a run.
#include "emu/pisa/run_plot.h"

namespace alp85::pisa {

plot::Chart toolpath_chart(const std::string& title, const Tape& tape, const RunResult& r) {
    plot::Chart c;
    c.title = title;
    c.equal_scale = true;
    plot::Series exact{"exact path", {}, false, true};
    for (const auto& p : ideal_path_mm(tape)) exact.points.push_back({p.x, p.y});
    plot::Series outputs{"6 ms outputs", {}, false, false};
    plot::Series tables{"tables (servo, Kv 25/s)", {}, false, false};
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
        const auto& s = r.samples[i];
        if (i < r.output_samples)
            outputs.points.push_back({static_cast<double>(s.cmd_x_um) / 1000, static_cast<double>(s.cmd_y_um) / 1000});
        tables.points.push_back({s.x_mm, s.y_mm});
    }
    c.series = {exact, outputs, tables};
    return c;
}

}  // namespace alp85::pisa
