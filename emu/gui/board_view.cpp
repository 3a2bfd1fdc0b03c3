#include "emu/gui/board_view.h"

#include <string>

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

void draw_display(ImDrawList* dl, Backdrop& bd, const std::array<std::uint8_t, 8>& segments) {
    const Rect b = kBoardRect, d = kDisplayRect;
    bd.fill(b, colour::kBoard);
    dl->AddText({b.x + 10, b.y + 4}, IM_COL32(220, 230, 220, 255), "ALP 85");
    bd.fill(d, colour::kDisplayWindow);
    const ImU32 lit = to_imu32(colour::kSegmentLit), unlit = to_imu32(colour::kSegmentUnlit);
    for (unsigned digit = 0; digit < 8; ++digit) {
        const std::uint8_t bits = segments[digit];
        for (unsigned s = 0; s < 7; ++s) draw_segment(dl, segment(digit, s), (bits >> s & 1) ? lit : unlit);
        dl->AddCircleFilled(v(dp_centre(digit)), kDpRadius, (bits & 0x80) ? lit : unlit, 12);
    }
}

void draw_keypad(ImDrawList* dl, const Presser& presser) {
    for (const PadKey& k : pad_keys()) {
        const Rect r = key_rect(k);
        const bool digit = k.pad == Pad::Matrix && k.key <= periph::Key::KF;
        const Rgb face = presser.held(k) ? colour::kKeyPressed : digit ? colour::kKey : colour::kKeyFunction;
        dl->AddRectFilled({r.x, r.y}, {r.x + r.w, r.y + r.h}, to_imu32(face), 5);
        dl->AddRect({r.x, r.y}, {r.x + r.w, r.y + r.h}, IM_COL32(0, 0, 0, 255), 5);
        const std::string cap(cap_label(k));
        const ImU32 ink = digit ? IM_COL32(20, 20, 20, 255) : IM_COL32(240, 240, 240, 255);
        const ImVec2 size = ImGui::CalcTextSize(cap.c_str());
        dl->AddText({r.x + (r.w - size.x) / 2, r.y + 6}, ink, cap.c_str());
        const std::string hint = "[" + std::string(pc_key_label(k)) + "]";
        const ImVec2 hs = ImGui::CalcTextSize(hint.c_str());
        dl->AddText({r.x + (r.w - hs.x) / 2, r.y + r.h - hs.y - 3}, digit ? IM_COL32(90, 90, 90, 255) : IM_COL32(170, 190, 230, 255),
                    hint.c_str());
    }
    const float y = kKeyY0 + 4 * kKeyPitchY + 2;
    dl->AddText({kKeyX0, y}, IM_COL32(200, 220, 200, 255),
                "PC keys in [ ]: 0-9 A-F, R, Enter = EXEC, Space = NEXT, Bksp = PREV,\n"
                "G = GO, M = SUBST MEM, X = EXAM REG, S = SINGLE STEP, Esc = RESET,\n"
                "V = VECT INTR. Click a key or type it; a press lasts at least 30 ms.");
}

}  // namespace alp85::gui
