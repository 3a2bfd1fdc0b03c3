#include "emu/gui/input.h"

#include <string>

namespace alp85::gui {
namespace {

// SDL's keycode as the key map's PC key name (keys.h), "" for a key it does not name; the board's
// description decides the rest.
std::string pc_name(SDL_Keycode key) {
    if (key >= SDLK_0 && key <= SDLK_9) return std::string(1, static_cast<char>('0' + (key - SDLK_0)));
    if (key >= SDLK_KP_1 && key <= SDLK_KP_9) return std::string(1, static_cast<char>('1' + (key - SDLK_KP_1)));
    if (key >= SDLK_a && key <= SDLK_z) return std::string(1, static_cast<char>('A' + (key - SDLK_a)));
    switch (key) {
        case SDLK_KP_0: return "0";
        case SDLK_RETURN:
        case SDLK_KP_ENTER: return "Enter";
        case SDLK_SPACE: return "Space";
        case SDLK_BACKSPACE: return "Backspace";
        case SDLK_ESCAPE: return "Esc";
        case SDLK_COMMA: return ",";
        case SDLK_PERIOD: return ".";
        case SDLK_SLASH: return "/";
        default: return {};
    }
}

}  // namespace

std::optional<PadKey> pad_key_for(SDL_Keycode key) {
    const std::string pc = pc_name(key);
    return pc.empty() ? std::nullopt : pad_key_for_pc(pc);
}

std::optional<PadKey> pad_key_for(SDL_Keycode key, const script::Session& s) {
    const std::string pc = pc_name(key);
    return pc.empty() ? std::nullopt : pad_key_for_pc(pc, s);
}

bool is_key_map_key(const SDL_Keysym& k) {
    return k.sym == SDLK_F1 || k.sym == SDLK_QUESTION || (k.sym == SDLK_SLASH && (k.mod & KMOD_SHIFT));
}

}  // namespace alp85::gui
