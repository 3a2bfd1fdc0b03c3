// Instruction encoding, driven entirely by the shared opcode table.
//
// A register operand may be a register name or any expression with the register's number
// (B=0 C=1 D=2 E=3 H=4 L=5 M=6 A=7; pairs B=0 D=2 H=4 SP=PSW=6), as Intel's assembler allows.
#include "asm/instructions.h"

#include <cctype>
#include <unordered_map>

#include "asm/assembler.h"
#include "asm/isa.h"

namespace alp85::asm85 {
namespace {

const std::unordered_map<std::string, std::vector<std::uint8_t>>& index() {
    static const auto table = [] {
        std::unordered_map<std::string, std::vector<std::uint8_t>> t;
        for (int op = 0; op < 256; ++op) {
            const auto& o = isa::kOpcodes[static_cast<std::size_t>(op)];
            t[std::string(o.mnemonic)].push_back(static_cast<std::uint8_t>(op));
            if (!o.alt.empty()) t[std::string(o.alt)].push_back(static_cast<std::uint8_t>(op));
        }
        return t;
    }();
    return table;
}

// The operand slots of every opcode, split once.
const std::vector<std::string>& slots_of(std::uint8_t op) {
    static const auto table = [] {
        std::vector<std::vector<std::string>> t(256);
        for (int i = 0; i < 256; ++i) t[static_cast<std::size_t>(i)] = template_slots(isa::kOpcodes[static_cast<std::size_t>(i)].operands);
        return t;
    }();
    return table[op];
}

bool is_data_slot(const std::string& s) { return s == "d8" || s == "d16" || s == "a16" || s == "p8"; }
bool is_rst_slot(const std::string& s) { return s.size() == 1 && std::isdigit(static_cast<unsigned char>(s[0])); }

}  // namespace

const std::vector<std::uint8_t>* find_mnemonic(const std::string& upper) {
    auto& t = index();
    auto it = t.find(upper);
    return it == t.end() ? nullptr : &it->second;
}

std::vector<std::string> template_slots(std::string_view operands) {
    std::vector<std::string> out;
    if (operands.empty()) return out;
    std::size_t start = 0;
    for (;;) {
        auto comma = operands.find(',', start);
        out.emplace_back(operands.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return out;
}

bool Assembler::try_instruction(const std::string& op, const Token& optok, const std::vector<Token>& toks, std::size_t p) {
    std::vector<std::uint8_t> out;
    if (!encode_instruction(op, optok, toks, p, out)) return false;
    for (auto b : out) emit(b);
    return true;
}

// Encodes into `out` (always the instruction's full length; zeros where an operand failed).
bool Assembler::encode_instruction(const std::string& op, const Token& optok, const std::vector<Token>& toks, std::size_t p,
                                   std::vector<std::uint8_t>& out) {
    const auto* ops = find_mnemonic(op);
    if (!ops) return false;
    const isa::OpInfo& first = isa::kOpcodes[(*ops)[0]];
    const auto& slots = slots_of((*ops)[0]);

    // Operand starts at top-level commas.
    std::vector<std::size_t> starts;
    if (toks[p].kind != Tok::End) {
        starts.push_back(p);
        int depth = 0;
        for (std::size_t i = p; toks[i].kind != Tok::End; ++i) {
            if (toks[i].kind != Tok::Punct) continue;
            if (toks[i].punct == '(') ++depth;
            if (toks[i].punct == ')') --depth;
            if (toks[i].punct == ',' && depth == 0) starts.push_back(i + 1);
        }
    }
    if (starts.size() != slots.size()) {
        int col = starts.size() > slots.size() && !starts.empty() ? toks[starts[slots.size()]].col : optok.col;
        error(col, op + " takes " + std::to_string(slots.size()) + (slots.size() == 1 ? " operand" : " operands") +
                       ", not " + std::to_string(starts.size()));
        out.assign(first.length, 0);
        return true;
    }

    // Register and RST operands select the opcode; data operands follow it.
    struct Sel {
        bool named = false;
        std::string name;
        int value = -1;
    };
    std::vector<Sel> sel(slots.size());
    bool ok = true;
    for (std::size_t i = 0; i < slots.size(); ++i) {
        if (is_data_slot(slots[i])) continue;
        const Token& t = toks[starts[i]];
        const Token& after = toks[starts[i] + 1];
        bool alone = after.kind == Tok::End || (after.kind == Tok::Punct && after.punct == ',');
        int rv = 0;
        if (!is_rst_slot(slots[i]) && t.kind == Tok::Ident && alone && is_register_name(t.text, &rv)) {
            sel[i] = {true, t.text, rv};
            continue;
        }
        std::size_t pos = starts[i];
        Value v;
        if (!expr(toks, pos, v, !is_rst_slot(slots[i]))) {
            ok = false;
            continue;
        }
        if (v.v > 7) {
            error(t.col, is_rst_slot(slots[i]) ? "RST number must be 0 to 7" : "register number must be 0 to 7");
            ok = false;
            continue;
        }
        sel[i] = {false, "", v.v};
    }
    if (!ok) {
        out.assign(first.length, 0);
        return true;
    }
    int chosen = -1;
    for (auto code : *ops) {
        const auto& ts = slots_of(code);
        bool match = true;
        for (std::size_t i = 0; i < ts.size() && match; ++i) {
            if (is_data_slot(ts[i])) continue;
            int want = 0;
            if (is_rst_slot(ts[i])) {
                want = ts[i][0] - '0';
            } else {
                is_register_name(ts[i], &want);
                if (sel[i].named && sel[i].name != ts[i]) match = false;
            }
            if (want != sel[i].value) match = false;
        }
        if (match) {
            chosen = code;
            break;
        }
    }
    if (chosen < 0) {
        std::size_t bad = 0;
        for (std::size_t i = 0; i < slots.size(); ++i)
            if (!is_data_slot(slots[i])) { bad = i; break; }
        std::string shown;
        for (std::size_t i = 0; i < slots.size(); ++i)
            if (!is_data_slot(slots[i])) shown += (shown.empty() ? "" : ",") + (sel[i].named ? sel[i].name : std::to_string(sel[i].value));
        error(toks[starts[bad]].col, "invalid operand for " + op + ": " + op + " " + shown + " does not exist");
        out.assign(first.length, 0);
        return true;
    }
    const auto& info = isa::kOpcodes[static_cast<std::size_t>(chosen)];
    if (info.set == isa::Set::Only8085 && cpu_ == Cpu::i8080) {
        error(optok.col, op + " is an 8085 instruction; the 8080 (--cpu 8080) has no " + op);
    } else if (info.set == isa::Set::Undoc8085 && cpu_ != Cpu::i8085u) {
        error(optok.col, op + " is an undocumented 8085 instruction; enable it with --cpu 8085u or the directive CPU 8085U");
    }
    out.push_back(static_cast<std::uint8_t>(chosen));
    for (std::size_t i = 0; i < slots.size(); ++i) {
        if (!is_data_slot(slots[i])) continue;
        std::size_t pos = starts[i];
        Value v{0, true};
        int col = toks[pos].col;
        bool good = expr(toks, pos, v);
        if (slots[i] == "d8" || slots[i] == "p8")
            out.push_back(good ? byte_of(v, col) : 0);
        else {
            out.push_back(static_cast<std::uint8_t>(good ? v.v & 0xFF : 0));
            out.push_back(static_cast<std::uint8_t>(good ? v.v >> 8 : 0));
        }
    }
    return true;
}

Value Assembler::instruction_value(const std::vector<Token>& toks, std::size_t first, std::size_t last) {
    std::vector<Token> sub(toks.begin() + static_cast<std::ptrdiff_t>(first), toks.begin() + static_cast<std::ptrdiff_t>(last));
    Token end;
    end.kind = Tok::End;
    end.col = toks[last].col;
    sub.push_back(end);
    std::vector<std::uint8_t> bytes;
    if (insn_depth_ >= 16) {
        error(sub[0].col, "parenthesized instructions nested too deeply");
        return {0, true};
    }
    ++insn_depth_;
    encode_instruction(sub[0].text, sub[0], sub, 1, bytes);
    --insn_depth_;
    return {static_cast<std::uint16_t>(bytes.empty() ? 0 : bytes[0]), true};
}

}  // namespace alp85::asm85
