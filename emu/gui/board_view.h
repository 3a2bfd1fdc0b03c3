// The board drawn into the window from its description (through the Session): its seven-segment
// digits (each segment a bar, lit or unlit, and the decimal point; as many as the board has) and
// its keypad, each key where the description puts it, with its caption and its PC key under it.
#pragma once

#include <array>
#include <cstdint>

#include <imgui.h>

#include "emu/gui/backdrop.h"
#include "emu/gui/input.h"

namespace alp85::gui {

ImU32 to_imu32(Rgb c, std::uint8_t alpha = 255);

void draw_display(ImDrawList* dl, Backdrop& bd, const std::array<std::uint8_t, 8>& segments, unsigned digits);
void draw_keypad(ImDrawList* dl, const Presser& presser, const script::Session& s);
// The key map (F1 or ?): a window over the middle of the picture.
void draw_key_map(bool debug, const script::Session& s);
inline constexpr Rect kKeyMapRect{340, 150, 600, 340};

}  // namespace alp85::gui
