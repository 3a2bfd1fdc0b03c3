// The board drawn into the window: the eight seven-segment digits (each segment a bar, lit or
// unlit, and the decimal point) and the keypad with each key's PC key under its caption.
#pragma once

#include <array>
#include <cstdint>

#include <imgui.h>

#include "emu/gui/backdrop.h"
#include "emu/gui/input.h"

namespace alp85::gui {

ImU32 to_imu32(Rgb c, std::uint8_t alpha = 255);

void draw_display(ImDrawList* dl, Backdrop& bd, const std::array<std::uint8_t, 8>& segments);
void draw_keypad(ImDrawList* dl, const Presser& presser);
// The key map (F1 or ?): a window over the middle of the picture.
void draw_key_map(bool debug);
inline constexpr Rect kKeyMapRect{340, 150, 600, 340};

}  // namespace alp85::gui
