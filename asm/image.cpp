// The sparse memory image and the Result queries.
#include <algorithm>

#include "asm/asm85.h"
#include "asm/lexer.h"

namespace alp85::asm85 {

Image::Image() = default;

bool Image::write(std::uint16_t address, std::uint8_t value) {
    if (bytes_.empty()) {  // allocated on the first byte: most images never pay for 64 KiB twice
        bytes_.assign(0x10000, 0);
        used_.assign(0x10000, false);
        lo_ = hi_ = address;
    }
    bool fresh = !used_[address];
    bytes_[address] = value;
    if (fresh) {
        used_[address] = true;
        ++count_;
        lo_ = std::min(lo_, address);
        hi_ = std::max(hi_, address);
    }
    return fresh;
}

std::optional<std::uint8_t> Image::read(std::uint16_t address) const {
    if (bytes_.empty() || !used_[address]) return std::nullopt;
    return bytes_[address];
}

std::uint16_t Image::lowest() const { return lo_; }

std::uint16_t Image::highest() const { return hi_; }

std::vector<Segment> Image::segments() const {
    std::vector<Segment> out;
    if (count_ == 0) return out;
    for (std::uint32_t a = lo_; a <= hi_; ++a) {
        if (!used_[a]) continue;
        if (out.empty() || out.back().end() != a) out.push_back({static_cast<std::uint16_t>(a), {}});
        out.back().bytes.push_back(bytes_[a]);
    }
    return out;
}

std::string_view kind_name(SymbolKind k) {
    switch (k) {
        case SymbolKind::Label: return "label";
        case SymbolKind::Equ: return "equ";
        case SymbolKind::Set: return "set";
        case SymbolKind::Define: return "define";
    }
    return "label";
}

std::optional<Cpu> parse_cpu(std::string_view text) {
    std::string t = to_upper(text);
    if (t == "8080") return Cpu::i8080;
    if (t == "8085") return Cpu::i8085;
    if (t == "8085U") return Cpu::i8085u;
    return std::nullopt;
}

int Result::error_count() const {
    return static_cast<int>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                          [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

int Result::warning_count() const {
    return static_cast<int>(std::count_if(diagnostics.begin(), diagnostics.end(),
                                          [](const Diagnostic& d) { return d.severity == Severity::Warning; }));
}

const Symbol* Result::find_symbol(std::string_view name) const {
    std::string up = to_upper(name);
    auto it = std::lower_bound(symbols.begin(), symbols.end(), up, [](const Symbol& s, const std::string& n) { return s.name < n; });
    return it != symbols.end() && it->name == up ? &*it : nullptr;
}

const LineSpan* Result::origin(std::uint16_t address) const {
    // The last span covering the address wins (a later ORG overwrote the byte).
    for (auto it = line_map.rbegin(); it != line_map.rend(); ++it)
        if (address >= it->address && address < it->address + it->length) return &*it;
    return nullptr;
}

}  // namespace alp85::asm85
