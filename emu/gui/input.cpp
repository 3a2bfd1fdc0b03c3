#include "emu/gui/input.h"

#include <algorithm>

#include "emu/board/key_press.h"

namespace alp85::gui {
namespace {

bool same(const PadKey& a, const PadKey& b) { return a.pad == b.pad && (a.pad != Pad::Matrix || a.key == b.key); }

void apply(const PadKey& k, bool down, std::uint64_t at, Machine& m) {
    const Button b = k.pad == Pad::Matrix ? Button::Matrix : k.pad == Pad::Reset ? Button::Reset : Button::Vect;
    schedule_key(m, b, k.key, down, at);
}

}  // namespace

std::optional<PadKey> pad_key_for(SDL_Keycode key) {
    if (key >= SDLK_0 && key <= SDLK_9) return find_pad_key(std::string(1, static_cast<char>('0' + (key - SDLK_0))));
    if (key >= SDLK_KP_1 && key <= SDLK_KP_9) return find_pad_key(std::string(1, static_cast<char>('1' + (key - SDLK_KP_1))));
    if (key >= SDLK_a && key <= SDLK_f) return find_pad_key(std::string(1, static_cast<char>('A' + (key - SDLK_a))));
    switch (key) {
        case SDLK_KP_0: return find_pad_key("0");
        case SDLK_r: return find_pad_key("R");
        case SDLK_RETURN:
        case SDLK_KP_ENTER: return find_pad_key("EXEC");
        case SDLK_SPACE: return find_pad_key("NEXT");
        case SDLK_BACKSPACE: return find_pad_key("PREV");
        case SDLK_g: return find_pad_key("GO");
        case SDLK_m: return find_pad_key("MEM");
        case SDLK_x: return find_pad_key("REG");
        case SDLK_s: return find_pad_key("STEP");
        case SDLK_ESCAPE: return find_pad_key("RESET");
        case SDLK_v: return find_pad_key("VECT");
        default: return std::nullopt;
    }
}

bool is_key_map_key(const SDL_Keysym& k) {
    return k.sym == SDLK_F1 || k.sym == SDLK_QUESTION || (k.sym == SDLK_SLASH && (k.mod & KMOD_SHIFT));
}

std::vector<KeyMapRow> key_map_rows(bool debug) {
    std::vector<KeyMapRow> rows = {
        {"0-9, A-F", "the hex keys"},
        {"Enter", "EXEC"},
        {"Space", "NEXT"},
        {"Backspace", "PREV"},
        {"R", "R (run a program: R 7 0800 EXEC)"},
        {"G", "GO"},
        {"M", "SUBST MEM"},
        {"X", "EXAM REG"},
        {"S", "SINGLE STEP"},
        {"Esc", "RESET"},
        {"V", "VECT INTR (RST 7.5)"},
        {"click a key", "press it (held at least 30 ms of machine time)"},
    };
    if (!debug) {
        rows.push_back({"wheel on the table", "zoom about the pointer"});
        rows.push_back({"right or middle drag", "pan the table view"});
        rows.push_back({"Home, double click", "frame the toolpath"});
        rows.push_back({"End", "back to the automatic fit"});
    } else {
        rows.push_back({"click a source line", "set or clear a breakpoint"});
    }
    rows.push_back({"F1, ?", "show or hide this key map"});
    return rows;
}

std::string_view pc_key_label(const PadKey& k) {
    if (k.pad == Pad::Reset) return "Esc";
    if (k.pad == Pad::Vect) return "V";
    switch (k.key) {
        case periph::Key::Exec: return "Enter";
        case periph::Key::Next: return "Space";
        case periph::Key::Prev: return "Bksp";
        case periph::Key::Go: return "G";
        case periph::Key::Mem: return "M";
        case periph::Key::Reg: return "X";
        case periph::Key::Step: return "S";
        case periph::Key::R: return "R";
        default: return periph::Keypad::info(k.key).name;  // the hex digit itself
    }
}

std::string_view cap_label(const PadKey& k) {
    if (k.pad == Pad::Reset) return "RESET";
    if (k.pad == Pad::Vect) return "VECT\nINTR";
    switch (k.key) {
        case periph::Key::Mem: return "SUBST\nMEM";
        case periph::Key::Reg: return "EXAM\nREG";
        case periph::Key::Step: return "SINGLE\nSTEP";
        default: return periph::Keypad::info(k.key).label;
    }
}

void Presser::down(const PadKey& k, Machine& m) {
    if (held(k)) return;
    held_.push_back({k, m.now()});
    apply(k, true, m.now(), m);
}

void Presser::up(const PadKey& k, Machine& m) {
    const auto it = std::find_if(held_.begin(), held_.end(), [&](const Held& h) { return same(h.key, k); });
    if (it == held_.end()) return;
    apply(k, false, std::max(m.now(), it->since + kMinHold), m);
    held_.erase(it);
}

void Presser::release_all(Machine& m) {
    while (!held_.empty()) up(held_.back().key, m);
}

bool Presser::held(const PadKey& k) const {
    return std::any_of(held_.begin(), held_.end(), [&](const Held& h) { return same(h.key, k); });
}

}  // namespace alp85::gui
