#include "emu/front/views.h"

namespace alp85::front {

DisplayView display_view(const script::Session& s) { return {s.display(), s.display_text()}; }

unsigned display_digits(const script::Session& s) { return s.board().display.digits; }

bool has_tool(const script::Session& s) { return !s.board().tool.empty(); }

std::vector<BoardChoice> board_choices() {
    std::vector<BoardChoice> out;
    for (const board::Board* b : board::kBoards) out.push_back({b->name, b->title});
    return out;
}

std::optional<RomPlace> monitor_rom(const script::Session& s) {
    if (const board::MemoryRegion* r = board::rom_at_reset(s.board())) return RomPlace{r->base, r->size};
    return std::nullopt;
}

CpuView cpu_view(const script::Session& s) {
    static const cpu::Register& pc = *cpu::description().find("PC");
    return {s.reg(pc), s.halted()};
}

ToolView tool_view(const script::Session& s) {
    ToolView v;
    const auto& tool = s.tool();
    v.model = tool.model();
    for (std::size_t a = 0; a < v.axes.size(); ++a) {
        const auto axis = static_cast<Axis>(a);
        v.axes[a] = {tool.table_mm(axis),         tool.table_steps(axis),   tool.rotor_angle_deg(axis),
                     tool.commanded_steps(axis),  tool.transducer_count(axis), tool.lost_steps(axis),
                     tool.end_stop(axis).at,      tool.phase_pattern(axis),  tool.params().axes[a].table.travel_mm};
    }
    return v;
}

}  // namespace alp85::front
