#include "emu/front/keys.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

namespace alp85::front {
namespace {

bool same(const PadKey& a, const PadKey& b) { return a.pad == b.pad && (a.pad != Button::Matrix || a.key == b.key); }

void apply(const PadKey& k, bool down, std::uint64_t at, script::Session& s) { s.key(k.pad, k.key, down, at); }

using periph::Key;
constexpr std::array<PadKey, 26> kPad{{
    {Button::Reset, Key::K0, 0, 0}, {Button::Vect, Key::K0, 0, 1}, {Button::Matrix, Key::R, 0, 2},
    {Button::Matrix, Key::KC, 0, 3}, {Button::Matrix, Key::KD, 0, 4}, {Button::Matrix, Key::KE, 0, 5},
    {Button::Matrix, Key::KF, 0, 6},
    {Button::Matrix, Key::Reg, 1, 0}, {Button::Matrix, Key::Mem, 1, 1}, {Button::Matrix, Key::Go, 1, 2},
    {Button::Matrix, Key::K8, 1, 3}, {Button::Matrix, Key::K9, 1, 4}, {Button::Matrix, Key::KA, 1, 5},
    {Button::Matrix, Key::KB, 1, 6},
    {Button::Matrix, Key::Step, 2, 0}, {Button::Matrix, Key::Prev, 2, 1}, {Button::Matrix, Key::Next, 2, 2},
    {Button::Matrix, Key::K4, 2, 3}, {Button::Matrix, Key::K5, 2, 4}, {Button::Matrix, Key::K6, 2, 5},
    {Button::Matrix, Key::K7, 2, 6},
    {Button::Matrix, Key::Exec, 3, 2}, {Button::Matrix, Key::K0, 3, 3}, {Button::Matrix, Key::K1, 3, 4},
    {Button::Matrix, Key::K2, 3, 5}, {Button::Matrix, Key::K3, 3, 6},
}};

// The function keys on the PC (the hex keys are their own names); key_map_rows describes them.
// The last two are the browser's names (KeyboardEvent.key) of Esc and Space.
constexpr std::array<PcKey, 12> kPcKeys{{
    {"Enter", "EXEC", "Enter"}, {"Space", "NEXT", "Space"}, {"Backspace", "PREV", "Bksp"},
    {"R", "R", "R"}, {"G", "GO", "G"}, {"M", "MEM", "M"}, {"X", "REG", "X"}, {"S", "STEP", "S"},
    {"Esc", "RESET", "Esc"}, {"V", "VECT", "V"}, {"Escape", "RESET", "Esc"}, {" ", "NEXT", "Space"},
}};

bool same_name(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}

}  // namespace

std::span<const PadKey> pad_keys() { return kPad; }

std::optional<PadKey> find_pad_key(std::string_view name) {
    if (same_name(name, "RESET")) return kPad[0];
    if (same_name(name, "VECT") || same_name(name, "VECT INTR") || same_name(name, "VECTINTR")) return kPad[1];
    const auto key = periph::Keypad::find(name);
    if (!key) return std::nullopt;
    for (const PadKey& k : kPad)
        if (k.pad == Button::Matrix && k.key == *key) return k;
    return std::nullopt;
}

std::optional<PadKey> pad_key_for_pc(std::string_view pc_name) {
    if (pc_name.size() == 1 && std::isxdigit(static_cast<unsigned char>(pc_name[0])))
        return find_pad_key(std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(pc_name[0])))));
    for (const PcKey& p : kPcKeys)
        if (same_name(p.pc, pc_name)) return find_pad_key(p.pad);
    return std::nullopt;
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
    for (const PcKey& p : kPcKeys)
        if (const auto pad = find_pad_key(p.pad); pad && pad->pad == k.pad && (k.pad != Button::Matrix || pad->key == k.key))
            return p.label;
    return periph::Keypad::info(k.key).name;  // the hex digit itself
}

std::string_view cap_label(const PadKey& k) {
    if (k.pad == Button::Reset) return "RESET";
    if (k.pad == Button::Vect) return "VECT\nINTR";
    switch (k.key) {
        case periph::Key::Mem: return "SUBST\nMEM";
        case periph::Key::Reg: return "EXAM\nREG";
        case periph::Key::Step: return "SINGLE\nSTEP";
        default: return periph::Keypad::info(k.key).label;
    }
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
