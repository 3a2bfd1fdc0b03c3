#include "emu/gui/tool_view.h"

#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "emu/gui/board_view.h"
#include "emu/plot/plot.h"

namespace alp85::gui {
namespace {

ImVec2 im(Vec2 p) { return {p.x, p.y}; }  // not board_view.cpp's v(): one unit in unity builds

}  // namespace

Bounds table_bounds(const ToolView& tool, const Toolpath& path, const script::Session& s) {
    Bounds b = path.workpiece(s);
    if (const auto l = path.ideal(s)) b.add(l->from.x, l->from.y), b.add(l->to.x, l->to.y);
    for (const PointMm& p : path.points()) b.add(p.x, p.y);
    b.add(tool[Axis::X].mm, tool[Axis::Y].mm);
    return b;
}

std::optional<float> grid_label_y(float line_y) {
    const float y = line_y - kGridLabelRise;
    if (y < kTableRect.y + kTableTitleBand) return std::nullopt;
    return y;
}

TableView table_view(const ToolView& tool, const Toolpath& path, const script::Session& s) {
    return TableView::fit(table_bounds(tool, path, s));
}

void draw_table(ImDrawList* dl, Backdrop& bd, const Toolpath& path, const script::Session& s, const TableView& view) {
    const Rect r = kTableRect;
    bd.fill(r, colour::kTableBed);
    dl->PushClipRect({r.x, r.y}, {r.x + r.w, r.y + r.h}, true);
    // The mm grid, at 1-2-5 steps across the visible span.
    const double half_w = (r.w / 2) / view.scale, half_h = (r.h / 2) / view.scale;
    const ImU32 grid = IM_COL32(80, 86, 94, 255), label = IM_COL32(150, 156, 164, 255);
    for (double x : plot::ticks(view.cx - half_w, view.cx + half_w, 8)) {
        const Vec2 p = view.to_px(x, 0);
        dl->AddLine({p.x, r.y}, {p.x, r.y + r.h}, grid);
        dl->AddText({p.x + 2, r.y + r.h - 16}, label, fmt::format("{:g}", x).c_str());
    }
    for (double y : plot::ticks(view.cy - half_h, view.cy + half_h, 6)) {
        const Vec2 p = view.to_px(0, y);
        dl->AddLine({r.x, p.y}, {r.x + r.w, p.y}, grid);
        if (const auto ly = grid_label_y(p.y)) dl->AddText({r.x + 2, *ly}, label, fmt::format("{:g}", y).c_str());
    }
    const Bounds w = path.workpiece(s);
    const Vec2 w0 = view.to_px(w.x0, w.y1), w1 = view.to_px(w.x1, w.y0);
    bd.fill_clipped({w0.x, w0.y, w1.x - w0.x, w1.y - w0.y}, r, colour::kWorkpieceFill);
    dl->AddRect(im(w0), im(w1), to_imu32(colour::kWorkpiece), 0, 0, 2);
    dl->AddText({w0.x + 4, w0.y + 2}, IM_COL32(230, 210, 170, 255), "workpiece");
    dl->PopClipRect();
    // The title fits the view (the Z gauge starts where the table ends); F1 tells the mouse's zoom and pan.
    dl->AddText({r.x + 6, r.y + 4}, IM_COL32(230, 230, 230, 255), kTableTitle);
}

void draw_toolpath(ImDrawList* dl, const ToolView& tool, const Toolpath& path, const script::Session& s, const TableView& view) {
    const Rect r = kTableRect;
    dl->PushClipRect({r.x, r.y}, {r.x + r.w, r.y + r.h}, true);
    const auto& pts = path.points();
    if (pts.size() >= 2) {
        // Thinned to about one point per pixel of the view.
        const double step_mm = 1 / view.scale;
        Vec2 last = view.to_px(pts[0].x, pts[0].y);
        PointMm last_mm = pts[0];
        for (std::size_t i = 1; i < pts.size(); ++i) {
            if (i + 1 < pts.size() && std::hypot(pts[i].x - last_mm.x, pts[i].y - last_mm.y) < step_mm) continue;
            const Vec2 p = view.to_px(pts[i].x, pts[i].y);
            dl->AddLine(im(last), im(p), to_imu32(colour::kToolpath), 2);
            last = p, last_mm = pts[i];
        }
    }
    if (const auto l = path.ideal(s)) {
        const ImU32 c = to_imu32(colour::kIdealLine, l->started ? 255 : 140);
        dl->AddLine(im(view.to_px(l->from.x, l->from.y)), im(view.to_px(l->to.x, l->to.y)), c, 1.0f);
        dl->AddCircle(im(view.to_px(l->to.x, l->to.y)), 4, c);
    }
    const Vec2 at = view.to_px(tool[Axis::X].mm, tool[Axis::Y].mm);
    dl->AddCircle(im(at), kToolRadius + 1.5f, IM_COL32(0, 0, 0, 255), 20, 2);
    dl->AddCircleFilled(im(at), kToolRadius, to_imu32(colour::kTool), 20);
    dl->PopClipRect();
}

void draw_z_gauge(ImDrawList* dl, Backdrop& bd, const ToolView& tool) {
    const Rect r = kZGaugeRect;
    const double travel = tool[Axis::Z].travel_mm;
    const double z = tool[Axis::Z].mm;
    dl->AddText({r.x + 4, r.y - 20}, IM_COL32(230, 230, 230, 255), "Z (mm)");
    bd.fill({r.x + 18, r.y, 24, r.h}, colour::kTableBed);
    const float frac = static_cast<float>(std::clamp(z / travel, 0.0, 1.0));
    const float y = r.y + r.h - frac * r.h;
    bd.fill({r.x + 18, y, 24, r.y + r.h - y}, colour::kZColumn);
    dl->AddLine({r.x + 10, y}, {r.x + 50, y}, to_imu32(colour::kTool), 3);
    for (double t : plot::ticks(0, travel, 5)) {
        const float ty = r.y + r.h - static_cast<float>(t / travel) * r.h;
        dl->AddLine({r.x + 42, ty}, {r.x + 48, ty}, IM_COL32(200, 200, 200, 255));
    }
    dl->AddText({r.x, r.y + r.h + 4}, IM_COL32(230, 230, 230, 255), fmt::format("{:.2f}", z).c_str());
}

void draw_travel_strip(ImDrawList* dl, Backdrop& bd, const ToolView& tool) {
    const Rect r = kStripRect;
    const double tx = tool[Axis::X].travel_mm, ty = tool[Axis::Y].travel_mm;
    const float h = r.h - 18, w = std::min(r.w, static_cast<float>(h * tx / ty));
    dl->AddText({r.x, r.y}, IM_COL32(230, 230, 230, 255),
                fmt::format("whole travel: X {:g} mm, Y {:g} mm", tx, ty).c_str());
    const float x0 = r.x, y0 = r.y + 16;
    bd.fill({x0, y0, w, h}, colour::kTableBed);
    // Whole pixels: a dot moving by less than one does not repaint the strip.
    const float px = std::round(x0 + static_cast<float>(std::clamp(tool[Axis::X].mm / tx, 0.0, 1.0)) * w);
    const float py = std::round(y0 + h - static_cast<float>(std::clamp(tool[Axis::Y].mm / ty, 0.0, 1.0)) * h);
    dl->AddCircleFilled({px, py}, 4, to_imu32(colour::kTool), 12);
}

std::optional<MotorModel> axes_panel(const ToolView& axes, MotorModel motor) {
    const Rect r = kAxesRect;
    ImGui::SetNextWindowPos({r.x, r.y});
    ImGui::SetNextWindowSize({r.w, r.h});
    ImGui::Begin("Machine tool", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBackground);
    if (ImGui::BeginTable("axes", 9, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
        // Headers whole: the narrow ones and the phase lamps at their own widths, the numbers share the rest.
        for (const char* h : kAxisHeaders) {
            const std::string_view name(h);
            const bool fixed = name == "axis" || name.starts_with("phases");
            ImGui::TableSetupColumn(h, fixed ? ImGuiTableColumnFlags_WidthFixed : ImGuiTableColumnFlags_WidthStretch,
                                    fixed ? ImGui::CalcTextSize(h).x + 8 : 0.0f);
        }
        ImGui::TableHeadersRow();
        for (int a = 0; a < 3; ++a) {
            const AxisView& x = axes.axes[static_cast<std::size_t>(a)];
            ImGui::TableNextRow();
            ImGui::TableNextColumn(); ImGui::TextUnformatted(a == 0 ? "X" : a == 1 ? "Y" : "Z");
            ImGui::TableNextColumn(); ImGui::Text("%.3f", x.mm);
            ImGui::TableNextColumn(); ImGui::Text("%.2f", x.steps);
            ImGui::TableNextColumn(); ImGui::Text("%lld", static_cast<long long>(x.commanded));
            ImGui::TableNextColumn(); ImGui::Text("%lld", static_cast<long long>(x.count));
            ImGui::TableNextColumn(); ImGui::Text("%lld", static_cast<long long>(x.lost));
            ImGui::TableNextColumn(); ImGui::TextUnformatted(x.end_stop < 0 ? "LOW" : x.end_stop > 0 ? "HIGH" : "-");
            ImGui::TableNextColumn();
            const std::uint8_t ph = x.phases;
            ImDrawList* dl = ImGui::GetWindowDrawList();
            const ImVec2 p = ImGui::GetCursorScreenPos();
            for (int i = 0; i < 4; ++i) {
                const bool on = ph >> (3 - i) & 1;
                const ImVec2 q{p.x + 4 + 22.0f * static_cast<float>(i), p.y + 2};
                dl->AddRectFilled(q, {q.x + 16, q.y + 12}, on ? IM_COL32(255, 200, 40, 255) : IM_COL32(60, 60, 60, 255), 2);
            }
            ImGui::Dummy({92, 14});
            ImGui::TableNextColumn(); ImGui::Text("%.1f", x.rotor_deg);
        }
        ImGui::EndTable();
    }
    std::optional<MotorModel> pick;
    int model = motor == MotorModel::Ideal ? 0 : 1;
    ImGui::TextUnformatted("Motors:");
    ImGui::SameLine();
    if (ImGui::RadioButton("ideal (1.8 deg per pulse)", &model, 0)) pick = MotorModel::Ideal;
    ImGui::SameLine();
    if (ImGui::RadioButton("physical (currents, inertia)", &model, 1)) pick = MotorModel::Physical;
    ImGui::End();
    return pick;
}

}  // namespace alp85::gui
