#include "emu/front/keys.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace alp85::front {
namespace {

bool same(const PadKey& a, const PadKey& b) { return a.pad == b.pad && (a.pad != Button::Matrix || a.key == b.key); }

void apply(const PadKey& k, bool down, std::uint64_t at, script::Session& s) { s.key(k.pad, k.key, down, at); }

// A key of the board's description as a button of the front panel.
PadKey pad_of(const board::BoardKey& k) {
    const Button b = k.wire == board::KeyWire::ResetIn    ? Button::Reset
                     : k.wire == board::KeyWire::VectIntr ? Button::Vect
                                                          : Button::Matrix;
    return {b, k.wire == board::KeyWire::Matrix ? k.key : periph::Key::K0, k.panel_row, k.panel_col};
}

const board::BoardKey* described(const PadKey& k, const board::Board& b) {
    for (const board::BoardKey& d : b.keys)
        if (same(pad_of(d), k)) return &d;
    return nullptr;
}

bool same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

std::vector<PadKey> pads_of(const board::Board& b) {
    std::vector<PadKey> out;
    for (const board::BoardKey& k : b.keys) out.push_back(pad_of(k));
    return out;
}

std::optional<PadKey> find_in(std::string_view name, const board::Board& b) {
    if (same_name(name, "VECT INTR") || same_name(name, "VECTINTR")) name = "VECT";
    for (const board::BoardKey& k : b.keys)
        if (same_name(k.name, name)) return pad_of(k);
    return std::nullopt;
}

std::optional<PadKey> for_pc_in(std::string_view pc_name, const board::Board& b) {
    if (pc_name.size() == 1 && std::isxdigit(static_cast<unsigned char>(pc_name[0])))
        return find_in(std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(pc_name[0])))), b);
    for (const board::BoardKey& k : b.keys)
        for (std::string_view pc : k.pc)
            if (!pc.empty() && same_name(pc, pc_name)) return pad_of(k);
    return std::nullopt;
}

std::string_view pc_label_in(const PadKey& k, const board::Board& b) {
    const board::BoardKey* d = described(k, b);
    return d ? d->pc_label : std::string_view{};
}

std::string_view cap_in(const PadKey& k, const board::Board& b) {
    const board::BoardKey* d = described(k, b);
    return d ? d->cap : std::string_view{};
}

const board::Board& default_board() { return script::Session::default_board(); }

}  // namespace

std::span<const PadKey> pad_keys() {
    static const std::vector<PadKey> pads = pads_of(default_board());
    return pads;
}
std::vector<PadKey> pad_keys(const script::Session& s) { return pads_of(s.board()); }

std::optional<PadKey> find_pad_key(std::string_view name) { return find_in(name, default_board()); }
std::optional<PadKey> find_pad_key(std::string_view name, const script::Session& s) { return find_in(name, s.board()); }

std::optional<PadKey> pad_key_for_pc(std::string_view pc_name) { return for_pc_in(pc_name, default_board()); }
std::optional<PadKey> pad_key_for_pc(std::string_view pc_name, const script::Session& s) {
    return for_pc_in(pc_name, s.board());
}

namespace {
// The mouse's rows of the key map, after the keys'.
void mouse_rows(std::vector<KeyMapRow>& rows, bool debug, bool table) {
    if (!debug && table) {
        rows.push_back({"wheel on the table", "zoom about the pointer"});
        rows.push_back({"right or middle drag", "pan the table view"});
        rows.push_back({"Home, double click", "frame the toolpath"});
        rows.push_back({"End", "back to the automatic fit"});
    } else if (debug) {
        rows.push_back({"click a source line", "set or clear a breakpoint"});
    }
    rows.push_back({"F1, ?", "show or hide this key map"});
}

}  // namespace

std::vector<KeyMapRow> key_map_rows(bool debug, const script::Session& s) {
    if (&s.board() == &default_board()) return key_map_rows(debug);
    std::vector<KeyMapRow> rows = {{"0-9, A-F", "the hex keys"}};
    for (const KeypadKey& k : keypad_view(s))
        if (k.fn) rows.push_back({k.pc, k.cap});  // a caption of two lines ("VECT\nINTR") as it is on the cap
    rows.push_back({"click a key", "press it (held at least 30 ms of machine time)"});
    mouse_rows(rows, debug, !s.board().tool.empty());
    return rows;
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
    mouse_rows(rows, debug, true);
    return rows;
}

std::string_view pc_key_label(const PadKey& k) { return pc_label_in(k, default_board()); }
std::string_view pc_key_label(const PadKey& k, const script::Session& s) { return pc_label_in(k, s.board()); }

std::string_view cap_label(const PadKey& k) { return cap_in(k, default_board()); }
std::string_view cap_label(const PadKey& k, const script::Session& s) { return cap_in(k, s.board()); }

std::vector<KeypadKey> keypad_view(const script::Session& s) {
    std::vector<KeypadKey> out;
    for (const board::BoardKey& k : s.board().keys) {
        const PadKey p = pad_of(k);
        const bool hex = p.pad == Button::Matrix && p.key <= periph::Key::KF;
        out.push_back({p, k.name, k.cap, k.pc_label, !hex});
    }
    return out;
}

std::optional<std::string_view> feed_prompt_hint(std::string_view display, bool physical_motors) {
    if (!physical_motors || !display.starts_with("H=")) return std::nullopt;
    return "F 0006-1500 mm/min; F <= 0300 runs away along X (physical motors)";
}

void Presser::down(const PadKey& k, script::Session& m) {
    if (held(k)) return;
    // After a press whose release is still to come (a short one), this one waits its turn: closed
    // with it, it would merge into it (the same key) or be two keys at once to the 8279. A queue
    // further ahead than kQueueLimit is from a machine taken back in time (restore, reverse).
    const std::uint64_t at = free_at_ > m.now() && free_at_ - m.now() <= kQueueLimit ? free_at_ : m.now();
    held_.push_back({k, at});
    apply(k, true, at, m);
}

void Presser::up(const PadKey& k, script::Session& m) {
    const auto it = std::find_if(held_.begin(), held_.end(), [&](const Held& h) { return same(h.key, k); });
    if (it == held_.end()) return;
    const std::uint64_t release = std::max(m.now(), it->since + kMinHold);
    apply(k, false, release, m);
    free_at_ = release + kMinGap;
    held_.erase(it);
}

bool Presser::held(const PadKey& k) const {
    return std::any_of(held_.begin(), held_.end(), [&](const Held& h) { return same(h.key, k); });
}

}  // namespace alp85::front
