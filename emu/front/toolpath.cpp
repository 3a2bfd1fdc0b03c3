#include "emu/front/toolpath.h"

#include <algorithm>
#include <cmath>

namespace alp85::front {
namespace {
constexpr double kStepMm = 0.05;   // lead / steps per revolution (docs/machine.md)
constexpr double kMinMove = 0.005; // mm between recorded points
}  // namespace

void Bounds::add(double x, double y) {
    if (empty()) {
        *this = {x, y, x, y};
        return;
    }
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
}


void Toolpath::clear() {
    points_.clear();
    have_cmd_ = false;
    cleared_ = true;
    anchor_.reset();
    past_unknown_ = false;
}

void Toolpath::restored() {
    clear();
    cleared_ = false;
    past_unknown_ = true;
}

std::optional<std::array<std::int32_t, 4>> Toolpath::read_vars(const script::Session& s) const {
    if (!vars_at_) return std::nullopt;
    std::array<std::int32_t, 4> v{};
    for (int i = 0; i < 4; ++i) {
        const auto a = static_cast<std::uint16_t>(*vars_at_ + 3 * i);
        v[static_cast<std::size_t>(i)] = s.peek(a) | s.peek(static_cast<std::uint16_t>(a + 1)) << 8;
    }
    if (v[0] == 0 && v[1] == 0 && v[2] == 0 && v[3] == 0) return std::nullopt;
    return v;
}

void Toolpath::observe(const debug::ToolSample& sample, const script::Session& session) {
    const debug::ToolSample& s = sample;
    const PointMm p{s.axes[0].mm, s.axes[1].mm};
    if (points_.empty() || std::hypot(p.x - points_.back().x, p.y - points_.back().y) >= kMinMove) {
        if (points_.size() >= kMaxPoints) {  // keep every other point
            std::size_t j = 0;
            for (std::size_t i = 0; i < points_.size(); i += 2) points_[j++] = points_[i];
            points_.resize(j);
        }
        points_.push_back(p);
    }
    const std::array<std::int64_t, 2> cmd{s.axes[0].commanded, s.axes[1].commanded};
    if (!have_cmd_) {
        last_cmd_ = cmd, last_change_ = s.t, have_cmd_ = true;
        return;
    }
    if (cmd != last_cmd_) {
        if (cleared_ || s.t - last_change_ >= kIdle) {  // a move starts from where the table stood
            if (const auto v = read_vars(session)) {
                anchor_ = last_cmd_;
                anchor_vars_ = *v;
                past_unknown_ = false;
            }
        }
        last_cmd_ = cmd;
        last_change_ = s.t;
        cleared_ = false;
    }
}

std::optional<Toolpath::Line> Toolpath::ideal(const script::Session& s) const {
    std::array<std::int32_t, 4> v{};
    std::array<std::int64_t, 2> from{};
    Line line;
    if (anchor_) {
        v = anchor_vars_, from = *anchor_, line.started = true;
    } else if (past_unknown_) {
        return std::nullopt;
    } else {
        const auto now = read_vars(s);
        if (!now) return std::nullopt;
        v = *now;
        from = {s.tool().commanded_steps(periph::MachineTool::Axis::X), s.tool().commanded_steps(periph::MachineTool::Axis::Y)};
    }
    line.from = {static_cast<double>(from[0]) * kStepMm, static_cast<double>(from[1]) * kStepMm};
    line.to = {line.from.x + (v[2] - v[0]) * kStepMm, line.from.y + (v[3] - v[1]) * kStepMm};
    line.origin = {line.from.x - v[0] * kStepMm, line.from.y - v[1] * kStepMm};
    return line;
}

Bounds Toolpath::workpiece(const script::Session& s) const {
    PointMm o{};
    if (const auto l = ideal(s)) {
        o = l->origin;
    } else if (const auto v = past_unknown_ ? read_vars(s) : std::nullopt) {  // standing at (X2, Y2)
        o = {static_cast<double>(s.tool().commanded_steps(periph::MachineTool::Axis::X) - (*v)[2]) * kStepMm,
             static_cast<double>(s.tool().commanded_steps(periph::MachineTool::Axis::Y) - (*v)[3]) * kStepMm};
    }
    return {o.x, o.y, o.x + kWorkpieceW, o.y + kWorkpieceH};
}

}  // namespace alp85::front
