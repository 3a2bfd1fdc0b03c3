// Snapshot views of the board for the front ends: the display and the machine tool as plain
// values, read from the Session at one instant. The window, the page and DAP draw or list these and
// never hold the machine's parts.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/script/session.h"

namespace alp85::front {

// The digits: their segment bytes (leftmost first, the bit order of the seven-segment decoder:
// a = bit 0 ... g = bit 6, dp = bit 7; up to eight, those past the board's count dark) and the
// nearest character of each ('.' for dp).
struct DisplayView {
    std::array<std::uint8_t, 8> segments{};
    std::string text;
};
DisplayView display_view(const script::Session& s);
// How many digits the session's board has (its description's display: 8 on the ALP 85, 6 on
// the SDK-85), the ones a front end draws.
unsigned display_digits(const script::Session& s);
// Whether the session's board carries the machine tool (its description's tool wiring): the
// front ends show its views only then.
bool has_tool(const script::Session& s);
// The boards there are (--board, the page's selector): name and title, the default first.
struct BoardChoice {
    std::string_view name, title;
};
std::vector<BoardChoice> board_choices();
// Where the session's board keeps its monitor ROM (its description's MonitorEprom region): the
// place a user's ROM file goes (--rom, the page's Load ROM). nullopt: the board has none.
struct RomPlace {
    std::uint16_t base = 0, size = 0;
};
std::optional<RomPlace> monitor_rom(const script::Session& s);

// The CPU's program counter and whether it waits after a HLT.
struct CpuView {
    std::uint16_t pc = 0;
    bool halted = false;
};
CpuView cpu_view(const script::Session& s);

using Axis = periph::MachineTool::Axis;
using MotorModel = periph::MachineTool::MotorModel;

// One axis of the machine tool: the table (mm from the power-on position, and in 0.05 mm steps),
// the rotor, the sequencer's commanded steps, the transducer's count, the steps lost, the end stop
// it stands on (-1 low, +1 high, 0 none), the phase lamps (8 A, 4 /A, 2 B, 1 /B) and its travel.
struct AxisView {
    double mm = 0, steps = 0, rotor_deg = 0;
    std::int64_t commanded = 0, count = 0, lost = 0;
    std::int8_t end_stop = 0;
    std::uint8_t phases = 0;
    double travel_mm = 0;
};
struct ToolView {
    std::array<AxisView, 3> axes{};  // X, Y, Z
    MotorModel model = MotorModel::Physical;
    const AxisView& operator[](Axis a) const { return axes[static_cast<std::size_t>(a)]; }
};
ToolView tool_view(const script::Session& s);

}  // namespace alp85::front
