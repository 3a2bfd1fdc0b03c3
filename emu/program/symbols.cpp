#include "emu/program/symbols.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85 {

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
    std::vector<std::string> files;
    if (j.contains("files")) {
        if (!j["files"].is_array()) return "asm85 map: files is not an array";
        for (const auto& f : j["files"]) {
            if (!f.is_string()) return "asm85 map: a file name that is not a string";
            files.push_back(f.get<std::string>());
        }
    }
    if (j.contains("lines")) {
        if (!j["lines"].is_array()) return "asm85 map: lines is not an array";
        for (const auto& l : j["lines"]) {
            if (!l.is_object() || !l.contains("address") || !l["address"].is_number_unsigned() ||
                l["address"].get<unsigned long long>() > 0xFFFF || !l.contains("length") ||
                !l["length"].is_number_unsigned() || l["length"].get<unsigned long long>() > 0x10000 ||
                !l.contains("file") || !l["file"].is_number_unsigned() ||
                l["file"].get<unsigned long long>() >= files.size() || !l.contains("line") ||
                !l["line"].is_number_integer())
                return "asm85 map: a line entry without address, length, file or line";
        }
    }
    for (const auto& s : j["symbols"]) {
        const std::string name = s["name"].get<std::string>();
        const auto value = static_cast<std::uint16_t>(s["value"].get<unsigned>());
        const std::string kind = s.contains("kind") ? s["kind"].get<std::string>() : "label";
        add(name, value, kind);
    }
    if (j.contains("lines")) {
        for (const auto& l : j["lines"])
            add_line(static_cast<std::uint16_t>(l["address"].get<unsigned>()),
                     static_cast<std::uint16_t>(std::min(l["length"].get<unsigned>(), 0xFFFFu)),
                     files[l["file"].get<std::size_t>()], l["line"].get<int>());
    }
    return {};
}

void SymbolTable::add_assembly(const asm85::Result& result) {
    for (const asm85::Symbol& s : result.symbols) {
        add(s.name, s.value, asm85::kind_name(s.kind));
    }
    for (const asm85::LineSpan& l : result.line_map) {
        if (l.file >= 0 && static_cast<std::size_t>(l.file) < result.files.size())
            add_line(l.address, l.length, result.files[static_cast<std::size_t>(l.file)], l.line);
    }
}

void SymbolTable::add_table(const SymbolTable& other) {
    for (const auto& [addr, name] : other.labels_) add(name, addr, "label");
    for (const auto& [addr, name] : other.equates_) add(name, addr, "equ");
    for (const auto& [name, value] : other.names()) by_name_[name] = value;
    for (const Span& sp : other.spans_)
        add_line(sp.address, sp.length, other.files_[static_cast<std::size_t>(sp.file)], sp.line);
}

int SymbolTable::file_index(const std::string& file) {
    for (std::size_t i = 0; i < files_.size(); ++i)
        if (files_[i] == file) return static_cast<int>(i);
    files_.push_back(file);
    return static_cast<int>(files_.size() - 1);
}

void SymbolTable::add_line(std::uint16_t address, std::uint16_t length, const std::string& file, int line) {
    if (length == 0) return;
    spans_.push_back({address, length, file_index(file), line});
    starts_[address] = length;
    if (span_at_.empty()) span_at_.assign(0x10000, 0);
    const auto index = static_cast<std::uint32_t>(spans_.size());
    for (std::uint32_t k = 0; k < length; ++k) span_at_[static_cast<std::uint16_t>(address + k)] = index;
}

std::optional<SourceLine> SymbolTable::line_of(std::uint16_t addr) const {
    if (span_at_.empty() || span_at_[addr] == 0) return std::nullopt;
    const Span& s = spans_[span_at_[addr] - 1];
    return SourceLine{files_[static_cast<std::size_t>(s.file)], s.line};
}

bool SymbolTable::file_matches(int index, std::string_view file) const {
    const std::string& full = files_[static_cast<std::size_t>(index)];
    if (full == file) return true;
    // "thesis.asm" or "thesis/thesis.asm" names the file whose path ends in those components.
    return full.size() > file.size() && full.compare(full.size() - file.size(), file.size(), file) == 0 &&
           full[full.size() - file.size() - 1] == '/';
}

