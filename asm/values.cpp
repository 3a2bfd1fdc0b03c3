// Values and bytes: diagnostics, symbol lookup and definition, expressions, emission.
#include <fmt/format.h>

#include "asm/assembler.h"
#include "asm/instructions.h"

namespace alp85::asm85 {
namespace {

constexpr int kMaxErrors = 1000;

}  // namespace

bool is_register_name(const std::string& n, int* value) {
    static const std::unordered_map<std::string, int> kRegs{
        {"B", 0}, {"C", 1}, {"D", 2}, {"E", 3}, {"H", 4}, {"L", 5},
        {"M", 6}, {"A", 7}, {"SP", 6}, {"PSW", 6}};
    auto it = kRegs.find(n);
    if (it == kRegs.end()) return false;
    if (value) *value = it->second;
    return true;
}


void Assembler::diag(Severity s, int col, const std::string& msg) {
    if (limit_reported_) return;
    if (s == Severity::Error && ++errors_this_pass_ > kMaxErrors) {
        diags_.push_back({Severity::Error, "", 0, 0, "too many errors; assembly stopped", ""});
        limit_reported_ = true;
        ended_ = true;
        return;
    }
    Diagnostic d;
    d.severity = s;
    d.message = msg;
    if (cur_line_ && cur_line_->file >= 0) {
        d.file = files_[static_cast<std::size_t>(cur_line_->file)].name;
        d.line = cur_line_->line;
        d.col = col + 1;
        d.source_line = cur_line_->text;
    }
    diags_.push_back(std::move(d));
    if (cur_line_ && cur_line_->depth > 0 && cur_line_->site_file >= 0) {
        const SourceFile& sf = files_[static_cast<std::size_t>(cur_line_->site_file)];
        Diagnostic n;
        n.severity = Severity::Note;
        n.file = sf.name;
        n.line = cur_line_->site_line;
        n.message = "in the expansion invoked here";
        if (cur_line_->site_line >= 1 && static_cast<std::size_t>(cur_line_->site_line) <= sf.lines.size())
            n.source_line = sf.lines[static_cast<std::size_t>(cur_line_->site_line - 1)];
        diags_.push_back(std::move(n));
    }
}

Value Assembler::lookup(const Token& t, bool registers) {
    // As in ASM80 and DR ASM, register names are predefined symbols (B=0 ... A=7, SP=PSW=6) in
    // every expression: `UR EQU B` then `MOV UR,A` is period practice.
    (void)registers;
    int rv = 0;
    if (is_register_name(t.text, &rv)) return {static_cast<std::uint16_t>(rv), true};
    auto it = syms_.find(key(t.text));
    if (it != syms_.end() && it->second.pass >= pass_ - 1) return {it->second.value, true};
    if (pass_ > 1) {
        error(t.col, "undefined symbol '" + t.text + "'");
    }
    return {0, false};
}

bool Assembler::expr(const std::vector<Token>& toks, std::size_t& pos, Value& out, bool registers) {
    ExprContext ctx;
    ctx.pc = loc();
    ctx.lookup = [this, registers](const Token& t) { return lookup(t, registers); };
    ctx.error = [this](int col, const std::string& m) { error(col, m); };
    ctx.is_mnemonic = [this](const std::string& w) { return find_mnemonic(w) != nullptr && syms_.count(w) == 0; };
    ctx.instruction = [this, &toks](std::size_t first, std::size_t last) { return instruction_value(toks, first, last); };
    return eval_expr(toks, pos, ctx, out);
}

bool Assembler::expr_all(const std::vector<Token>& toks, std::size_t pos, Value& out) {
    if (!expr(toks, pos, out)) return false;
    if (toks[pos].kind != Tok::End) {
        error(toks[pos].col, "unexpected ',' after expression");
        return false;
    }
    return true;
}

void Assembler::define(const std::string& full_name, int col, std::uint16_t value, SymbolKind kind) {
    const std::string name = key(full_name);
    if (is_operator_word(name)) {
        error(col, "'" + name + "' is an operator and can't be a symbol");
        return;
    }
    if (is_register_name(name)) {
        error(col, "'" + name + "' is a register name and can't be a symbol");
        return;
    }
    auto [it, inserted] = syms_.try_emplace(name);
    SymEntry& e = it->second;
    int file = cur_line_ ? cur_line_->file : -1;
    int line = cur_line_ ? cur_line_->line : 0;
    if (!inserted && e.pass == pass_) {
        if (e.kind == SymbolKind::Define && kind != SymbolKind::Define) {
            if (e.value != value)
                warning(col, fmt::format("'{}' is set on the command line to {:04X}H; this definition ({:04X}H) is ignored", name, e.value, value));
            return;
        }
        if (kind == SymbolKind::Equ && e.kind == SymbolKind::Equ && e.value == value) return;  // ASM80 allows
        if (kind == SymbolKind::Set && e.kind == SymbolKind::Set) {
            e.value = value;
            e.file = file;
            e.line = line;
            return;
        }
        std::string where = e.file >= 0 ? fmt::format(" (first defined at {}:{})", files_[static_cast<std::size_t>(e.file)].name, e.line) : "";
        error(col, "'" + name + "' is already defined" + where);
        return;
    }
    if (inserted || e.pass < pass_ - 1) {
        if (pass_ > 1) changed_ = true;
    } else if (kind != SymbolKind::Set && e.value != value) {
        changed_ = true;
    }
    e = {value, kind, pass_, file, line};
}

std::uint8_t Assembler::byte_of(const Value& v, int col) {
    if (v.known && (v.v & 0xFF00) != 0 && (v.v & 0xFF00) != 0xFF00)
        warning(col, fmt::format("value {:04X}H truncated to byte {:02X}H", v.v, v.v & 0xFF));
    return static_cast<std::uint8_t>(v.v & 0xFF);
}

void Assembler::emit(std::uint8_t b) {
    if (pc_ > 0xFFFF) {
        if (!pc_overflow_reported_) error(op_col_, "code beyond address 0FFFFH");
        pc_overflow_reported_ = true;
        ++pc_;
        return;
    }
    auto addr = static_cast<std::uint16_t>(pc_);
    if (!image_.write(addr, b) && !overlap_reported_) {
        warning(op_col_, fmt::format("overlapping ORG regions: address {:04X}H is written twice", addr));
        overlap_reported_ = true;
    }
    if (!listing_.empty()) {
        auto& ll = listing_.back();
        if (ll.bytes.empty() && !ll.address) ll.address = loc();  // the run address under .PHASE
        ll.bytes.push_back(b);
    }
    if (cur_line_) {
        if (!line_map_.empty()) {
            LineSpan& s = line_map_.back();
            if (s.file == cur_line_->site_file && s.line == cur_line_->site_line && s.address + s.length == addr &&
                s.length < 0xFFFF) {
                ++s.length;
                ++pc_;
                return;
            }
        }
        line_map_.push_back({addr, 1, cur_line_->site_file, cur_line_->site_line});
    }
    ++pc_;
}

void Assembler::emit_word(std::uint16_t w) {
    emit(static_cast<std::uint8_t>(w & 0xFF));
    emit(static_cast<std::uint8_t>(w >> 8));
}

}  // namespace alp85::asm85
