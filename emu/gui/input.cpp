#include "emu/gui/input.h"

#include <string>

namespace alp85::gui {

// SDL's keycode as the key map's PC key name (keys.h); the key map decides the rest.
std::optional<PadKey> pad_key_for(SDL_Keycode key) {
    if (key >= SDLK_0 && key <= SDLK_9) return pad_key_for_pc(std::string(1, static_cast<char>('0' + (key - SDLK_0))));
    if (key >= SDLK_KP_1 && key <= SDLK_KP_9) return pad_key_for_pc(std::string(1, static_cast<char>('1' + (key - SDLK_KP_1))));
    if (key >= SDLK_a && key <= SDLK_z) return pad_key_for_pc(std::string(1, static_cast<char>('A' + (key - SDLK_a))));
    switch (key) {
        case SDLK_KP_0: return pad_key_for_pc("0");
        case SDLK_RETURN:
        case SDLK_KP_ENTER: return pad_key_for_pc("Enter");
        case SDLK_SPACE: return pad_key_for_pc("Space");
        case SDLK_BACKSPACE: return pad_key_for_pc("Backspace");
        case SDLK_ESCAPE: return pad_key_for_pc("Esc");
        default: return std::nullopt;
    }
}

bool is_key_map_key(const SDL_Keysym& k) {
    return k.sym == SDLK_F1 || k.sym == SDLK_QUESTION || (k.sym == SDLK_SLASH && (k.mod & KMOD_SHIFT));
}

}  // namespace alp85::gui
