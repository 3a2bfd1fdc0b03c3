// Macros and repeat blocks: collecting bodies, argument lists, parameter substitution, LOCAL
// names, EXITM.
//
// Arguments are separated by commas; <...> groups an argument that holds commas (M80), !c takes
// c literally and %expr passes the expression's decimal value. In a body, parameters are replaced
// as whole names; '&' joins a parameter to adjacent text and is the only way to reach a parameter
// inside a quoted string. ';;' comments are dropped from expansions.
#include <fmt/format.h>

#include "asm/assembler.h"

namespace alp85::asm85 {
namespace {

constexpr int kMaxExpansionDepth = 100;

}  // namespace

std::string trim(std::string_view s) {
    auto b = s.find_first_not_of(" \t\r\f");
    if (b == std::string_view::npos) return "";
    auto e = s.find_last_not_of(" \t\r\f");
    return std::string(s.substr(b, e - b + 1));
}

std::string strip_angle(std::string s) {
    s = trim(s);
    if (s.size() >= 2 && s.front() == '<' && s.back() == '>') s = s.substr(1, s.size() - 2);
    return s;
}


std::vector<std::string> Assembler::split_args(std::string_view text) {
    std::vector<std::string> out;
    std::string cur;
    int angle = 0, paren = 0;
    char quote = 0;
    bool any = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        if (quote) {
            cur += c;
            if (c == quote) quote = 0;
            continue;
        }
        if (c == ';' && angle == 0) break;
        if (c == '\'' || c == '"') {
            quote = c;
            cur += c;
            continue;
        }
        if (c == '<') {
            if (angle++ == 0) continue;  // the outer brackets only group
        } else if (c == '>' && angle > 0) {
            if (--angle == 0) continue;
        } else if (c == '!' && i + 1 < text.size()) {
            cur += text[++i];
            continue;
        } else if (angle == 0 && c == '(') {
            ++paren;
        } else if (angle == 0 && c == ')' && paren > 0) {
            --paren;
        } else if (c == ',' && angle == 0 && paren == 0) {
            out.push_back(trim(cur));
            cur.clear();
            any = true;
            continue;
        }
        cur += c;
    }
    if (any || !trim(cur).empty()) out.push_back(trim(cur));
    return out;
}

void Assembler::begin_collect(Collect::Kind kind, const std::vector<Token>& toks, std::size_t p,
                              const std::string& name, const Line& line) {
    Collect c;
    c.kind = kind;
    c.depth = 1;
    c.file = line.file;
    c.line = line.line;
    c.col = toks[p - 1].col + 1;
    c.def.body = std::make_shared<std::vector<BodyLine>>();
    c.def.file = line.file;
    c.def.line = line.line;
    auto raw_from = [&](std::size_t i) -> std::string {
        int from = toks[i].col, to = toks.back().col;
        return to > from ? line.text.substr(static_cast<std::size_t>(from), static_cast<std::size_t>(to - from)) : "";
    };
    switch (kind) {
        case Collect::Macro: {
            c.def.name = name;
            if (is_directive_word(name) || is_conditional_word(name))
                error(toks[p - 1].col, "'" + name + "' is a directive and can't name a macro");
            for (std::size_t i = p; toks[i].kind != Tok::End; ++i) {
                if (toks[i].kind == Tok::Ident) {
                    c.def.params.push_back(toks[i].text);
                } else if (!(toks[i].kind == Tok::Punct && toks[i].punct == ',')) {
                    error(toks[i].col, "macro parameters must be names");
                    break;
                }
            }
            break;
        }
        case Collect::Rept: {
            Value v;
            if (expr_all(toks, p, v)) c.count = v.v;
            c.def.name = "REPT";
            break;
        }
        case Collect::Irp:
        case Collect::Irpc: {
            c.def.name = kind == Collect::Irp ? "IRP" : "IRPC";
            if (toks[p].kind != Tok::Ident || !(toks[p + 1].kind == Tok::Punct && toks[p + 1].punct == ',')) {
                error(toks[p].col, c.def.name + " needs: name,list");
                break;
            }
            c.def.params.push_back(toks[p].text);
            std::string list = strip_angle(raw_from(p + 2));
            if (kind == Collect::Irp) {
                for (auto& a : split_args(list)) c.args.push_back({a});
            } else {
                for (char ch : list) c.args.push_back({std::string(1, ch)});
            }
            if (c.args.empty()) c.args.push_back({""});
            c.count = c.args.size();
            break;
        }
        case Collect::None:
            break;
    }
    collect_ = std::move(c);
}

void Assembler::finish_collect() {
    Collect c = std::move(collect_);
    collect_ = Collect{};
    if (c.kind == Collect::Macro) {
        if (c.def.name.empty()) return;
        macros_[c.def.name] = std::move(c.def);
        return;
    }
    if (c.count == 0 || c.def.body->empty()) return;
    int depth = 0;
    for (auto& f : frames_)
        if (f.kind != FrameKind::File) ++depth;
    if (depth >= kMaxExpansionDepth) {
        error(0, "expansions nested more than 100 deep");
        return;
    }
    Frame f;
    f.kind = FrameKind::Repeat;
    f.body = c.def.body;
    f.params = c.def.params;
    f.args = std::move(c.args);
    f.count = c.count;
    f.cond_depth = cond_.size();
    f.site_file = cur_line_ ? cur_line_->site_file : 0;
    f.site_line = cur_line_ ? cur_line_->site_line : 0;
    f.name = c.def.name;
    frames_.push_back(std::move(f));
}

