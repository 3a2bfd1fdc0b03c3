// Directives: location (ORG, DS, END, .PHASE), symbols (EQU, SET, =), data (DB, DW), files
// (INCLUDE, MACLIB), checks (ERROR, .ERRxx) and the listing/segment directives of ASM80 and M80
// that change no byte. Conditionals are in conditionals.cpp, macros in macros.cpp.
#include <algorithm>
#include <unordered_set>

#include <fmt/format.h>

#include "asm/assembler.h"

namespace alp85::asm85 {
namespace {

// Accepted and ignored: they steer listings, relocation or linking, not absolute bytes.
const std::unordered_set<std::string>& no_effect_words() {
    static const std::unordered_set<std::string> s{
        "PAGE", "EJECT", "NAME", "SPACE", "LIST", "NOLIST", "SUBTTL", ".LIST", ".XLIST", ".SALL", ".LALL",
        ".XALL", ".SFCOND", ".LFCOND", ".TFCOND", ".CREF", ".XCREF", ".8080", ".8085", "ASEG", "CSEG", "DSEG",
        "PUBLIC", "EXTRN", "EXT", "EXTERNAL", "ENTRY", "GLOBAL", ".REQUEST", "STKLN", ".PRINTX", "PRINTX",
        "IDENT", "FORM", "PRINT", "$TITLE", "EXTERN"};
    return s;
}

const std::unordered_set<std::string>& directive_words() {
    static const std::unordered_set<std::string> s{
        "ORG", "EQU", "SET", "DEFL", "DB", "DEFB", "DEFM", "DC", "DW", "DEFW", "DS", "DEFS", "END", "MACRO",
        "ENDM", "LOCAL", "REPT", "IRP", "IRPC", "EXITM", "INCLUDE", "MACLIB", "ERROR", ".ERROR", ".ERR",
        ".ERRE", ".ERRNZ", ".ERRDEF", ".ERRNDEF", ".ERR1", ".ERR2", "CPU", "TITLE", ".RADIX", ".COMMENT",
        ".PHASE", ".DEPHASE", ".Z80", "="};
    return s;
}

}  // namespace

bool is_directive_word(const std::string& w) { return directive_words().count(w) || no_effect_words().count(w); }


void Assembler::do_include(const std::string& raw, int col) {
    std::string name = trim(raw);
    if (name.size() >= 2 && (name.front() == '\'' || name.front() == '"') && name.back() == name.front())
        name = name.substr(1, name.size() - 2);
    if (name.empty()) {
        error(col, "missing file name");
        return;
    }
    int depth = 0;
    for (auto& f : frames_)
        if (f.kind == FrameKind::File) ++depth;
    if (depth >= 32) {
        error(col, "INCLUDE nested more than 32 deep");
        return;
    }
    auto path = find_include(name);
    int idx = path ? load_file(*path, path->string()) : -1;
    if (idx < 0) {
        error(col, "cannot open include file '" + name + "'");
        return;
    }
    Frame f;
    f.kind = FrameKind::File;
    f.file = idx;
    frames_.push_back(std::move(f));
}

void Assembler::data_bytes(const std::vector<Token>& toks, std::size_t p, bool high_bit_last) {
    if (toks[p].kind == Tok::End) {
        error(toks[p].col, "missing data");
        return;
    }
    for (;;) {
        const Token& t = toks[p];
        const Token& after = toks[p + 1];
        bool last = false;
        if (t.kind == Tok::String && (after.kind == Tok::End || (after.kind == Tok::Punct && after.punct == ','))) {
            for (std::size_t i = 0; i < t.text.size(); ++i) {
                auto b = static_cast<std::uint8_t>(t.text[i]);
                if (high_bit_last && i + 1 == t.text.size() && after.kind == Tok::End) b |= 0x80;
                emit(b);
            }
            ++p;
        } else {
            Value v;
            if (!expr(toks, p, v)) return;
            emit(byte_of(v, t.col));
        }
        if (toks[p].kind == Tok::End) return;
        last = toks[p + 1].kind == Tok::End;
        if (last) {
            error(toks[p].col, "missing value after ','");
            return;
        }
        ++p;  // the comma
    }
}

bool Assembler::try_directive(const std::string& op, const std::vector<Token>& toks, std::size_t p,
                              const std::string& name, int name_col, const Line& line) {
    if (!directive_words().count(op)) return no_effect_words().count(op) != 0;
    const int opcol = toks[p - 1].col;
    const std::uint16_t here = loc();
    auto raw_operand = [&]() -> std::string {
        int from = toks[p].col;
        int to = toks.back().col;
        if (to <= from) return "";
        return line.text.substr(static_cast<std::size_t>(from), static_cast<std::size_t>(to - from));
    };

    if (op == "EQU" || op == "SET" || op == "DEFL" || op == "=") {
        Value v;
        std::vector<std::string> refs;
        refs_ = &refs;
        const bool ok = expr_all(toks, p, v);
        refs_ = nullptr;
        if (!ok) return true;
        define(name, name_col, v.v, op == "EQU" ? SymbolKind::Equ : SymbolKind::Set, v.known, std::move(refs));
        listing_.back().value = v.v;
        return true;
    }
    if (op == "MACRO") {
        begin_collect(Collect::Macro, toks, p, name, line);
        return true;
    }
    if (op == "REPT" || op == "IRP" || op == "IRPC") {
        begin_collect(op == "REPT" ? Collect::Rept : op == "IRP" ? Collect::Irp : Collect::Irpc, toks, p, name, line);
        return true;
    }
    if (op == "ORG") {
        Value v;
        if (!expr_all(toks, p, v)) return true;
        pc_ = v.v;
        phase_ = 0;
        overlap_reported_ = false;
        pc_overflow_reported_ = false;
        listing_.back().address = v.v;
        return true;
    }
    if (op == "DB" || op == "DEFB" || op == "DEFM" || op == "DC") {
        if (!listing_.back().address) listing_.back().address = here;
        data_bytes(toks, p, op == "DC");
        return true;
    }
    if (op == "DW" || op == "DEFW") {
        if (toks[p].kind == Tok::End) {
            error(toks[p].col, "missing data");
            return true;
        }
        for (;;) {
            Value v;
            if (!expr(toks, p, v)) return true;
            emit_word(v.v);
            if (toks[p].kind == Tok::End) return true;
            ++p;
        }
    }
    if (op == "DS" || op == "DEFS") {
        Value n;
        if (!expr(toks, p, n)) return true;
        listing_.back().address = here;
        if (toks[p].kind == Tok::End) {
            pc_ += n.v;  // reserved, not written: the output stays sparse
            return true;
        }
        ++p;
        int col = toks[p].col;
        Value fill;
        if (!expr_all(toks, p, fill)) return true;
        std::uint8_t b = byte_of(fill, col);
        for (std::uint32_t i = 0; i < n.v && !ended_; ++i) emit(b);
        return true;
    }
    if (op == "END") {
        if (toks[p].kind != Tok::End) {
            Value v;
            if (expr_all(toks, p, v)) {
                image_.start_address = v.v;
                listing_.back().value = v.v;
            }
        }
        ended_ = true;
        return true;
    }
    if (op == "INCLUDE" || op == "MACLIB") {
        std::string fname = raw_operand();
        if (toks[p].kind == Tok::String) fname = toks[p].text;
        fname = trim(fname);
        if (op == "MACLIB" && fname.find('.') == std::string::npos) fname += ".LIB";
        do_include(fname, toks[p].col);
        return true;
    }
    if (op == "ENDM") {
        error(opcol, "ENDM without MACRO, REPT, IRP or IRPC");
        return true;
    }
    if (op == "EXITM") {
        exitm();
        return true;
    }
    if (op == "LOCAL") {
        add_locals(toks, p);
        return true;
    }
    if (op == "ERROR" || op == ".ERROR" || op == ".ERR") {
        std::string msg = toks[p].kind == Tok::String && toks[p + 1].kind == Tok::End ? toks[p].text : trim(raw_operand());
        error(opcol, msg.empty() ? "ERROR directive" : msg);
        return true;
    }
    if (op == ".ERRE" || op == ".ERRNZ") {
        Value v;
        if (!expr_all(toks, p, v)) return true;
        if ((op == ".ERRE") == (v.v == 0) && v.known) error(opcol, fmt::format("{} failed: value is {:04X}H", op, v.v));
        return true;
    }
    if (op == ".ERRDEF" || op == ".ERRNDEF") {
        bool def = toks[p].kind == Tok::Ident && syms_.count(key(toks[p].text)) && syms_.at(key(toks[p].text)).pass == pass_;
        if ((op == ".ERRDEF") == def) error(opcol, op + " failed for '" + toks[p].text + "'");
        return true;
    }
    if (op == ".ERR1" || op == ".ERR2") {
        if (op == ".ERR2") error(opcol, ".ERR2 directive");
        return true;
    }
    if (op == "CPU") {
        std::string v = to_upper(trim(raw_operand()));
        if (toks[p].kind == Tok::String) v = to_upper(toks[p].text);
        if (auto c = parse_cpu(v)) cpu_ = *c;
        else error(toks[p].col, "CPU must be 8080, 8085 or 8085U");
        return true;
    }
    if (op == "TITLE") {
        title_ = toks[p].kind == Tok::String ? toks[p].text : trim(raw_operand());
        return true;
    }
    if (op == ".RADIX") {
        LexError le;
        // The argument is always decimal.
        std::uint32_t r = 0;
        if (toks[p].kind != Tok::Number || !parse_number(toks[p].text + "D", 10, r) || r < 2 || r > 16) {
            error(toks[p].col, ".RADIX must be 2 to 16");
            return true;
        }
        radix_ = static_cast<int>(r);
        return true;
    }
    if (op == ".COMMENT") {
        std::string rest = trim(raw_operand());
        if (rest.empty()) {
            error(opcol, ".COMMENT needs a delimiter character");
            return true;
        }
        // The block ends at the next line holding the delimiter (this line may already).
        if (rest.find(rest[0], 1) == std::string::npos) comment_delim_ = std::string(1, rest[0]);
        return true;
    }
    if (op == ".PHASE") {  // assemble for another run address; bytes still go to pc_
        Value v;
        if (!expr_all(toks, p, v)) return true;
        phase_ = static_cast<std::int32_t>(v.v) - static_cast<std::int32_t>(pc_);
        listing_.back().value = v.v;
        return true;
    }
    if (op == ".DEPHASE") {
        phase_ = 0;
        return true;
    }
    if (op == ".Z80") {
        error(opcol, "Z80 mnemonics are not supported (asm85 is an 8080/8085 assembler)");
        return true;
    }
    return no_effect_words().count(op) != 0;
}

}  // namespace alp85::asm85
