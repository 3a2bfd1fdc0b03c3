// The Pisa interpolator's assembler: labels, EQU, ORG, END and the mnemonics of pisa_isa.h, in
// passes until the symbols settle, on asm85's tokenizer and expressions.
#include "asm/pisa_asm.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include <fmt/format.h>

#include "asm/assembler.h"
#include "asm/expr.h"
#include "asm/lexer.h"
#include "asm/pisa_isa.h"

namespace alp85::pisa_asm {
namespace {

using asm85::Diagnostic;
using asm85::Severity;
using asm85::Tok;
using asm85::Token;
using pisa::Form;
using pisa::Op;

struct Sym {
    std::uint16_t value = 0;
    asm85::SymbolKind kind = asm85::SymbolKind::Label;
    int line = 0;
    int pass = 0;
};

class Assembler {
public:
    Assembler(const Options& o, std::string name, std::vector<std::string> lines)
        : opt_(o), name_(std::move(name)), lines_(std::move(lines)) {}

    Result run();

private:
    void pass(int n, bool final);
    void statement(const std::vector<Token>& t);
    void instruction(const pisa::Mnemonic& m, const std::vector<Token>& t, std::size_t p);
    bool value(const std::vector<Token>& t, std::size_t& p, int lo, int hi, const char* what, int& out);
    bool comma(const std::vector<Token>& t, std::size_t& p);
    void define(const std::string& name, int col, std::uint16_t v, asm85::SymbolKind k);
    void error(int col, std::string msg);
    void emit(std::uint32_t word);

