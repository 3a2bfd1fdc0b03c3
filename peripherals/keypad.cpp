#include "peripherals/keypad.h"

#include <algorithm>
#include <cctype>

#include "peripherals/state_io.h"

namespace alp85::periph {

namespace {
constexpr std::array<KeyInfo, Keypad::kKeyCount> kLayout{{
    {Key::K0, "0", "0", 0, 0},       {Key::K1, "1", "1", 0, 1},       {Key::K2, "2", "2", 0, 2},
    {Key::K3, "3", "3", 0, 3},       {Key::K4, "4", "4", 0, 4},       {Key::K5, "5", "5", 0, 5},
    {Key::K6, "6", "6", 0, 6},       {Key::K7, "7", "7", 0, 7},       {Key::K8, "8", "8", 1, 0},
    {Key::K9, "9", "9", 1, 1},       {Key::KA, "A", "A", 1, 2},       {Key::KB, "B", "B", 1, 3},
    {Key::KC, "C", "C", 1, 4},       {Key::KD, "D", "D", 1, 5},       {Key::KE, "E", "E", 1, 6},
    {Key::KF, "F", "F", 1, 7},       {Key::Exec, "EXEC", "EXEC", 2, 0}, {Key::Next, "NEXT", "NEXT", 2, 1},
    {Key::Go, "GO", "GO", 2, 2},     {Key::Mem, "MEM", "SUBST MEM", 2, 3}, {Key::Reg, "REG", "EXAM REG", 2, 4},
    {Key::Step, "STEP", "SINGLE STEP", 2, 5}, {Key::Prev, "PREV", "PREV", 2, 6}, {Key::R, "R", "R", 2, 7},
}};

bool iequal(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::toupper(static_cast<unsigned char>(x)) == std::toupper(static_cast<unsigned char>(y));
           });
}
}  // namespace

std::span<const KeyInfo, Keypad::kKeyCount> Keypad::layout() { return kLayout; }

const KeyInfo& Keypad::info(Key key) { return kLayout[static_cast<std::size_t>(key)]; }

std::optional<Key> Keypad::find(std::string_view name) {
    for (const auto& k : kLayout) {
        if (iequal(k.name, name)) return k.key;
    }
    return std::nullopt;
}

std::optional<Key> Keypad::from_code(std::uint8_t fifo_code) {
    for (const auto& k : kLayout) {
        if (k.code() == (fifo_code & 0x3F)) return k.key;
    }
    return std::nullopt;
}

std::array<std::uint8_t, Keypad::kKeyCount> Keypad::layout_places() {
    std::array<std::uint8_t, kKeyCount> places{};
    for (const KeyInfo& k : kLayout) places[static_cast<std::size_t>(k.key)] = k.code();
    return places;
}

void Keypad::clear_places() {
    place_.fill(kNowhere);
    closed_.fill(0);
}

void Keypad::place(Key key, std::uint8_t row, std::uint8_t column) {
    place_[static_cast<std::size_t>(key)] = static_cast<std::uint8_t>((row & 7) * 8 + (column & 7));
}

void Keypad::set(Key key, bool down) {
    const std::uint8_t p = place_[static_cast<std::size_t>(key)];
    if (p == kNowhere) return;
    const std::uint8_t row = p / 8;
    const auto bit = static_cast<std::uint8_t>(1u << (p % 8));
    closed_[row] = static_cast<std::uint8_t>(down ? (closed_[row] | bit) : (closed_[row] & ~bit));
}

bool Keypad::is_pressed(Key key) const {
    const std::uint8_t p = place_[static_cast<std::size_t>(key)];
    return p != kNowhere && ((closed_[p / 8] >> (p % 8)) & 1);
}

std::uint8_t Keypad::return_lines(std::uint8_t scan_lines) const {
    return static_cast<std::uint8_t>(~closed_[scan_lines & 7]);
}

void Keypad::load_state(StateReader& r) {
    std::array<std::uint8_t, 8> rows{};
    std::uint64_t now = 0;
    r(now), r(rows);
    r.expect_end();
    std::array<std::uint8_t, 8> used{};  // per row: the return lines a key sits on
    for (const std::uint8_t p : place_)
        if (p != kNowhere) used[p / 8] = static_cast<std::uint8_t>(used[p / 8] | 1u << (p % 8));
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i] & ~used[i]) r.fail(used[i] ? "key down where this board has none" : "key down on an unused row");
    }
    closed_ = rows;
    now_ = now;
}

void Keypad::describe(Description& d) const {
    d.title = "keypad (key matrix)";
    std::string down;
    for (const KeyInfo& k : layout())
        if (is_pressed(k.key)) down += (down.empty() ? "" : " ") + std::string(k.name);
    d.add(Field::note("keys down", down.empty() ? "none" : down));
}

}  // namespace alp85::periph
