#include "emu/program/disasm_listing.h"

#include <array>
#include <bitset>

#include <fmt/format.h>

#include "asm/disasm.h"

namespace alp85 {

namespace {

// The jumps and calls with a 16-bit target (JMP, CALL, Jcc, Ccc; the 8085's JNK and JK).
bool transfers_control(std::uint8_t op, Variant v) {
    if (op == 0xC3 || op == 0xCD) return true;
    if ((op & 0xC7) == 0xC2 || (op & 0xC7) == 0xC4) return true;  // Jcc, Ccc
    return v == Variant::I8085 && (op == 0xDD || op == 0xFD);
}

DisasmResult decode(const std::vector<ImageSegment>& segments, const ImageDisasmOptions& options);

}  // namespace

DisasmResult disassemble_image(const std::vector<ImageSegment>& segments, const ImageDisasmOptions& options) {
    if (!options.label_targets) return decode(segments, options);
    // Decode once to see where lines start and what jumps where, then again with the labels.
    ImageDisasmOptions plain = options;
    plain.label_targets = false;
    const DisasmResult first = decode(segments, plain);
    if (first.blocks.empty()) return first;
    std::set<std::uint16_t> starts;
    for (const DisasmBlock& b : first.blocks)
        for (const DisasmLine& l : b.lines) starts.insert(l.address);
    SymbolTable labels;
    if (options.symbols) labels.add_table(*options.symbols);
    const auto has_label = [&](std::uint16_t a) { return labels.label_at(a).has_value(); };
    const auto add_label = [&](std::uint16_t a, std::string name) {
        if (labels.value_of(name)) name = fmt::format("L{:04X}", a);
        while (labels.value_of(name)) name += '_';
        labels.add(name, a, "label");
    };
    const std::uint16_t entry = first.blocks.front().lines.front().address;
    if (!has_label(entry)) add_label(entry, "START");
    for (const DisasmBlock& b : first.blocks)
        for (const DisasmLine& l : b.lines) {
            if (l.bytes.size() != 3 || !transfers_control(l.bytes[0], options.variant)) continue;
            const auto target = static_cast<std::uint16_t>(l.bytes[1] | l.bytes[2] << 8);
            if (starts.count(target) && !has_label(target)) add_label(target, fmt::format("L{:04X}", target));
        }
    plain.symbols = &labels;
    return decode(segments, plain);
}

namespace {

DisasmResult decode(const std::vector<ImageSegment>& segments, const ImageDisasmOptions& options) {
    std::array<std::uint8_t, 0x10000> mem{};
    std::bitset<0x10000> present;
    for (const ImageSegment& s : segments)
        for (std::size_t i = 0; i < s.bytes.size() && s.address + i <= 0xFFFF; ++i) {
            mem[s.address + i] = s.bytes[i];
            present.set(s.address + i);
        }
    const unsigned lo = options.from.value_or(0);
    const unsigned hi = options.to.value_or(0xFFFF);
    auto inside = [&](unsigned a) { return a >= lo && a <= hi && present.test(a); };

    DisasmResult out;
    asm85::DisasmOptions dopt;
    dopt.cpu8080 = options.variant == Variant::I8080;
    if (options.symbols) {
        dopt.symbol = [&](std::uint16_t a) {
            auto name = options.symbols->name_at(a);
            if (name) out.names_used.insert(*name);
            return name;
        };
        dopt.data_symbol = [&](std::uint16_t v) {
            auto name = options.symbols->data_name_at(v);
            if (name) out.names_used.insert(*name);
            return name;
        };
    }
    const auto read = [&](std::uint16_t a) { return mem[a]; };

    for (unsigned a = lo; a <= hi;) {
        if (!inside(a)) {
            ++a;
            continue;
        }
        if (a == lo || !inside(a - 1)) out.blocks.push_back({static_cast<std::uint16_t>(a), {}});
        DisasmLine line;
        line.address = static_cast<std::uint16_t>(a);
        if (options.symbols)
            if (auto l = options.symbols->label_at(line.address)) line.label = *l;
        // Decode first without names, so a split instruction does not count the names it would use.
        const asm85::Disassembly plain = asm85::disassemble(read, line.address, {.symbol = {}, .cpu8080 = dopt.cpu8080, .data_symbol = {}});
        // The first byte is in range; the operands may follow `to` (an instruction is not split there).
        unsigned n = 1;
        while (n < plain.length && a + n <= 0xFFFF && present.test(a + n)) ++n;
        // A label inside the instruction marks where code (or data) really starts: stop there.
        if (options.symbols)
            for (unsigned i = 1; i < n; ++i)
                if (options.symbols->label_at(static_cast<std::uint16_t>(a + i))) {
                    n = i;
                    break;
                }
        if (n == plain.length) {
            line.text = asm85::disassemble(read, line.address, dopt).text;
        } else {  // the operand bytes are not in this block, or a label cuts it: keep them as data
            line.text = "DB ";
            for (unsigned i = 0; i < n; ++i) line.text += (i ? "," : "") + asm85::hex_operand(mem[a + i], 2);
        }
        line.bytes.assign(mem.begin() + a, mem.begin() + a + n);
        out.bytes += n;
        out.blocks.back().lines.push_back(std::move(line));
        a += n;
    }
    return out;
}

}  // namespace

std::string format_listing(const DisasmResult& result) {
    std::string s;
    for (std::size_t b = 0; b < result.blocks.size(); ++b) {
        if (b) s += '\n';
        for (const DisasmLine& l : result.blocks[b].lines) {
            if (!l.label.empty()) s += l.label + ":\n";
            std::string hex;
            for (std::uint8_t v : l.bytes) hex += fmt::format("{}{:02X}", hex.empty() ? "" : " ", v);
            s += fmt::format("{:04X}  {:<9}  {}\n", l.address, hex, l.text);
        }
    }
    return s;
}

std::string format_source(const DisasmResult& result, const ImageDisasmOptions& options, const std::string& origin) {
    std::set<std::string> placed;
    for (const DisasmBlock& b : result.blocks)
        for (const DisasmLine& l : b.lines)
            if (!l.label.empty()) placed.insert(l.label);

    std::string s = fmt::format("; Disassembled by alp85 disasm from {}\n", origin);
    s += options.variant == Variant::I8080
             ? "; as an 8080 decodes it. Assemble with: asm85 --cpu 8080 FILE\n"
             : "; as an 8085 decodes it. Assemble with: asm85 --cpu 8085u FILE (undocumented opcodes)\n";
    bool equ = false;
    for (const std::string& name : result.names_used) {
        if (placed.count(name) || !options.symbols) continue;
        if (const auto v = options.symbols->value_of(name)) {
            if (!equ) s += '\n';
            equ = true;
            s += fmt::format("{:<15} EQU {}\n", name, asm85::hex_operand(*v, 4));
        }
    }
    for (const DisasmBlock& b : result.blocks) {
        s += fmt::format("\n                ORG {}\n", asm85::hex_operand(b.start, 4));
        for (const DisasmLine& l : b.lines) {
            if (!l.label.empty()) s += l.label + ":\n";
            s += fmt::format("                {:<24}; {:04X}\n", l.text, l.address);
        }
    }
    const std::string* start = nullptr;  // the first line's label: where a reader starts
    if (!result.blocks.empty() && !result.blocks.front().lines.empty() && !result.blocks.front().lines.front().label.empty())
        start = &result.blocks.front().lines.front().label;
    s += start ? fmt::format("\n                END {}\n", *start) : "\n                END\n";
    return s;
}

}  // namespace alp85
