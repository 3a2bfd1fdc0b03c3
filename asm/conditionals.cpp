// Conditional assembly: IF and its M80 relatives, ELSE, ENDIF/ENDC, nested to 1000 levels.
// An expression is true when non-zero (CP/M ASM manual 3.4); IF1 is true only in the first pass.
// Inside a macro or repeat expansion, ELSE and ENDIF reach only the IFs opened in it (ASM80).
#include <unordered_set>

#include <fmt/format.h>

#include "asm/assembler.h"

namespace alp85::asm85 {

bool is_conditional_word(const std::string& w) {
    static const std::unordered_set<std::string> s{"IF", "IFE", "IFT", "IFF", "IFDEF", "IFNDEF", "IFB", "IFNB",
                                                   "IFIDN", "IFDIF", "IF1", "IF2", "COND", "ELSE", "ENDIF", "ENDC"};
    return s.count(w) != 0;
}

void Assembler::conditional(const std::string& op, const std::vector<Token>& toks, std::size_t p, const Line& line) {
    const int opcol = toks[p - 1].col;
    // The IFs below this level were opened outside the innermost macro or repeat expansion.
    std::size_t floor = 0;
    const Frame* expansion = nullptr;
    for (auto it = frames_.rbegin(); it != frames_.rend(); ++it)
        if (it->kind != FrameKind::File && it->cond_scope) {
            floor = it->cond_depth;
            expansion = &*it;
            break;
        }
    if ((op == "ELSE" || op == "ENDIF" || op == "ENDC") && !cond_.empty() && cond_.size() <= floor) {
        error(opcol, op + " without IF in the expansion of " + expansion->name +
                         " (an IF opened outside a macro or repeat block must end outside it)");
        return;
    }
    if (op == "ELSE") {
        if (cond_.empty()) {
            error(opcol, "ELSE without IF");
            return;
        }
        Cond& c = cond_.back();
        if (c.in_else) {
            error(opcol, "second ELSE for one IF");
            return;
        }
        c.in_else = true;
        c.active = c.parent_active && !c.taken;
        c.taken = c.taken || c.active;
        return;
    }
    if (op == "ENDIF" || op == "ENDC") {
        if (cond_.empty()) {
            error(opcol, op + " without IF");
            return;
        }
        cond_.pop_back();
        return;
    }
    Cond c;
    c.parent_active = !skipping();
    c.file = line.file;
    c.line = line.line;
    c.col = opcol + 1;
    if (cond_.size() >= 1000) {
        error(opcol, "IF nested more than 1000 deep");
        return;
    }
    bool truth = false;
    if (c.parent_active) {
        auto raw = [&]() -> std::string {
            int from = toks[p].col, to = toks.back().col;
            return to > from ? line.text.substr(static_cast<std::size_t>(from), static_cast<std::size_t>(to - from)) : "";
        };
        if (op == "IF" || op == "IFT" || op == "IFE" || op == "IFF" || op == "COND") {
            Value v;
            if (expr_all(toks, p, v)) truth = v.v != 0;
            // Intel's ASM80 tests bit 0 of an IF's value, M80 and DR ASM any bit: the two agree on
            // 0, relations (0FFFFH) and odd values, and part only on an even non-zero value.
            if (op == "IF" && truth && v.known && (v.v & 1) == 0)
                warning(toks[p].col, fmt::format("IF value {:04X}H is even: true here (non-zero), but false to Intel's "
                                                 "ASM80, which tests only bit 0",
                                                 v.v));
            if (op == "IFE" || op == "IFF") truth = !truth;
        } else if (op == "IFDEF" || op == "IFNDEF") {
            if (toks[p].kind != Tok::Ident) {
                error(toks[p].col, op + " needs a symbol name");
            } else {
                auto it = syms_.find(key(toks[p].text));
                bool def = (it != syms_.end() && it->second.pass == pass_) || macros_.count(toks[p].text);
                truth = (op == "IFDEF") == def;
            }
        } else if (op == "IFB" || op == "IFNB") {
            truth = (op == "IFB") == strip_angle(raw()).empty();
        } else if (op == "IFIDN" || op == "IFDIF") {
            auto parts = split_args(raw());
            if (parts.size() != 2) error(toks[p].col, op + " needs two arguments");
            else truth = (op == "IFIDN") == (parts[0] == parts[1]);
        } else if (op == "IF1") {
            truth = pass_ == 1;
        } else if (op == "IF2") {
            truth = pass_ > 1;
        }
    }
    c.active = c.parent_active && truth;
    c.taken = c.active || !c.parent_active;
    cond_.push_back(c);
}

}  // namespace alp85::asm85