    Options opt_;
    std::string name_;
    std::vector<std::string> lines_;
    std::unordered_map<std::string, Sym> syms_;
    int pass_ = 0;
    bool final_ = false;
    bool changed_ = false;
    int pc_ = 0;
    int line_ = 0;
    const std::string* text_ = nullptr;
    bool ended_ = false;
    Result r_;
    std::map<int, std::uint32_t> words_;
    asm85::ListingLine* listing_ = nullptr;
};

void Assembler::error(int col, std::string msg) {
    if (!final_) return;
    Diagnostic d;
    d.severity = Severity::Error;
    d.file = name_;
    d.line = line_;
    d.col = col + 1;
    d.message = std::move(msg);
    d.source_line = text_ ? *text_ : std::string();
    r_.out.diagnostics.push_back(std::move(d));
}

void Assembler::define(const std::string& name, int col, std::uint16_t v, asm85::SymbolKind k) {
    auto it = syms_.find(name);
    if (it != syms_.end() && it->second.pass == pass_) {
        error(col, fmt::format("'{}' is already defined (line {})", name, it->second.line));
        return;
    }
    if (it != syms_.end() && it->second.value != v) changed_ = true;
    if (it == syms_.end()) changed_ = true;
    syms_[name] = {v, k, line_, pass_};
}

void Assembler::emit(std::uint32_t w) {
    if (pc_ >= pisa::kRomMax) {
        error(0, fmt::format("ROM address {} is beyond the largest ROM (4096 words)", pc_));
        ++pc_;
        return;
    }
    if (final_) {
        if (words_.count(pc_)) error(0, fmt::format("ROM word {} is assembled twice (ORG)", pc_));
        words_[pc_] = w;
        r_.out.line_map.push_back({static_cast<std::uint16_t>(pc_), 1, 0, line_});
        if (listing_) {
            listing_->address = static_cast<std::uint16_t>(pc_);
            listing_->bytes = {static_cast<std::uint8_t>(w >> 16), static_cast<std::uint8_t>(w >> 8),
                               static_cast<std::uint8_t>(w)};
        }
    }
    ++pc_;
}

bool Assembler::comma(const std::vector<Token>& t, std::size_t& p) {
    if (t[p].kind == Tok::Punct && t[p].punct == ',') {
        ++p;
        return true;
    }
    error(t[p].col, t[p].kind == Tok::End ? "missing operand" : "expected ','");
    return false;
}

bool Assembler::value(const std::vector<Token>& t, std::size_t& p, int lo, int hi, const char* what, int& out) {
    if (t[p].kind == Tok::End || (t[p].kind == Tok::Punct && t[p].punct == ',')) {
        error(t[p].col, fmt::format("missing {}", what));
        return false;
    }
    int col = t[p].col;
    asm85::ExprContext ctx;
    bool unknown_reported = false;
    ctx.lookup = [&](const Token& tok) -> asm85::Value {
        auto it = syms_.find(tok.text);
        if (it != syms_.end()) return {it->second.value, true};
        if (final_ && !unknown_reported) {
            error(tok.col, fmt::format("undefined symbol '{}'", tok.text));
            unknown_reported = true;
        }
        return {0, false};
    };
    ctx.error = [&](int c, const std::string& m) { error(c, m); };
    ctx.pc = static_cast<std::uint16_t>(pc_);
    ctx.is_mnemonic = [](const std::string&) { return false; };
    asm85::Value v;
    if (!asm85::eval_expr(t, p, ctx, v)) return false;
    if (!v.known) return false;
    int n = static_cast<std::int16_t>(v.v);  // 16-bit arithmetic: 0FFFFH is -1
    if (n < lo || n > hi) {
        error(col, fmt::format("{} {} is outside {}..{}", what, n, lo, hi));
        return false;
    }
    out = n;
    return true;
}

void Assembler::instruction(const pisa::Mnemonic& m, const std::vector<Token>& t, std::size_t p) {
    int a = 0, b = 0, c = 0, f = 0;
    bool ok = true;
    auto rwm = [&](int& v) { return value(t, p, 0, 63, "RWM address", v); };
    auto rom = [&](int& v) { return value(t, p, 0, pisa::kRomMax - 1, "ROM address", v); };
    std::uint32_t w = 0;
    switch (m.form) {
        case Form::Three:
            ok = rwm(a) && comma(t, p) && rwm(b) && comma(t, p) && rwm(c);
            w = pisa::pack(m.op, static_cast<unsigned>(a), static_cast<unsigned>(b), static_cast<unsigned>(c));
            break;
        case Form::Two:
            ok = rwm(a) && comma(t, p) && rwm(c);
            w = pisa::pack(m.op, static_cast<unsigned>(a), 0, static_cast<unsigned>(c));
            break;
        case Form::Shift:
            ok = rwm(a) && comma(t, p) && value(t, p, 0, 8, "shift", b) && comma(t, p) && rwm(c);
            w = pisa::pack(m.op, static_cast<unsigned>(a), static_cast<unsigned>(b) | m.fixed, static_cast<unsigned>(c));
            break;
        case Form::Store: {
            bool raw = t[p].kind == Tok::Punct && t[p].punct == '#';
            if (raw) {
                ++p;
                ok = value(t, p, 0, 4095, "12-bit configuration", f);
            } else {
                int k = 0;
                ok = value(t, p, 0, 999, "constant", k);
                // Three decimal digits in excess-three: the cells as the RWM holds them.
                f = ((k / 100 + 3) << 8) | ((k / 10 % 10 + 3) << 4) | (k % 10 + 3);
            }
            ok = ok && comma(t, p) && rwm(a);
            w = pisa::pack_f(m.op, static_cast<unsigned>(a), static_cast<unsigned>(f));
            break;
        }
        case Form::Jump:
            ok = rom(f);
            w = pisa::pack_f(m.op, 0, static_cast<unsigned>(f));
            break;
        case Form::Indir:
            ok = rwm(a);
            w = pisa::pack_f(m.op, static_cast<unsigned>(a), 0);
            break;
        case Form::Cond:
            ok = rom(f) && comma(t, p) &&
                 (m.op == Op::TRS ? value(t, p, 0, 63, "indicator", a) : rwm(a));
            w = pisa::pack_f(m.op, static_cast<unsigned>(a), static_cast<unsigned>(f));
            break;
        case Form::Ind:
            ok = value(t, p, 0, 63, "indicator", a);
            w = pisa::pack(m.op, static_cast<unsigned>(a), 0, m.fixed);
            break;
        case Form::Io:
            ok = value(t, p, 0, 63, "channel", b) && comma(t, p) && value(t, p, 1, 8, "digit count", c) &&
                 comma(t, p) && rwm(a);
            w = pisa::pack(m.op, static_cast<unsigned>(a), static_cast<unsigned>(b), static_cast<unsigned>(c));
            break;
    }
    if (ok && t[p].kind != Tok::End) error(t[p].col, fmt::format("unexpected '{}' after the operands", t[p].kind == Tok::Punct ? std::string(1, t[p].punct) : t[p].text));
    emit(w);
}

void Assembler::statement(const std::vector<Token>& t) {
    std::size_t p = 0;
    std::string label;
    int label_col = 0;
    auto is_op = [](const std::string& s) {
        return pisa::find_mnemonic(s).has_value() || s == "EQU" || s == "ORG" || s == "END";
    };
    if (t[0].kind == Tok::Ident && ((t[1].kind == Tok::Punct && t[1].punct == ':') || (t[0].col == 0 && !is_op(t[0].text)) ||
                                    (t[1].kind == Tok::Ident && t[1].text == "EQU"))) {
        label = t[0].text;
        label_col = t[0].col;
        p = 1;
        if (t[1].kind == Tok::Punct && t[1].punct == ':') p = 2;
    }
    if (t[p].kind == Tok::End) {
        if (!label.empty()) define(label, label_col, static_cast<std::uint16_t>(pc_), asm85::SymbolKind::Label);
        if (listing_ && !label.empty()) listing_->address = static_cast<std::uint16_t>(pc_);
        return;
    }
    if (t[p].kind != Tok::Ident) {
        error(t[p].col, "expected an operation");
        return;
    }
    std::string op = t[p].text;
    int op_col = t[p].col;
    ++p;
    if (op == "EQU") {
        if (label.empty()) {
            error(op_col, "EQU needs a name");
            return;
        }
        int v = 0;
        if (value(t, p, -32768, 65535, "value", v)) {
            define(label, label_col, static_cast<std::uint16_t>(v), asm85::SymbolKind::Equ);
            if (listing_) listing_->value = static_cast<std::uint16_t>(v);
        } else if (!final_) {
            changed_ = true;  // a forward reference: another pass
        }
        return;
    }
    if (!label.empty()) define(label, label_col, static_cast<std::uint16_t>(pc_), asm85::SymbolKind::Label);
    if (op == "ORG") {
        int v = 0;
        if (value(t, p, 0, pisa::kRomMax - 1, "ROM address", v)) pc_ = v;
        if (listing_) listing_->address = static_cast<std::uint16_t>(pc_);
        return;
    }
    if (op == "END") {
        ended_ = true;
        return;
    }
    auto m = pisa::find_mnemonic(op);
    if (!m) {
        error(op_col, fmt::format("unknown operation '{}'", op));
        return;
    }
    instruction(*m, t, p);
}

void Assembler::pass(int n, bool final) {
    pass_ = n;
    final_ = final;
    changed_ = false;
    pc_ = 0;
    ended_ = false;
    for (std::size_t i = 0; i < lines_.size() && !ended_; ++i) {
        line_ = static_cast<int>(i) + 1;
        text_ = &lines_[i];
        listing_ = nullptr;
        if (final_) {
            r_.out.listing.push_back({});
            listing_ = &r_.out.listing.back();
            listing_->file = 0;
            listing_->line = line_;
            listing_->text = lines_[i];
        }
        asm85::LexError le;
        auto toks = asm85::tokenize(lines_[i], le, 10);
        if (!le.message.empty()) {
            error(le.col, le.message);
            continue;
        }
        if (toks.size() < 2) continue;  // only the End token: blank or comment
        toks.push_back(toks.back());    // room to look one token past the end
        statement(toks);
    }
}

Result Assembler::run() {
    r_.out.files = {name_};
    // Command-line defines first, as asm85 does.
    // A NAME that is not a name, or a VALUE that is not one whole expression, is an error (the
    // command line reports it as a usage error).
    for (auto& [k, v] : opt_.defines) {
        asm85::LexError le;
        auto toks = asm85::tokenize(v.empty() ? "1" : v, le, 10);
        std::size_t p = 0;
        int n = 0;
        text_ = nullptr;
        final_ = true;
        if (k.empty() || !asm85::is_name_start(k[0]) || !std::all_of(k.begin(), k.end(), asm85::is_name_char)) {
            error(-1, fmt::format("-D: '{}' is not a valid name", k));
            continue;
        }
        if (!le.message.empty()) {
            error(-1, fmt::format("-D {}: {}", k, le.message));
            continue;
        }
        const std::size_t reported = r_.out.diagnostics.size();
        if (!value(toks, p, -32768, 65535, "value", n)) {
            if (r_.out.diagnostics.size() == reported) error(-1, fmt::format("-D {}: '{}' is not a value", k, v));
            continue;
        }
        if (toks[p].kind != Tok::End) {
            error(-1, fmt::format("-D {}: unexpected text after the value", k));
            continue;
        }
        syms_[asm85::to_upper(k)] = {static_cast<std::uint16_t>(n), asm85::SymbolKind::Define, 0, -1};
    }
    int n = 1;
    for (; n <= 8; ++n) {
        pass(n, false);
        if (!changed_ && n >= 2) break;
    }
    r_.out.listing.clear();
    pass(n + 1, true);
    r_.out.passes = n + 1;
    for (auto& [name, s] : syms_)
        r_.out.symbols.push_back({name, s.value, s.kind, s.kind == asm85::SymbolKind::Define ? -1 : 0, s.line});
    std::sort(r_.out.symbols.begin(), r_.out.symbols.end(), [](auto& a, auto& b) { return a.name < b.name; });
    if (!words_.empty()) {
        r_.rom.assign(static_cast<std::size_t>(words_.rbegin()->first) + 1, 0);
        for (auto& [a, w] : words_) {
            r_.rom[static_cast<std::size_t>(a)] = w;
            for (int k = 0; k < 3; ++k)
                r_.out.image.write(static_cast<std::uint16_t>(3 * a + k), static_cast<std::uint8_t>(w >> (16 - 8 * k)));
        }
    }
    return std::move(r_);
}

}  // namespace

Result assemble_string(std::string_view source, const Options& options, std::string_view name) {
    return Assembler(options, std::string(name), asm85::split_lines(source)).run();
}

Result assemble_file(const std::filesystem::path& path, const Options& options) {
    auto reader = options.read_file ? options.read_file : asm85::read_disk_file;
    auto text = reader(path);
    if (!text) {
        Result r;
        r.out.files = {path.string()};
        r.out.diagnostics.push_back({Severity::Error, path.string(), 0, 0, "cannot read the source file", ""});
        return r;
    }
    return assemble_string(*text, options, path.string());
}

asm85::OutputFormat output_format() {
    return {"pisa-asm  MULTI-PURPOSE INTERPOLATOR (CNR-IEI PISA, 1969)", 3, 3, "word22"};
}

std::string write_rom_text(const Result& r) {
    std::string out;
    for (std::size_t a = 0; a < r.rom.size(); ++a) out += fmt::format("{:04d} {:08o}\n", a, r.rom[a]);
    return out;
}

}  // namespace alp85::pisa_asm
