#include "emu/program/symbols.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace alp85 {

namespace {
std::string upper(std::string_view s) {
    std::string u(s);
    std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return u;
}
}  // namespace

std::string SymbolTable::load_map_text(std::string_view json) {
    nlohmann::json j = nlohmann::json::parse(json.begin(), json.end(), nullptr, false);
    if (j.is_discarded()) return "not valid JSON";
    // Check each member's type before reading it: json::value() throws on a wrong type.
    if (!j.is_object() || !j.contains("format") || !j["format"].is_string() ||
        j["format"].get<std::string>() != "alp85-asm-map")
        return "not an asm85 map (format alp85-asm-map)";
    if (!j.contains("version") || !j["version"].is_number_integer() || j["version"].get<int>() != 1)
        return "unsupported asm85 map version";
    if (!j.contains("symbols") || !j["symbols"].is_array()) return "asm85 map without a symbols array";
    // Validate everything before taking anything.
    for (const auto& s : j["symbols"]) {
        if (!s.is_object() || !s.contains("name") || !s["name"].is_string() || !s.contains("value") ||
            !s["value"].is_number_unsigned() || s["value"].get<unsigned long long>() > 0xFFFF)
            return "asm85 map: a symbol without a name or a 16-bit value";
        if (s.contains("kind") && !s["kind"].is_string()) return "asm85 map: a symbol kind that is not a string";
    }
    for (const auto& s : j["symbols"]) {
        const std::string name = s["name"].get<std::string>();
        const auto value = static_cast<std::uint16_t>(s["value"].get<unsigned>());
        const std::string kind = s.contains("kind") ? s["kind"].get<std::string>() : "label";
        add(name, value, kind);
    }
    return {};
}

void SymbolTable::add(std::string_view name, std::uint16_t value, std::string_view kind) {
    by_name_.emplace(upper(name), value);
    if (kind == "label")
        labels_.emplace(value, std::string(name));
    else if (kind == "equ" || kind == "set")
        equates_.emplace(value, std::string(name));
}

std::string SymbolTable::load_map_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) return "cannot open " + path;
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string err = load_map_text(ss.str());
    return err.empty() ? err : path + ": " + err;
}

std::optional<std::string> SymbolTable::name_at(std::uint16_t addr) const {
    if (auto it = labels_.find(addr); it != labels_.end()) return it->second;
    if (auto it = equates_.find(addr); it != equates_.end()) return it->second;
    return std::nullopt;
}

std::optional<std::string> SymbolTable::data_name_at(std::uint16_t value) const {
    if (auto it = labels_.find(value); it != labels_.end()) return it->second;
    if (value > 0xFF)
        if (auto it = equates_.find(value); it != equates_.end()) return it->second;
    return std::nullopt;
}

std::optional<std::string> SymbolTable::label_at(std::uint16_t addr) const {
    if (auto it = labels_.find(addr); it != labels_.end()) return it->second;
    return std::nullopt;
}

std::optional<std::uint16_t> SymbolTable::value_of(std::string_view name) const {
    if (auto it = by_name_.find(upper(name)); it != by_name_.end()) return it->second;
    return std::nullopt;
}

asm85::Disassembly disassemble(const Bus& bus, std::uint16_t addr, Variant variant, const SymbolTable* symbols) {
    asm85::DisasmOptions opt;
    opt.cpu8080 = variant == Variant::I8080;
    if (symbols) {
        opt.symbol = [symbols](std::uint16_t a) { return symbols->name_at(a); };
        opt.data_symbol = [symbols](std::uint16_t v) { return symbols->data_name_at(v); };
    }
    return asm85::disassemble([&bus](std::uint16_t a) { return bus.peek(a); }, addr, opt);
}

}  // namespace alp85
