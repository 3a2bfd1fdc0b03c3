#include "peripherals/description.h"

#include <cctype>

#include <fmt/format.h>

namespace alp85::periph {

namespace {
bool same_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    return true;
}
const Field* find_in(const std::vector<Field>& fields, std::string_view watch) {
    for (const Field& f : fields) {
        if (!f.watch.empty() && same_name(f.watch, watch)) return &f;
        if (const Field* g = find_in(f.fields, watch)) return g;
    }
    return nullptr;
}
void names_in(const std::vector<Field>& fields, std::vector<std::string>& out) {
    for (const Field& f : fields) {
        if (!f.watch.empty()) out.push_back(f.watch);
        names_in(f.fields, out);
    }
}
}  // namespace

Field Field::hex(std::string name, std::int64_t value, int width, std::string text) {
    return {std::move(name), value, width, -1, Shown::Hex, std::move(text), {}, {}};
}

Field Field::bits(std::string name, std::int64_t reg, int lsb, int width, std::string text) {
    const std::int64_t v = (reg >> lsb) & ((std::int64_t{1} << width) - 1);
    return {std::move(name), v, width, lsb, width > 4 ? Shown::Hex : Shown::Bits, std::move(text), {}, {}};
}

Field Field::flag(std::string name, bool set, int bit, std::string text_when_set) {
    return {std::move(name), set ? 1 : 0, 1, bit, Shown::Bits, set ? std::move(text_when_set) : std::string{}, {}, {}};
}

Field Field::decimal(std::string name, std::int64_t value, int width, std::string text) {
    return {std::move(name), value, width, -1, Shown::Decimal, std::move(text), {}, {}};
}

Field Field::note(std::string name, std::string text) {
    return {std::move(name), 0, 0, -1, Shown::Text, std::move(text), {}, {}};
}

std::string Field::number() const {
    switch (shown) {
        case Shown::Hex: return width <= 8 ? fmt::format("{:02X}H", value) : fmt::format("{:04X}H", value);
        case Shown::Bits: return fmt::format("{:0{}b}", value, width);
        case Shown::Decimal: return std::to_string(value);
        case Shown::Text: return {};
    }
    return {};
}

std::string Field::bit_range() const {
    if (lsb < 0) return {};
    return width == 1 ? fmt::format("bit {}", lsb) : fmt::format("bits {}-{}", lsb + width - 1, lsb);
}

std::string Field::shown_value() const {
    std::string v = lsb >= 0 ? bit_range() + " = " + number() : number();
    if (!text.empty()) v += v.empty() ? text : ": " + text;
    return v;
}

const Field* Description::find_watch(std::string_view watch) const { return find_in(fields, watch); }

std::vector<std::string> Description::watch_names() const {
    std::vector<std::string> out;
    names_in(fields, out);
    return out;
}

std::string summary(const std::vector<Field>& fields) {
    std::string out;
    for (const Field& f : fields) {
        if (f.text.empty()) continue;
        if (!out.empty()) out += ", ";
        out += f.name + " " + f.text;
    }
    return out;
}

}  // namespace alp85::periph
