// One source line: comment and control lines, the label field, then dispatch of the operation.
#include <cctype>
#include <optional>

#include "asm/assembler.h"
#include "asm/instructions.h"

namespace alp85::asm85 {
namespace {

bool is_name_op(const std::string& w) { return w == "EQU" || w == "SET" || w == "DEFL" || w == "MACRO" || w == "="; }

bool is_block_start(const std::string& w) { return w == "MACRO" || w == "REPT" || w == "IRP" || w == "IRPC"; }

// Splits at DR ASM's '!' statement separator (not inside <...> macro argument groups).
std::vector<std::vector<Token>> split_statements(std::vector<Token>& toks) {
    std::vector<std::vector<Token>> out(1);
    int angle = 0;
    for (auto& t : toks) {
        if (t.kind == Tok::Punct && t.punct == '<') ++angle;
        if (t.kind == Tok::Punct && t.punct == '>' && angle > 0) --angle;
        if (t.kind == Tok::Punct && t.punct == '!' && angle == 0) {
            Token end;
            end.kind = Tok::End;
            end.col = t.col;
            out.back().push_back(end);
            out.emplace_back();
            continue;
        }
        out.back().push_back(std::move(t));
    }
    return out;
}

}  // namespace

bool Assembler::is_op_word(const std::string& w) const {
    return is_directive_word(w) || is_conditional_word(w) || is_name_op(w) || find_mnemonic(w) != nullptr ||
           macros_.count(w) != 0;
}

void Assembler::process_line(const Line& line) {
    ListingLine ll;
    ll.file = line.file;
    ll.line = line.line;
    ll.expansion_depth = line.depth;
    ll.text = line.text;
    ll.skipped = skipping();
    for (auto& f : frames_)
        if (f.kind == FrameKind::File) ++ll.include_depth;
    --ll.include_depth;
    listing_.push_back(std::move(ll));

    if (collect_.kind != Collect::None) {
        collect_line(line);
        return;
    }
    const std::string& text = line.text;
    if (!comment_delim_.empty()) {  // M80 .COMMENT block
        if (text.find(comment_delim_) != std::string::npos) comment_delim_.clear();
        return;
    }
    auto first = text.find_first_not_of(" \t\f\r");
    if (first == std::string::npos || text[0] == '*' || text[first] == ';') return;
    if (text[0] == '$') {  // Intel control line: $INCLUDE(file) matters, the rest is listing control
        if (!skipping()) control_line(text);
        return;
    }
    LexError le;
    auto toks = tokenize(text, le, radix_);
    if (!le.message.empty() && !skipping()) {
        error(le.col, le.message);
        return;
    }
    auto stmts = split_statements(toks);
    for (std::size_t i = 0; i < stmts.size(); ++i) {
        if (ended_ || collect_.kind != Collect::None) break;
        const std::size_t depth = frames_.size();
        process_statement(stmts[i], line);
        if (frames_.size() > depth && i + 1 < stmts.size()) {
            // A macro or INCLUDE started mid-line: the statements after the next '!' run when it
            // is done, from a one-line frame under the new one.
            int from = stmts[i].back().col + 1;
            Frame rest;
            rest.kind = FrameKind::Repeat;
            rest.body = std::make_shared<std::vector<BodyLine>>();
            rest.body->push_back({text.substr(static_cast<std::size_t>(from)), line.file, line.line});
            rest.count = 1;
            rest.cond_depth = cond_.size();
            rest.cond_scope = false;
            rest.site_file = line.site_file;
            rest.site_line = line.site_line;
            rest.name = "the rest of the line";
            frames_.insert(frames_.begin() + static_cast<std::ptrdiff_t>(depth), std::move(rest));
            break;
        }
    }
}

// An ASM80 control line: '$' in column 1, then controls separated by blanks, each a word with an
// optional (argument); quotes in an argument may hold parentheses. INCLUDE(file) includes the
// file after this line (several are read in their order); the other controls ($MOD85, $NOLIST,
// $TITLE('...'), $EJECT, ...) steer ISIS listings and object files and change no byte here.
void Assembler::control_line(const std::string& text) {
    struct Included {
        std::string name;
        int col = 0;
    };
    std::vector<Included> includes;
    std::size_t i = 1;
    const std::size_t n = text.size();
    while (i < n) {
        const char c = text[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f') {
            ++i;
            continue;
        }
        if (c == ';') break;
        const std::size_t word_at = i;
        while (i < n && std::isalnum(static_cast<unsigned char>(text[i]))) ++i;
        const std::string word = to_upper(text.substr(word_at, i - word_at));
        if (word.empty()) {
            ++i;  // not a control word: listing text such as a stray character, ignored as before
            continue;
        }
        std::size_t j = i;
        while (j < n && (text[j] == ' ' || text[j] == '\t')) ++j;
        std::optional<std::string> arg;
        std::size_t arg_at = j + 1;
        if (j < n && text[j] == '(') {
            int depth = 0;
            char quote = 0;
            std::size_t k = j;
            for (; k < n; ++k) {
                const char d = text[k];
                if (quote) {
                    if (d == quote) quote = 0;
                } else if (d == '\'' || d == '"') {
                    quote = d;
                } else if (d == '(') {
                    ++depth;
                } else if (d == ')' && --depth == 0) {
                    break;
                }
            }
            if (k < n) {
                arg = text.substr(j + 1, k - j - 1);
                i = k + 1;
            } else {
                i = n;  // unclosed: only INCLUDE needs its argument
            }
        }
        if (word != "INCLUDE") continue;
        if (!arg) {
            error(static_cast<int>(word_at), "$INCLUDE needs (filename)");
            continue;
        }
        std::string name = *arg;
        // ISIS drive prefixes (:F1:) mean nothing here.
        if (name.size() > 4 && name[0] == ':' && name[3] == ':') {
            name = name.substr(4);
            arg_at += 4;
        }
        includes.push_back({name, static_cast<int>(arg_at)});
    }
    // Frames are read last-in first: push the last file first so that the files follow the line's order.
    for (auto it = includes.rbegin(); it != includes.rend(); ++it) do_include(it->name, it->col);
}

void Assembler::process_statement(const std::vector<Token>& toks, const Line& line) {
    auto ident = [&](std::size_t i) { return toks[i].kind == Tok::Ident; };
    auto punct = [&](std::size_t i, char c) { return toks[i].kind == Tok::Punct && toks[i].punct == c; };
    auto op_at = [&](std::size_t i) { return (ident(i) && is_op_word(toks[i].text)) || punct(i, '='); };

    std::string label;
    int label_col = 0;
    std::size_t p = 0;
    if (toks[0].kind == Tok::End) return;
    if (ident(0)) {
        if (punct(1, ':')) {
            label = toks[0].text;
            label_col = toks[0].col;
            p = 2;
        } else if ((ident(1) && is_name_op(toks[1].text)) || punct(1, '=')) {
            label = toks[0].text;
            label_col = toks[0].col;
            p = 1;
        } else if (!is_op_word(toks[0].text) && ((toks[1].kind == Tok::End && toks[0].col == 0) || op_at(1))) {
            label = toks[0].text;  // a label without a colon (DR ASM, Intel's names)
            label_col = toks[0].col;
            p = 1;
        }
    }
    if (toks[p].kind == Tok::End) {
        if (skipping() || label.empty()) return;
        define(label, label_col, loc(), SymbolKind::Label);
        listing_.back().address = loc();
        return;
    }
    if (!ident(p) && !punct(p, '=')) {
        if (!skipping()) error(toks[p].col, "expected an instruction or directive");
        return;
    }
    const std::string op = punct(p, '=') ? std::string("=") : toks[p].text;
    const std::size_t args = p + 1;
    op_col_ = toks[p].col;
    if (is_conditional_word(op)) {
        // A label names the line's address where the line itself is assembled: an IF outside a
        // false branch, an ELSE or ENDIF where its IF is (it was dropped without a word before).
        const bool closing = op == "ELSE" || op == "ENDIF" || op == "ENDC";
        if (!label.empty() && (closing ? cond_.empty() || cond_.back().parent_active : !skipping())) {
            define(label, label_col, loc(), SymbolKind::Label);
            listing_.back().address = loc();
        }
        conditional(op, toks, args, line);
        return;
    }
    if (skipping()) return;
    if (is_name_op(op)) {
        if (label.empty()) {
            error(toks[p].col, op + " needs a name in the label field");
            return;
        }
        try_directive(op, toks, args, label, label_col, line);
        return;
    }
    if (!label.empty()) {
        define(label, label_col, loc(), SymbolKind::Label);
        if (!listing_.back().address) listing_.back().address = loc();
    }
    if (try_directive(op, toks, args, label, label_col, line)) return;
    if (auto it = macros_.find(op); it != macros_.end()) {
        call_macro(it->second, line, toks[args].col, toks.back().col);
        return;
    }
    if (try_instruction(op, toks[p], toks, args)) return;
    if (p == 0 && ident(1) && !label.empty())
        error(toks[0].col, "unknown instruction '" + op + "'");
    else
        error(toks[p].col, "unknown instruction or directive '" + op + "'");
}

void Assembler::collect_line(const Line& line) {
    LexError le;
    auto toks = tokenize(line.text, le, radix_);
    std::string op;
    if (toks[0].kind == Tok::Ident) {
        if (toks[1].kind == Tok::Punct && toks[1].punct == ':')
            op = toks[2].kind == Tok::Ident ? toks[2].text : "";
        else if (is_block_start(toks[0].text) || toks[0].text == "ENDM")
            op = toks[0].text;
        else if (toks[1].kind == Tok::Ident)
            op = toks[1].text;
    }
    if (!line.text.empty() && line.text[0] == '*') op.clear();
    if (is_block_start(op)) {
        ++collect_.depth;
    } else if (op == "ENDM") {
        if (--collect_.depth == 0) {
            finish_collect();
            return;
        }
    }
    collect_.def.body->push_back({line.text, line.file, line.line});
}

}  // namespace alp85::asm85
