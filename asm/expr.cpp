#include "asm/expr.h"

#include <array>
#include <string_view>

namespace alp85::asm85 {
namespace {

constexpr int kMaxDepth = 200;  // nesting limit, so hostile input can't exhaust the stack

class Parser {
public:
    Parser(const std::vector<Token>& t, std::size_t& p, ExprContext& c) : toks_(t), pos_(p), ctx_(c) {}

    bool parse(Value& out) { return orxor(out); }

private:
    const std::vector<Token>& toks_;
    std::size_t& pos_;
    ExprContext& ctx_;
    int depth_ = 0;

    const Token& cur() const { return toks_[pos_]; }
    bool is_word(const char* w) const { return cur().kind == Tok::Ident && cur().text == w; }
    bool is_punct(char c) const { return cur().kind == Tok::Punct && cur().punct == c; }

    bool fail(const std::string& msg) {
        ctx_.error(cur().col, msg);
        return false;
    }

    static Value combine(const Value& a, const Value& b, std::uint32_t v) {
        return {static_cast<std::uint16_t>(v & 0xFFFF), a.known && b.known};
    }

    bool orxor(Value& out) {
        if (!andx(out)) return false;
        while (is_word("OR") || is_word("XOR")) {
            bool is_or = cur().text == "OR";
            ++pos_;
            Value r;
            if (!andx(r)) return false;
            out = combine(out, r, is_or ? (out.v | r.v) : (out.v ^ r.v));
        }
        return true;
    }

    bool andx(Value& out) {
        if (!notx(out)) return false;
        while (is_word("AND")) {
            ++pos_;
            Value r;
            if (!notx(r)) return false;
            out = combine(out, r, out.v & r.v);
        }
        return true;
    }

    bool notx(Value& out) {
        if (is_word("NOT")) {
            if (++depth_ > kMaxDepth) return fail("expression nested too deeply");
            ++pos_;
            if (!notx(out)) return false;
            --depth_;
            out.v = static_cast<std::uint16_t>(~out.v);
            return true;
        }
        return relation(out);
    }

    bool relation(Value& out) {
        if (!additive(out)) return false;
        static constexpr std::array<std::string_view, 6> kRel{"EQ", "NE", "LT", "LE", "GT", "GE"};
        for (;;) {
            if (cur().kind != Tok::Ident) return true;
            std::size_t which = kRel.size();
            for (std::size_t i = 0; i < kRel.size(); ++i)
                if (cur().text == kRel[i]) which = i;
            if (which == kRel.size()) return true;
            ++pos_;
            Value r;
            if (!additive(r)) return false;
            bool t = false;
            switch (which) {
                case 0: t = out.v == r.v; break;
                case 1: t = out.v != r.v; break;
                case 2: t = out.v < r.v; break;
                case 3: t = out.v <= r.v; break;
                case 4: t = out.v > r.v; break;
                default: t = out.v >= r.v; break;
            }
            out = combine(out, r, t ? 0xFFFFu : 0u);
        }
    }

    bool additive(Value& out) {
        // Unary + and - sit at this level in Intel's table: -A*B is -(A*B), the same number.
        if (is_punct('-') || is_punct('+')) {
            bool neg = is_punct('-');
            ++pos_;
            if (!multiplicative(out)) return false;
            if (neg) out.v = static_cast<std::uint16_t>(0u - out.v);
        } else if (!multiplicative(out)) {
            return false;
        }
        while (is_punct('+') || is_punct('-')) {
            bool add = is_punct('+');
            ++pos_;
            Value r;
            if (!multiplicative(r)) return false;
            out = combine(out, r, add ? out.v + r.v : out.v - r.v);
        }
        return true;
    }

    bool multiplicative(Value& out) {
        if (!highlow(out)) return false;
        for (;;) {
            int op = 0;
            if (is_punct('*')) op = 1;
            else if (is_punct('/')) op = 2;
            else if (is_word("MOD")) op = 3;
            else if (is_word("SHL")) op = 4;
            else if (is_word("SHR")) op = 5;
            else return true;
            int col = cur().col;
            ++pos_;
            Value r;
            if (!highlow(r)) return false;
            std::uint32_t v = 0;
            if ((op == 2 || op == 3) && r.v == 0) {
                if (r.known) {
                    ctx_.error(col, op == 2 ? "division by zero" : "MOD by zero");
                    return false;
                }
                v = 0;
            } else {
                switch (op) {
                    case 1: v = static_cast<std::uint32_t>(out.v) * r.v; break;
                    case 2: v = out.v / r.v; break;
                    case 3: v = out.v % r.v; break;
                    case 4: v = r.v >= 16 ? 0u : static_cast<std::uint32_t>(out.v) << r.v; break;
                    default: v = r.v >= 16 ? 0u : static_cast<std::uint32_t>(out.v) >> r.v; break;
                }
            }
            out = combine(out, r, v);
        }
    }

