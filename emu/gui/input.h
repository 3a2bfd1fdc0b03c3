// The window's keyboard: SDL's keycodes onto the one key map (keys.h).
#pragma once

#include <optional>

#include <SDL.h>

#include "emu/front/keys.h"
#include "emu/gui/layout.h"

namespace alp85::gui {

// The board key for an SDL keycode (the keypad's digits and Enter as the main ones): the default
// board's, or the session's board's (its description's PC keys).
std::optional<PadKey> pad_key_for(SDL_Keycode key);
std::optional<PadKey> pad_key_for(SDL_Keycode key, const script::Session& s);
// F1 or '?' (Shift+/ on most layouts): show or hide the key map.
bool is_key_map_key(const SDL_Keysym& k);

}  // namespace alp85::gui