void Assembler::call_macro(MacroDef& m, const Line& line, int args_col, int args_end) {
    m.used = true;
    int depth = 0;
    for (auto& f : frames_)
        if (f.kind != FrameKind::File) ++depth;
    if (depth >= kMaxExpansionDepth) {
        error(args_col, "macros nested more than 100 deep (a macro that calls itself?)");
        return;
    }
    std::string raw = args_end > args_col
                          ? line.text.substr(static_cast<std::size_t>(args_col), static_cast<std::size_t>(args_end - args_col))
                          : "";
    auto args = split_args(raw);
    for (auto& a : args) {
        if (a.empty() || a[0] != '%') continue;
        LexError le;
        auto toks = tokenize(std::string_view(a).substr(1), le, radix_);
        std::size_t p = 0;
        Value v;
        if (le.message.empty() && expr(toks, p, v)) a = std::to_string(v.v);
    }
    if (args.size() > m.params.size() && !(m.params.empty() && args.size() == 1 && args[0].empty())) {
        error(args_col, fmt::format("macro {} takes {} argument(s), {} given", m.name, m.params.size(), args.size()));
        return;
    }
    args.resize(m.params.size());
    if (m.body->empty()) return;
    Frame f;
    f.kind = FrameKind::Macro;
    f.body = m.body;
    f.params = m.params;
    f.args.push_back(std::move(args));
    f.count = 1;
    f.cond_depth = cond_.size();
    f.site_file = line.site_file;
    f.site_line = line.site_line;
    f.name = m.name;
    frames_.push_back(std::move(f));
}

std::string Assembler::substitute(const Frame& f, const std::string& text) const {
    const std::vector<std::string>* args = f.args.empty() ? nullptr : &f.args[std::min(f.iteration, f.args.size() - 1)];
    auto replacement = [&](const std::string& upper) -> const std::string* {
        for (std::size_t i = 0; i < f.params.size(); ++i)
            if (f.params[i] == upper) return args && i < args->size() ? &(*args)[i] : nullptr;
        for (auto& [n, v] : f.locals)
            if (n == upper) return &v;
        return nullptr;
    };
    static const std::string kEmpty;
    std::string out;
    out.reserve(text.size() + 16);
    char quote = 0;
    std::size_t i = 0;
    const std::size_t n = text.size();
    while (i < n) {
        char c = text[i];
        if (!quote && c == ';') {
            if (i + 1 < n && text[i + 1] == ';') break;  // ;; comments stay in the definition
            out.append(text, i, std::string::npos);
            break;
        }
        if (c == '\'' || c == '"') {
            if (!quote) quote = c;
            else if (quote == c) quote = 0;
            out += c;
            ++i;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i < n && is_name_char(text[i])) out += text[i++];
            continue;
        }
        if (is_name_start(c)) {
            std::size_t j = i;
            while (j < n && is_name_char(text[j])) ++j;
            std::string word = text.substr(i, j - i);
            std::string upper = to_upper(word);
            const std::string* rep = nullptr;
            bool amp_before = !out.empty() && out.back() == '&';
            bool amp_after = j < n && text[j] == '&';
            bool known = false;
            for (auto& p : f.params) known = known || p == upper;
            for (auto& l : f.locals) known = known || l.first == upper;
            if (known && (!quote || amp_before || amp_after)) {
                rep = replacement(upper);
                if (!rep) rep = &kEmpty;
                if (amp_before) out.pop_back();
                out += *rep;
                i = j;
                if (amp_after) ++i;
                continue;
            }
            out += word;
            i = j;
            continue;
        }
        out += c;
        ++i;
    }
    return out;
}

void Assembler::exitm() {
    for (std::size_t k = frames_.size(); k-- > 0;) {
        if (frames_[k].kind == FrameKind::File) break;
        cond_.resize(std::min(cond_.size(), frames_[k].cond_depth));
        frames_.resize(k);
        return;
    }
    error(0, "EXITM outside a macro or repeat block");
}

void Assembler::add_locals(const std::vector<Token>& toks, std::size_t p) {
    if (frames_.empty() || frames_.back().kind == FrameKind::File) {
        error(toks[p - 1].col, "LOCAL outside a macro");
        return;
    }
    Frame& f = frames_.back();
    for (std::size_t i = p; toks[i].kind != Tok::End; ++i) {
        if (toks[i].kind == Tok::Ident)
            f.locals.emplace_back(toks[i].text, fmt::format("??{:04d}", ++local_counter_));
        else if (!(toks[i].kind == Tok::Punct && toks[i].punct == ','))
            error(toks[i].col, "LOCAL takes a list of names");
    }
}

}  // namespace alp85::asm85
