#include "emu/gui/layout.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>

namespace alp85::gui {

Rect intersect(const Rect& a, const Rect& b) {
    const float x0 = std::max(a.x, b.x), y0 = std::max(a.y, b.y);
    const float x1 = std::min(a.x + a.w, b.x + b.w), y1 = std::min(a.y + a.h, b.y + b.h);
    return {x0, y0, std::max(0.0f, x1 - x0), std::max(0.0f, y1 - y0)};
}

Rect unite(const Rect& a, const Rect& b) {
    if (a.w <= 0 || a.h <= 0) return b;
    if (b.w <= 0 || b.h <= 0) return a;
    const float x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const float x1 = std::max(a.x + a.w, b.x + b.w), y1 = std::max(a.y + a.h, b.y + b.h);
    return {x0, y0, x1 - x0, y1 - y0};
}

Segment segment(unsigned digit, unsigned s) {
    const float x = kDigitX0 + kDigitPitch * static_cast<float>(digit), y = kDigitY0;
    const float h = kSegT / 2, gap = 1.5f;
    const float left = x + h, right = x + kDigitW - h;
    const float top = y + h, mid = y + kDigitH / 2, bottom = y + kDigitH - h;
    switch (s) {
        case 0: return {{left + h + gap, top}, {right - h - gap, top}};          // a
        case 1: return {{right, top + h + gap}, {right, mid - h - gap}};         // b
        case 2: return {{right, mid + h + gap}, {right, bottom - h - gap}};      // c
        case 3: return {{left + h + gap, bottom}, {right - h - gap, bottom}};    // d
        case 4: return {{left, mid + h + gap}, {left, bottom - h - gap}};        // e
        case 5: return {{left, top + h + gap}, {left, mid - h - gap}};           // f
        default: return {{left + h + gap, mid}, {right - h - gap, mid}};         // g
    }
}

Vec2 segment_centre(unsigned digit, unsigned s) {
    const Segment g = segment(digit, s);
    return {(g.a.x + g.b.x) / 2, (g.a.y + g.b.y) / 2};
}

Vec2 dp_centre(unsigned digit) {
    return {kDigitX0 + kDigitPitch * static_cast<float>(digit) + kDigitW + 7, kDigitY0 + kDigitH - kDpRadius};
}

Rect key_rect(const PadKey& k) {
    return {kKeyX0 + kKeyPitchX * static_cast<float>(k.col), kKeyY0 + kKeyPitchY * static_cast<float>(k.row), kKeyW,
            kKeyH};
}

namespace {
std::optional<PadKey> key_among(float x, float y, std::span<const PadKey> keys) {
    for (const PadKey& k : keys)
        if (key_rect(k).contains(x, y)) return k;
    return std::nullopt;
}
}  // namespace

std::optional<PadKey> key_at(float x, float y) { return key_among(x, y, pad_keys()); }
std::optional<PadKey> key_at(float x, float y, const script::Session& s) { return key_among(x, y, pad_keys(s)); }

Rect keypad_rect(std::span<const PadKey> keys) {
    Rect all{};
    for (const PadKey& k : keys) all = unite(all, key_rect(k));
    return all;
}

Rect display_rect(unsigned digits) {
    const unsigned n = std::min(digits, 8u);
    return {kDisplayRect.x, kDisplayRect.y, kDisplayRect.w - kDigitPitch * static_cast<float>(8 - n), kDisplayRect.h};
}

TableView TableView::fit(const Bounds& b, const Rect& r) {
    TableView v;
    const double w = std::max(b.x1 - b.x0, 1.0), h = std::max(b.y1 - b.y0, 1.0);
    v.scale = std::min((r.w - 2 * kTableMargin) / w, (r.h - 2 * kTableMargin) / h);
    v.cx = (b.x0 + b.x1) / 2;
    v.cy = (b.y0 + b.y1) / 2;
    return v;
}

Vec2 TableView::to_px(double x_mm, double y_mm, const Rect& r) const {
    return {static_cast<float>(r.x + r.w / 2 + (x_mm - cx) * scale), static_cast<float>(r.y + r.h / 2 - (y_mm - cy) * scale)};
}

std::pair<double, double> TableView::to_mm(float x, float y, const Rect& r) const {
    return {cx + (x - (r.x + r.w / 2)) / scale, cy - (y - (r.y + r.h / 2)) / scale};
}

TableView TableCamera::apply(const TableView& fitted) const {
    TableView v = framed && !framed->empty() ? TableView::fit(*framed) : fitted;
    v.scale *= zoom;
    v.cx += dx, v.cy += dy;
    return v;
}

void TableCamera::zoom_at(const TableView& fitted, float x, float y, double factor) {
    const TableView before = apply(fitted);
    const auto [mx, my] = before.to_mm(x, y);
    zoom = std::clamp(zoom * factor, 0.05, 500.0);
    const TableView after = apply(fitted);
    const auto [ax, ay] = after.to_mm(x, y);
    dx += mx - ax, dy += my - ay;
}

void TableCamera::pan(const TableView& fitted, float dx_px, float dy_px) {
    const double s = apply(fitted).scale;
    dx -= dx_px / s, dy += dy_px / s;
}

Fit fit_to(int w, int h) {
    Fit f;
    if (w <= 0 || h <= 0) return f;
    f.scale = std::min(static_cast<float>(w) / kWindowWidth, static_cast<float>(h) / kWindowHeight);
    f.ox = std::floor((static_cast<float>(w) - kWindowWidth * f.scale) / 2);
    f.oy = std::floor((static_cast<float>(h) - kWindowHeight * f.scale) / 2);
    return f;
}

Vec2 to_logical(const Fit& f, float x, float y) { return {(x - f.ox) / f.scale, (y - f.oy) / f.scale}; }
Vec2 to_window(const Fit& f, float x, float y) { return {x * f.scale + f.ox, y * f.scale + f.oy}; }

Size initial_window_size(double scale, int usable_w, int usable_h) {
    if (usable_w > 0 && usable_h > 0) {
        // Room for a title bar and a panel (about 60 pixels), and a margin at the sides.
        const double fit = std::max(0.25, std::min((usable_w - 40) / double(kWindowWidth), (usable_h - 60) / double(kWindowHeight)));
        scale = scale <= 0 ? std::min(1.0, fit) : std::min(scale, fit);
    } else if (scale <= 0) {
        scale = 1;  // the screen's size unknown
    }
    return {static_cast<int>(std::lround(kWindowWidth * scale)), static_cast<int>(std::lround(kWindowHeight * scale))};
}

Rect source_row(int i) {
    return {kSourceRect.x + 4, kSourceRect.y + kSourceTop + static_cast<float>(i) * kSourceRowH, kSourceRect.w - 8, kSourceRowH};
}

std::optional<int> source_row_at(float x, float y) {
    for (int i = 0; i < kSourceRows; ++i)
        if (source_row(i).contains(x, y)) return i;
    return std::nullopt;
}

Rect signals_row(int i) { return {kSignalsTraceX, kSignalsTop + static_cast<float>(i) * kSignalsRowH, kSignalsTraceW, kSignalsRowH}; }

float signals_x(std::uint64_t t, std::uint64_t end, std::uint64_t span) {
    const double from_end = static_cast<double>(end) - static_cast<double>(t);  // T-states before the right end
    return static_cast<float>(kSignalsTraceX + kSignalsTraceW - from_end * kSignalsTraceW / static_cast<double>(span));
}

double signals_t(float x, std::uint64_t end, std::uint64_t span) {
    return static_cast<double>(end) - static_cast<double>(kSignalsTraceX + kSignalsTraceW - x) * static_cast<double>(span) / kSignalsTraceW;
}

}  // namespace alp85::gui
