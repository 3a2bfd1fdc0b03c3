#include "emu/gui/board_view.h"

#include <string>
#include <vector>

#include <fmt/format.h>

#include "emu/front/views.h"

namespace alp85::gui {

ImU32 to_imu32(Rgb c, std::uint8_t alpha) { return IM_COL32(c.r, c.g, c.b, alpha); }

namespace {

ImVec2 v(Vec2 p) { return {p.x, p.y}; }

// A bar along the segment's centre line, kSegT thick, with pointed ends as LED segments have.
void draw_segment(ImDrawList* dl, const Segment& s, ImU32 col) {
    const float h = kSegT / 2;
    ImVec2 p[6];
    if (s.a.y == s.b.y) {  // horizontal
        p[0] = {s.a.x - h, s.a.y}, p[1] = {s.a.x, s.a.y - h}, p[2] = {s.b.x, s.b.y - h};
        p[3] = {s.b.x + h, s.b.y}, p[4] = {s.b.x, s.b.y + h}, p[5] = {s.a.x, s.a.y + h};
    } else {
        p[0] = {s.a.x, s.a.y - h}, p[1] = {s.a.x + h, s.a.y}, p[2] = {s.b.x + h, s.b.y};
        p[3] = {s.b.x, s.b.y + h}, p[4] = {s.b.x - h, s.b.y}, p[5] = {s.a.x - h, s.a.y};
    }
    dl->AddConvexPolyFilled(p, 6, col);
}

}  // namespace

// A trainer's card: green solder mask with white silkscreen, mounting holes in the corners, the
// gold fingers of its edge connector, and on it the display behind its red filter and the keypad.
void draw_display(ImDrawList* dl, Backdrop& bd, const std::array<std::uint8_t, 8>& segments, unsigned digits) {
    bd.fill(kBoardRect, colour::kBoard);
    bd.fill(display_rect(digits), colour::kDisplayWindow);
    const ImU32 lit = to_imu32(colour::kSegmentLit), unlit = to_imu32(colour::kSegmentUnlit);
    for (unsigned digit = 0; digit < digits && digit < segments.size(); ++digit) {
        const std::uint8_t bits = segments[digit];
        for (unsigned s = 0; s < 7; ++s) draw_segment(dl, segment(digit, s), (bits >> s & 1) ? lit : unlit);
        dl->AddCircleFilled(v(dp_centre(digit)), kDpRadius, (bits & 0x80) ? lit : unlit, 12);
    }
}

void draw_keypad(ImDrawList* dl, const Presser& presser, const script::Session& session) {
    // The card under the display and the keys (this layer covers the whole board).
    const Rect b = kBoardRect, d = display_rect(display_digits(session));
    const ImU32 silk = IM_COL32(226, 232, 222, 255), copper = IM_COL32(206, 168, 74, 255);
    const ImU32 legend = IM_COL32(170, 200, 176, 255);
    dl->AddRect({b.x + 3, b.y + 3}, {b.x + b.w - 3, b.y + b.h - 3}, IM_COL32(36, 96, 62, 255), 6, 0, 2);  // the card's edge
    for (const Vec2 h : {Vec2{b.x + 12, b.y + 12}, Vec2{b.x + b.w - 12, b.y + 12}, Vec2{b.x + 12, b.y + b.h - 30},
                         Vec2{b.x + b.w - 12, b.y + b.h - 30}}) {
        dl->AddCircleFilled(v(h), 5, copper, 16);  // plated mounting holes
        dl->AddCircleFilled(v(h), 2.5f, to_imu32(colour::kBackground), 12);
    }
    // Silkscreen: the board's title (its description's), between the holes.
    const std::string title(session.board().title);
    dl->AddText({b.x + 28, b.y + 6}, silk, title.c_str());
    dl->AddRect({d.x - 3, d.y - 3}, {d.x + d.w + 3, d.y + d.h + 3}, silk, 3, 0, 1);  // the display's outline
    const std::string parts = fmt::format("DS1-DS{}  8279", display_digits(session));
    dl->AddText({d.x + d.w - 100, d.y + d.h + 5}, legend, parts.c_str());
    // The edge connector's gold fingers along the bottom of the card.
    const float fy = b.y + b.h - 16;
    for (float x = b.x + 40; x + 6 < b.x + b.w - 40; x += 10) dl->AddRectFilled({x, fy}, {x + 6, b.y + b.h - 2}, copper, 1);

    std::vector<PadKey> pads;
    for (const KeypadKey& k : keypad_view(session)) {
        pads.push_back(k.key);
        const Rect r = key_rect(k.key);
        const Rgb face = presser.held(k.key) ? colour::kKeyPressed : k.fn ? colour::kKeyFunction : colour::kKey;
        dl->AddRectFilled({r.x, r.y}, {r.x + r.w, r.y + r.h}, to_imu32(face), 5);
        dl->AddRect({r.x, r.y}, {r.x + r.w, r.y + r.h}, IM_COL32(0, 0, 0, 255), 5);
        const std::string cap(k.cap);
        const ImU32 ink = k.fn ? IM_COL32(240, 240, 240, 255) : IM_COL32(20, 20, 20, 255);
        const ImVec2 size = ImGui::CalcTextSize(cap.c_str());
        dl->AddText({r.x + (r.w - size.x) / 2, r.y + 6}, ink, cap.c_str());
        const std::string hint = "[" + std::string(k.pc) + "]";
        const ImVec2 hs = ImGui::CalcTextSize(hint.c_str());
        dl->AddText({r.x + (r.w - hs.x) / 2, r.y + r.h - hs.y - 3}, k.fn ? IM_COL32(170, 190, 230, 255) : IM_COL32(90, 90, 90, 255),
                    hint.c_str());
    }
    const Rect pad = keypad_rect(pads);
    dl->AddRect({pad.x - 6, pad.y - 6}, {pad.x + pad.w + 6, pad.y + pad.h + 6}, legend, 4, 0, 1);  // the keypad's silkscreen outline
    dl->AddText({kKeyX0, pad.y + pad.h + 16}, IM_COL32(200, 220, 200, 255),
                "Click a key or type its PC key [ ]; a press lasts at least 30 ms.\n"
                "F1 or ? shows the key map.");
}

void draw_key_map(bool debug, const script::Session& s) {
    const Rect r = kKeyMapRect;
    ImGui::SetNextWindowPos({r.x, r.y});
    ImGui::SetNextWindowSize({r.w, r.h});
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::Begin("Key map (F1 or ? to close)", nullptr,
                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextUnformatted("The keypad from the PC's keyboard, and the mouse:");
    ImGui::Separator();
    if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        for (const KeyMapRow& row : key_map_rows(debug, s)) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted(row.keys.data(), row.keys.data() + row.keys.size());
            ImGui::TableSetColumnIndex(1);
            ImGui::TextUnformatted(row.action.data(), row.action.data() + row.action.size());
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace alp85::gui