std::vector<std::uint16_t> SymbolTable::addresses_of(std::string_view file, int line) const {
    std::vector<std::uint16_t> out;
    for (const Span& s : spans_) {
        if (s.line == line && file_matches(s.file, file) &&
            std::find(out.begin(), out.end(), s.address) == out.end())
            out.push_back(s.address);
    }
    return out;
}

std::optional<SourceLine> SymbolTable::next_line_with_code(std::string_view file, int line) const {
    std::optional<SourceLine> best;
    for (const Span& s : spans_) {
        if (s.line >= line && file_matches(s.file, file) && (!best || s.line < best->line))
            best = SourceLine{files_[static_cast<std::size_t>(s.file)], s.line};
    }
    return best;
}

void SymbolTable::add(std::string_view name, std::uint16_t value, std::string_view kind) {
    by_name_[to_upper(name)] = value;
    if (kind == "label")
        labels_.emplace(value, std::string(name));
    else if (kind == "equ" || kind == "set")
        equates_.emplace(value, std::string(name));
}

std::string SymbolTable::load_map_file(const std::string& path) {
    std::string text;
    try {
        text = read_input(path, FileKind::Map);
    } catch (const InputError& e) {
        return e.what();
    }
    const std::string err = load_map_text(text);
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

std::optional<std::string> SymbolTable::data_name_near(std::uint16_t value) const {
    if (auto n = data_name_at(value)) return n;
    std::optional<std::pair<std::uint16_t, std::string>> below;
    if (auto it = labels_.upper_bound(value); it != labels_.begin()) below = *std::prev(it);
    if (auto it = equates_.upper_bound(value); it != equates_.begin())
        if (const auto& e = *std::prev(it); e.first > 0xFF && (!below || e.first > below->first)) below = e;
    if (!below || value - below->first >= 256) return std::nullopt;
    return below->second + "+" + std::to_string(value - below->first);
}

std::optional<std::string> SymbolTable::label_at(std::uint16_t addr) const {
    if (auto it = labels_.find(addr); it != labels_.end()) return it->second;
    return std::nullopt;
}

std::optional<std::string> SymbolTable::code_name_at(std::uint16_t addr) const {
    if (auto it = labels_.find(addr); it != labels_.end()) return it->second;
    if (addr > 0xFF && starts_.contains(addr))
        if (auto it = equates_.find(addr); it != equates_.end()) return it->second;
    return std::nullopt;
}

std::optional<std::string> SymbolTable::routine_at(std::uint16_t addr) const {
    constexpr int kReach = 1024;  // no routine of these programs is longer
    // The nearest name at or before addr; any label (a data table's too) ends the routine before it.
    std::optional<std::uint16_t> base;
    std::string name;
    if (auto it = labels_.upper_bound(addr); it != labels_.begin()) {
        --it;
        base = it->first;
        name = it->second;
    }
    for (auto it = equates_.upper_bound(addr); it != equates_.begin();) {
        --it;
        if (base && it->first <= *base) break;
        if (addr - it->first > kReach) break;
        if (code_name_at(it->first) == it->second) {
            base = it->first;
            name = it->second;
            break;
        }
    }
    if (!base || addr - *base > kReach) return std::nullopt;
    if (*base == addr) return name;
    // Within the routine: instruction-sized lines, one after the other, from its name to addr.
    std::uint32_t a = *base;
    while (a < addr) {
        const auto it = starts_.find(static_cast<std::uint16_t>(a));
        if (it == starts_.end() || it->second > 3) return std::nullopt;
        a += it->second;
    }
    if (a != addr) return std::nullopt;
    return name + "+" + std::to_string(addr - *base);
}

std::optional<std::uint16_t> SymbolTable::value_of(std::string_view name) const {
    if (auto it = by_name_.find(to_upper(name)); it != by_name_.end()) return it->second;
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
