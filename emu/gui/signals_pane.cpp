#include "emu/gui/signals_pane.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <imgui.h>

#include "emu/gui/controls.h"
#include "emu/gui/layout.h"

namespace alp85::gui {

namespace {

ImU32 trace_colour(Rgb c) { return IM_COL32(c.r, c.g, c.b, 255); }

std::uint64_t span_tstates(int ms) { return board::tstates_from_ms(ms); }

std::string pin_label(const debug::PinTap::PinName& n) { return n.scope + "." + n.name; }

// The T-states shown: a span ending at the machine's present time.
struct Window {
    std::uint64_t end = 0, span = 1;
};
Window window_of(const SignalsPane& p, const script::Session& s) { return {s.now(), span_tstates(p.span_ms)}; }

// A logic pin's row: its level as a line (high, low, or between them when not driven), a
// vertical stroke at each edge. Where edges are closer than a pixel only one stroke is drawn.
void draw_logic_row(ImDrawList* dl, const debug::SignalTrace& tr, std::size_t k, const Rect& row, Window w, std::uint64_t from) {
    const auto& edges = tr.traces()[k].edges;
    const float hi = row.y + kSignalsHigh, lo = row.y + kSignalsLow, mid = (hi + lo) / 2;
    const auto level_line = [&](char level, float x0, float x1) {
        if (x1 - x0 < 0.5f) return;
        const float y = level == '1' ? hi : level == '0' ? lo : mid;
        dl->AddLine({x0, y}, {x1, y}, trace_colour(level == 'z' ? colour::kSignalFloat : colour::kSignal), 2.0f);
    };
    float x = signals_x(from, w.end, w.span);
    char level = tr.level_at(k, from);
    float stroke_x = -1;
    auto it = std::upper_bound(edges.begin(), edges.end(), from, [](std::uint64_t t, const debug::SignalTrace::Edge& e) { return t < e.t; });
    for (; it != edges.end() && it->t <= w.end; ++it) {
        const float xe = signals_x(it->t, w.end, w.span);
        level_line(level, x, xe);
        if (std::floor(xe) != stroke_x) {
            dl->AddLine({xe, hi}, {xe, lo}, trace_colour(colour::kSignal), 1.0f);
            stroke_x = std::floor(xe);
        }
        level = it->level;
        x = xe;
    }
    level_line(level, x, kSignalsTraceX + kSignalsTraceW);
}

// A real pin's row (a winding current, a rotor angle): its value every two pixels, scaled to the
// smallest and largest shown; the range is written beside the name.
std::string draw_real_row(ImDrawList* dl, const debug::SignalTrace& tr, std::size_t k, const Rect& row, Window w, std::uint64_t from) {
    const float x0 = std::max(signals_x(from, w.end, w.span), kSignalsTraceX);
    std::vector<ImVec2> points;
    double lo = 0, hi = 0;
    for (float x = x0; x <= kSignalsTraceX + kSignalsTraceW; x += 2) {
        const double t = std::max(signals_t(x, w.end, w.span), static_cast<double>(from));
        const double v = tr.value_at(k, static_cast<std::uint64_t>(t));
        if (points.empty()) lo = hi = v;
        lo = std::min(lo, v), hi = std::max(hi, v);
        points.push_back({x, static_cast<float>(v)});
    }
    const double range = hi > lo ? hi - lo : 1;
    for (ImVec2& q : points)
        q.y = static_cast<float>(row.y + kSignalsLow - (q.y - lo) / range * (kSignalsLow - kSignalsHigh));
    if (points.size() >= 2) dl->AddPolyline(points.data(), static_cast<int>(points.size()), trace_colour(colour::kSignal), 0, 1.5f);
    return fmt::format("{:.3g}..{:.3g}", lo, hi);
}

// Chooses or drops one pin; the trace is opened again on the pins then chosen, by their full names.
void toggle_pin(SignalsPane& p, script::Session& s, const debug::PinTap::PinName& pin, bool on) {
    std::vector<std::string> words;
    for (const auto& tr : s.signal_trace().traces())
        if (!(tr.pin.scope == pin.scope && tr.pin.name == pin.name)) words.push_back(pin_label(tr.pin));
    if (on) words.push_back(pin_label(pin));
    if (words.empty()) {  // the pane stays, with nothing traced
        close_signals(p, s);
        show_signals(p, s);
        return;
    }
    if (const auto o = open_signals(p, s, words, p.span_ms); o.status != script::Session::Status::Ok) p.error = o.message;
}

}  // namespace

script::Session::Outcome open_signals(SignalsPane& p, script::Session& s, const std::vector<std::string>& pins, int span_ms) {
    if (span_ms < 1 || span_ms > SignalsPane::kMaxSpanMs)
        return {script::Session::Status::Failed, fmt::format("the Signals pane shows 1 to {} ms, not {}", SignalsPane::kMaxSpanMs, span_ms)};
    if (pins.empty()) return {script::Session::Status::Failed, "no pin to show (PA0, X.PULSE, 8155, ...: docs/signals.md lists them)"};
    const auto o = s.trace_signals(pins, span_tstates(span_ms));
    if (o.status != script::Session::Status::Ok) return o;
    p.open = true;
    p.pins = pins;
    p.span_ms = span_ms;
    p.error.clear();
    p.names = s.pin_names();
    return o;
}

void show_signals(SignalsPane& p, const script::Session& s) {
    p.open = true;
    p.names = s.pin_names();
}

void close_signals(SignalsPane& p, script::Session& s) {
    s.trace_stop();
    p.open = false;
    p.pins.clear();
    p.cursors = {};
    p.next_cursor = 0;
}

bool place_cursor(SignalsPane& p, const script::Session& s, float x, float y) {
    const debug::SignalTrace& tr = s.signal_trace();
    const int rows = static_cast<int>(std::min<std::size_t>(tr.traces().size(), kSignalsRows));
    std::optional<int> row;
    for (int i = 0; i < rows; ++i)
        if (signals_row(i).contains(x, y)) row = i;
    if (!row) return false;
    const Window w = window_of(p, s);
    const double at = std::clamp(signals_t(x, w.end, w.span), 0.0, static_cast<double>(w.end));
    const auto t = static_cast<std::uint64_t>(std::llround(at));
    const auto within = static_cast<std::uint64_t>(SignalsPane::kSnapPixels * static_cast<double>(w.span) / kSignalsTraceW);
    const auto edge = tr.edge_near(static_cast<std::size_t>(*row), t, within);
    p.cursors[static_cast<std::size_t>(p.next_cursor)] = edge.value_or(t);
    p.next_cursor = 1 - p.next_cursor;
    return true;
}

std::string cursor_readout(const SignalsPane& p) {
    const auto& [a, b] = p.cursors;
    if (!a && !b) return "click a trace twice: cursors A and B (an edge near the click is taken)";
    if (!b) return fmt::format("A at T {}; click again for B", *a);
    if (!a) return fmt::format("B at T {}; click again for A", *b);
    return fmt::format("A at T {}, B at T {}: B - A = {}", *a, *b, debug::interval_text(*a, *b));
}

void draw_signals_pane(SignalsPane& p, script::Session& s) {
    if (!p.open) return;
    const Rect r = kSignalsRect;
    ImGui::SetNextWindowPos({r.x, r.y});
    ImGui::SetNextWindowSize({r.w, r.h});
    ImGui::SetNextWindowBgAlpha(1.0f);  // over the table view or the source pane: nothing shows through
    bool keep_open = true;
    ImGui::Begin("Signals", &keep_open,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    const debug::SignalTrace& tr = s.signal_trace();

    // ---- the choices: pins, span, cursors ----
    std::string chosen;
    for (const auto& t : tr.traces()) chosen += (chosen.empty() ? "" : " ") + t.pin.name;
    ImGui::SetNextItemWidth(300);
    const bool picking = ImGui::BeginCombo("##pins", chosen.empty() ? "choose pins" : chosen.c_str(), ImGuiComboFlags_HeightLarge);
    {
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        drawn_buttons()["signals.pins"] = {a.x, a.y, b.x, b.y};
    }
    if (picking) {
        for (const auto& n : p.names) {
            const bool on = std::any_of(tr.traces().begin(), tr.traces().end(),
                                        [&](const auto& t) { return t.pin.scope == n.scope && t.pin.name == n.name; });
            if (ImGui::Selectable(pin_label(n).c_str(), on, ImGuiSelectableFlags_DontClosePopups)) toggle_pin(p, s, n, !on);
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(200);
    if (ImGui::SliderInt("##span", &p.span_ms, 1, SignalsPane::kMaxSpanMs, "last %d ms", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
        s.set_trace_span(span_tstates(p.span_ms));
    ImGui::SameLine();
    if (named_button("signals.clear", "Clear cursors")) p.cursors = {}, p.next_cursor = 0;
    const std::string readout = !p.error.empty()        ? p.error
                                : tr.traces().empty() ? std::string("choose the pins to show (every pin record signals names)")
                                                      : cursor_readout(p);
    ImGui::TextUnformatted(readout.c_str());

    // ---- the traces ----
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const Window w = window_of(p, s);
    const std::uint64_t left = w.end > w.span ? w.end - w.span : 0;
    const std::uint64_t from = std::max(left, tr.started());  // nothing was traced before the pane opened
    const int rows = static_cast<int>(std::min<std::size_t>(tr.traces().size(), kSignalsRows));
    const float top = kSignalsTop - 4, bottom = kSignalsTop + static_cast<float>(std::max(rows, 1)) * kSignalsRowH;
    for (int i = 1; i < rows; i += 2) {  // every other row shaded: the rows' lines told apart
        const Rect row = signals_row(i);
        dl->AddRectFilled({r.x + 4, row.y}, {row.x + row.w, row.y + row.h}, IM_COL32(30, 32, 38, 255));
    }
    // A tick every tenth of the span, the span's start and the present time written above.
    for (int i = 0; i <= 10; ++i) {
        const float x = kSignalsTraceX + kSignalsTraceW * static_cast<float>(i) / 10;
        dl->AddLine({x, top}, {x, bottom}, IM_COL32(70, 74, 84, 255));
    }
    const ImU32 text = IM_COL32(200, 200, 200, 255);
    dl->AddText({kSignalsTraceX, kSignalsTop - 20}, text, fmt::format("-{} ms", p.span_ms).c_str());
    const std::string now = fmt::format("T {}", w.end);
    dl->AddText({kSignalsTraceX + kSignalsTraceW - ImGui::CalcTextSize(now.c_str()).x, kSignalsTop - 20}, text, now.c_str());
    if (from > left && from < w.end) {  // before the trace began: shaded
        const float x = signals_x(from, w.end, w.span);
        dl->AddRectFilled({kSignalsTraceX, top}, {x, bottom}, IM_COL32(50, 52, 60, 255));
    }
    for (int i = 0; i < rows; ++i) {
        const Rect row = signals_row(i);
        const auto k = static_cast<std::size_t>(i);
        std::string label = pin_label(tr.traces()[k].pin);
        if (from < w.end) {
            if (tr.traces()[k].pin.real)
                label += "\n" + draw_real_row(dl, tr, k, row, w, from);
            else
                draw_logic_row(dl, tr, k, row, w, from);
        }
        dl->AddText({r.x + 8, row.y + 4}, text, label.c_str());
    }
    if (tr.traces().size() > kSignalsRows)
        dl->AddText({r.x + 8, bottom + 2}, text, fmt::format("{} more pins chosen than shown", tr.traces().size() - kSignalsRows).c_str());
    // The cursors: a line each through every row, its letter above.
    for (std::size_t c = 0; c < 2; ++c) {
        if (!p.cursors[c] || *p.cursors[c] < left || *p.cursors[c] > w.end) continue;
        const float x = signals_x(*p.cursors[c], w.end, w.span);
        const ImU32 col = trace_colour(c == 0 ? colour::kCursorA : colour::kCursorB);
        dl->AddLine({x, top}, {x, bottom}, col, 2.0f);
        dl->AddText({x + 3, bottom}, col, c == 0 ? "A" : "B");
    }
    // Clicks on the traces place the cursors.
    ImGui::SetCursorScreenPos({kSignalsTraceX, kSignalsTop});
    ImGui::InvisibleButton("##traces", {kSignalsTraceW, std::max(1.0f, static_cast<float>(rows) * kSignalsRowH)});
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        place_cursor(p, s, m.x, m.y);
    }
    ImGui::End();
    if (!keep_open) close_signals(p, s);
}

}  // namespace alp85::gui