    bool highlow(Value& out) {
        if (is_word("HIGH") || is_word("LOW")) {
            bool high = cur().text == "HIGH";
            if (++depth_ > kMaxDepth) return fail("expression nested too deeply");
            ++pos_;
            if (!highlow(out)) return false;
            --depth_;
            out.v = high ? static_cast<std::uint16_t>(out.v >> 8) : static_cast<std::uint16_t>(out.v & 0xFF);
            return true;
        }
        return primary(out);
    }

    bool parenthesized_instruction(Value& out) {
        std::size_t first = pos_ + 1, i = first;
        int depth = 0;
        for (; toks_[i].kind != Tok::End; ++i) {
            if (toks_[i].kind != Tok::Punct) continue;
            if (toks_[i].punct == '(') ++depth;
            if (toks_[i].punct == ')' && depth-- == 0) break;
        }
        if (toks_[i].kind == Tok::End) {
            pos_ = i;
            return fail("expected ')'");
        }
        out = ctx_.instruction(first, i);
        pos_ = i + 1;
        return true;
    }

    bool primary(Value& out) {
        const Token& t = cur();
        switch (t.kind) {
            case Tok::Number:
                if (t.bad) return fail("invalid number '" + t.text + "'");
                if (t.value > 0xFFFF) return fail("number '" + t.text + "' does not fit in 16 bits");
                out = {static_cast<std::uint16_t>(t.value), true};
                ++pos_;
                return true;
            case Tok::String:
                if (t.text.size() > 2) return fail("string of more than 2 characters in an expression");
                out.known = true;
                out.v = 0;
                for (char c : t.text) out.v = static_cast<std::uint16_t>((out.v << 8) | static_cast<unsigned char>(c));
                ++pos_;
                return true;
            case Tok::Ident:
                if (t.text == "NUL") {  // M80: true when nothing follows
                    ++pos_;
                    bool empty = cur().kind == Tok::End;
                    while (cur().kind != Tok::End) ++pos_;
                    out = {static_cast<std::uint16_t>(empty ? 0xFFFF : 0), true};
                    return true;
                }
                if (is_operator_word(t.text)) return fail("operator '" + t.text + "' where a value is expected");
                out = ctx_.lookup(t);
                ++pos_;
                return true;
            case Tok::Punct:
                if (t.punct == '$') {
                    out = {ctx_.pc, true};
                    ++pos_;
                    return true;
                }
                if (t.punct == '(') {
                    if (ctx_.is_mnemonic && toks_[pos_ + 1].kind == Tok::Ident && ctx_.is_mnemonic(toks_[pos_ + 1].text))
                        return parenthesized_instruction(out);
                    if (++depth_ > kMaxDepth) return fail("expression nested too deeply");
                    ++pos_;
                    if (!orxor(out)) return false;
                    if (!is_punct(')')) return fail("expected ')'");
                    ++pos_;
                    --depth_;
                    return true;
                }
                if (t.punct == '-' || t.punct == '+') {  // unary inside a term: 2*-3
                    bool neg = t.punct == '-';
                    if (++depth_ > kMaxDepth) return fail("expression nested too deeply");
                    ++pos_;
                    if (!highlow(out)) return false;
                    --depth_;
                    if (neg) out.v = static_cast<std::uint16_t>(0u - out.v);
                    return true;
                }
                return fail(std::string("unexpected '") + t.punct + "' in expression");
            case Tok::End:
                return fail("missing operand");
        }
        return fail("bad expression");
    }
};

}  // namespace

bool is_operator_word(const std::string& w) {
    if (w.size() < 2 || w.size() > 4) return false;
    static constexpr std::array<std::string_view, 16> kWords{
        "MOD", "SHL", "SHR", "NOT", "AND", "OR", "XOR", "HIGH", "LOW", "EQ", "NE", "LT", "LE", "GT", "GE", "NUL"};
    for (auto k : kWords)
        if (w == k) return true;
    return false;
}

bool eval_expr(const std::vector<Token>& toks, std::size_t& pos, ExprContext& ctx, Value& out) {
    Parser p(toks, pos, ctx);
    if (!p.parse(out)) return false;
    const Token& t = toks[pos];
    if (t.kind == Tok::End || (t.kind == Tok::Punct && t.punct == ',')) return true;
    ctx.error(t.col, t.kind == Tok::Punct && t.punct == ')' ? "unbalanced ')'"
                                                          : "unexpected '" + (t.kind == Tok::Punct ? std::string(1, t.punct) : t.text) + "' after expression");
    return false;
}

}  // namespace alp85::asm85
