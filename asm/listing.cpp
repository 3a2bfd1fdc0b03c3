// The listing in Intel's ASM80 layout: LOC OBJ LINE SOURCE STATEMENT, then the symbol table.
//
// LOC is the address of the line's first byte (or of its label, ORG or DS); for EQU, SET and
// END the value stands there followed by '='. OBJ shows up to four bytes, the rest continue on
// lines of their own. After LINE, '+' marks a macro/REPT expansion line (with its depth) and
// '=' a line from an INCLUDE file. Diagnostics follow the line they concern.
#include <map>

#include <fmt/format.h>

#include "asm/asm85.h"

namespace alp85::asm85 {

std::string write_listing(const Result& r, const OutputFormat& form) {
    std::string out;
    out += form.title;
    if (!r.title.empty()) out += "    " + r.title;
    out += "\n\n  LOC  OBJ         LINE        SOURCE STATEMENT\n\n";

    std::multimap<std::pair<std::string, int>, const Diagnostic*> diags;
    for (auto& d : r.diagnostics)
        if (d.severity != Severity::Note) diags.emplace(std::make_pair(d.file, d.line), &d);

    int number = 0;
    for (const auto& l : r.listing) {
        ++number;
        std::string loc = "    ";
        std::string mark = "  ";
        if (l.value) {
            loc = fmt::format("{:04X}", *l.value);
        } else if (l.address) {
            loc = fmt::format("{:04X}", *l.address);
        }
        std::string obj;
        const auto per_line = static_cast<std::size_t>(form.obj_bytes);
        std::size_t shown = std::min<std::size_t>(l.bytes.size(), per_line);
        for (std::size_t i = 0; i < shown; ++i) obj += fmt::format("{:02X}", l.bytes[i]);
        if (l.value) obj = "=";
        if (l.expansion_depth > 0) mark = l.expansion_depth < 10 ? fmt::format("+{}", l.expansion_depth) : "+*";
        else if (l.include_depth > 0) mark = "= ";
        out += fmt::format("  {:4} {:<8} {:>6} {:2}  {}\n", loc, obj, number, mark, l.text);
        for (std::size_t i = per_line; i < l.bytes.size(); i += per_line) {
            std::string more;
            for (std::size_t k = i; k < std::min(l.bytes.size(), i + per_line); ++k) more += fmt::format("{:02X}", l.bytes[k]);
            auto unit = static_cast<std::size_t>(form.unit_bytes);
            out += fmt::format("  {:04X} {}\n", static_cast<unsigned>((l.address.value_or(0) + i / unit) & 0xFFFF), more);
        }
        if (l.file >= 0 && static_cast<std::size_t>(l.file) < r.files.size()) {
            auto range = diags.equal_range({r.files[static_cast<std::size_t>(l.file)], l.line});
            for (auto it = range.first; it != range.second; ++it) {
                const Diagnostic& d = *it->second;
                out += fmt::format("*** {}: {}\n", d.severity == Severity::Error ? "ERROR" : "WARNING", d.message);
            }
            diags.erase(range.first, range.second);  // once, on the first listing of that line
        }
    }

    out += "\nUSER SYMBOLS\n";
    int col = 0;
    for (const auto& s : r.symbols) {
        if (col > 0) out += "   ";
        out += fmt::format("{:<10} {} {:04X}", s.name, s.kind == SymbolKind::Label ? 'L' : s.kind == SymbolKind::Set ? 'S' : 'E', s.value);
        if (++col == 4) {
            out += '\n';
            col = 0;
        }
    }
    if (col != 0) out += '\n';
    int errors = r.error_count();
    int warnings = r.warning_count();
    out += "\nASSEMBLY COMPLETE, ";
    out += errors == 0 ? std::string("NO ERRORS") : fmt::format("{} ERROR{}", errors, errors == 1 ? "" : "S");
    if (warnings) out += fmt::format(", {} WARNING{}", warnings, warnings == 1 ? "" : "S");
    out += '\n';
    return out;
}

}  // namespace alp85::asm85
