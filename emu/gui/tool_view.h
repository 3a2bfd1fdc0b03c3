// The machine tool drawn into the window: the X-Y table from above (grid in mm, the workpiece
// outline, the ideal line, the toolpath so far and the tool), the Z axis as a gauge, the whole
// X-Y travel as a strip, and the axis panel (position in mm and steps, transducer count, lost
// steps, end stops, the motors' phase states, the motor model).
//
// The table view is in the table's coordinates (mm from the power-on position, as `print axes` and
// the toolpath plots give them): the tool is drawn where the table has brought the workpiece under
// it. The view fits the workpiece, the ideal line, the toolpath and the tool.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <imgui.h>

#include "emu/gui/backdrop.h"
#include "emu/front/toolpath.h"
#include "emu/front/views.h"
#include "emu/gui/layout.h"

namespace alp85::gui {

// What the table view fits: the workpiece, the ideal line, the toolpath and the tool.
Bounds table_bounds(const ToolView& tool, const Toolpath& path, const script::Session& s);
TableView table_view(const ToolView& tool, const Toolpath& path, const script::Session& s);
// The table: bed, mm grid, workpiece (changes only when the view does).
void draw_table(ImDrawList* dl, Backdrop& bd, const Toolpath& path, const script::Session& s, const TableView& view);
// Over it, in a window of its own (what moves): the toolpath, the ideal line, the tool.
void draw_toolpath(ImDrawList* dl, const ToolView& tool, const Toolpath& path, const script::Session& s, const TableView& view);
void draw_z_gauge(ImDrawList* dl, Backdrop& bd, const ToolView& tool);
void draw_travel_strip(ImDrawList* dl, Backdrop& bd, const ToolView& tool);
// An ImGui window at kAxesRect: the axes of a view of the tool (front::tool_view; the app takes one
// 15 times a second: a readout changing at 60 Hz cannot be read, and would repaint its panel every
// frame). Returns the motor model the user picked, if changed.
std::optional<MotorModel> axes_panel(const ToolView& axes, MotorModel model);

inline constexpr float kToolRadius = 7;
// The title's band at the top of the table view (the title is drawn at 4 px, 13 px of text):
// the grid's labels stay out of it.
inline constexpr float kTableTitleBand = 20;
inline constexpr float kGridLabelRise = 14;  // a Y label sits this far above its grid line
// Where the label of the horizontal grid line at window row `line_y` is drawn, or nullopt when it
// would overlap the title (the "30" that was drawn over it).
std::optional<float> grid_label_y(float line_y);
// The table view's title: it must fit kTableRect's width (the Z gauge follows).
inline constexpr const char* kTableTitle = "X-Y table from above, mm: ideal line (green), toolpath (blue), tool";
// The axis panel's column headers; "axis" and the phase lamps' get the width of their text.
inline constexpr std::array<const char*, 9> kAxisHeaders{"axis", "mm", "steps", "commanded", "transducer", "lost", "end stop",
                                                          "phases A /A B /B", "rotor deg"};

}  // namespace alp85::gui
