#include "emu/debug/tool_record.h"

#include <fmt/format.h>

namespace alp85::debug {

ToolSample sample_tool(const periph::MachineTool& tool, std::uint64_t t) {
    ToolSample s;
    s.t = t;
    for (int a = 0; a < 3; ++a) {
        const auto axis = static_cast<periph::MachineTool::Axis>(a);
        s.axes[static_cast<std::size_t>(a)] = {tool.commanded_steps(axis), tool.table_mm(axis),
                                               tool.transducer_count(axis), tool.lost_steps(axis),
                                               tool.phase_pattern(axis)};
    }
    return s;
}

void ToolRecorder::start(Machine& machine, std::uint64_t period) {
    stop();
    machine_ = &machine;
    samples_.clear();
    full_ = false;
    machine.tool().advance(machine.now());
    samples_.push_back(sample_tool(machine.tool(), machine.now()));
    machine.set_sampler(period, [this](std::uint64_t t) {
        if (samples_.size() < kMaxSamples) samples_.push_back(sample_tool(machine_->tool(), t));
        else full_ = true;
    });
}

void ToolRecorder::stop() {
    if (!machine_) return;
    machine_->set_sampler(0, {});
    machine_ = nullptr;
}

void ToolRecorder::write_csv(std::ostream& out) const {
    std::string row = "t_ms";
    for (const char* a : {"x", "y", "z"})
        row += fmt::format(",{0}_commanded,{0}_mm,{0}_count,{0}_lost,{0}_phases", a);
    out << row << '\n';
    for (const ToolSample& s : samples_) {
        row = fmt::format("{:.4f}", static_cast<double>(s.t) * 1000.0 / board::kCpuHz);
        for (const AxisSample& a : s.axes)
            row += fmt::format(",{},{:.5f},{},{},{:X}", a.commanded, a.mm, a.count, a.lost, a.phases);
        out << row << '\n';
    }
}

}  // namespace alp85::debug
