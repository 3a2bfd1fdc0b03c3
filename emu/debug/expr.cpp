#include "emu/debug/expr.h"

#include <algorithm>
#include <array>
#include <cctype>

#include <fmt/format.h>

#include "emu/core/cpu_registers.h"
#include "emu/util/text.h"

namespace alp85::debug {

namespace {
// A name as asm85 spells a symbol: a letter, _ ? @ or . first; digits and $ after it.
bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == '?' || c == '@' || c == '.'; }
bool is_name_char(char c) { return is_name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '$'; }

// Parsing and evaluating recurse: a bound on the depth keeps a hostile text ("((((...", a
// 200 000-term sum) from exhausting the stack. No expression a person types comes near it.
constexpr int kMaxDepth = 256;

// Two's-complement arithmetic, as the 64-bit machine word does it: no overflow is undefined.
std::int64_t wrap(std::uint64_t v) { return static_cast<std::int64_t>(v); }
std::uint64_t u(std::int64_t v) { return static_cast<std::uint64_t>(v); }
// The flag byte, as the CPU's description reads it.
std::uint16_t flag_byte(const Registers& r) { return cpu::description().flag_register()->read(r); }
}  // namespace

std::optional<std::uint8_t> flag_named(std::string_view n) {
    const cpu::Flag* f = cpu::description().find_flag(n);
    if (!f) return std::nullopt;
    return f->bit;
}

bool read_only_named(std::string_view n) { return n == "T" || n == "TIME"; }

// Recursive descent, one level per precedence (C's order).
class ExprParser {
public:
    // symbols null: the names are collected into `deferred` (Expr::shape), each read as 0.
    ExprParser(std::string_view text, const SymbolTable* symbols, Expr::Names names, int col_base, ExprError& error,
               const Expr::Variables* variables, std::vector<Expr::Name>* deferred = nullptr)
        : s_(text), symbols_(symbols), names_(names), base_(col_base), error_(error), vars_(variables), deferred_(deferred) {}

    bool reads_machine() const { return reads_machine_; }

    std::optional<Expr> run() {
        Expr e;
        e_ = &e;
        e.text_ = std::string(s_);
        const int root = binary(0);
        if (root < 0) return std::nullopt;
        skip();
        if (i_ < s_.size()) return fail(fmt::format("unexpected '{}'", s_.substr(i_, 1))), std::nullopt;
        e.root_ = root;
        e.width_ = width_of(root);
        return e;
    }

private:
    using K = Expr::Kind;
    struct BinOp {
        std::string_view text;
        K kind;
        int level;
    };
    static constexpr std::array<BinOp, 18> kBinOps = {{
        {"||", K::Or, 0}, {"&&", K::And, 1}, {"|", K::BitOr, 2}, {"^", K::BitXor, 3}, {"&", K::BitAnd, 4},
        {"==", K::Eq, 5}, {"!=", K::Ne, 5}, {"<=", K::Le, 6}, {">=", K::Ge, 6}, {"<<", K::Shl, 7},
        {">>", K::Shr, 7}, {"<", K::Lt, 6}, {">", K::Gt, 6}, {"+", K::Add, 8}, {"-", K::Sub, 8},
        {"*", K::Mul, 9}, {"/", K::Div, 9}, {"%", K::Mod, 9},
    }};
    static constexpr int kLevels = 10;

    int fail(std::string message, int at = -1) {
        error_.col = base_ + (at < 0 ? static_cast<int>(i_) : at) + 1;
        error_.message = std::move(message);
        return -1;
    }
    void skip() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    int add(Expr::Node n) {
        switch (n.kind) {
            case K::Reg: case K::Flag: case K::Time: case K::Mem8: case K::Mem16: case K::Var: reads_machine_ = true; break;
            default: break;
        }
        int d = 1;
        if (n.a >= 0) d = std::max(d, depth_of(n.a) + 1);
        if (n.b >= 0) d = std::max(d, depth_of(n.b) + 1);
        e_->nodes_.push_back(n);
        depth_.push_back(d);
        return static_cast<int>(e_->nodes_.size()) - 1;
    }
    int depth_of(int n) const { return depth_[static_cast<std::size_t>(n)]; }
    int width_of(int n) const {
        const Expr::Node& x = e_->nodes_[static_cast<std::size_t>(n)];
        switch (x.kind) {
            case K::Reg: return cpu::description().registers[static_cast<std::size_t>(x.value)].width;
            case K::Flag:
            case K::Mem8: return 8;
            case K::Number: return x.value >= -128 && x.value <= 255 ? 8 : 16;
            case K::Var: return 16;
            case K::Time: return 16;
            case K::Lt: case K::Le: case K::Gt: case K::Ge: case K::Eq: case K::Ne: case K::Not: case K::And: case K::Or:
                return 8;  // 0 or 1
            case K::Neg: case K::Compl: return width_of(x.a);
            default: return std::max(width_of(x.a), x.b >= 0 ? width_of(x.b) : 8);  // arithmetic: its operands' widest
        }
    }

    // A register's node; M, the byte at HL, is memory: byte[HL].
    int register_node(const cpu::Register& r, int col) {
        const cpu::Description& d = cpu::description();
        if (r.kind != cpu::Register::Kind::Memory)
            return add({K::Reg, static_cast<std::int64_t>(d.index_of(r)), -1, -1, col});
        const cpu::Register* at = d.find(r.high);
        if (!at) return fail(fmt::format("{} has no address register", r.name), col);
        return add({K::Mem8, 0, add({K::Reg, static_cast<std::int64_t>(d.index_of(*at)), -1, -1, col}), -1, col});
    }

    const BinOp* binop_here(int level) {
        skip();
        for (const BinOp& op : kBinOps) {
            if (op.level != level || s_.substr(i_, op.text.size()) != op.text) continue;
            // "&" is not "&&", "|" not "||", "<" not "<<" or "<=": the longer ones come first in
            // the table only within their level, so check the next character.
            const std::string_view rest = s_.substr(i_ + op.text.size());
            if (op.text.size() == 1 && !rest.empty()) {
                const char c = op.text[0], n = rest[0];
                if ((c == '&' && n == '&') || (c == '|' && n == '|') || ((c == '<' || c == '>') && (n == c || n == '=')))
                    continue;
            }
            return &op;
        }
        return nullptr;
    }

    // Entered for each parenthesis, bracket and prefix operator: the parser's own recursion.
    struct Nest {
        ExprParser& p;
        explicit Nest(ExprParser& parser) : p(parser) { ++p.nesting_; }
        ~Nest() { --p.nesting_; }
    };
    bool too_deep() const { return nesting_ > kMaxDepth; }
    int fail_deep() { return fail(fmt::format("the expression is nested too deeply (more than {} levels)", kMaxDepth)); }

    int binary(int level) {
        if (level == kLevels) return unary();
        int left = binary(level + 1);
        if (left < 0) return -1;
        while (const BinOp* op = binop_here(level)) {
            const int col = static_cast<int>(i_);
            i_ += op->text.size();
            const int right = binary(level + 1);
            if (right < 0) return -1;
            left = add({op->kind, 0, left, right, col});
            if (depth_of(left) > kMaxDepth)  // evaluation recurses once per level of the tree
                return fail(fmt::format("the expression is too long (more than {} operations in a chain)", kMaxDepth),
                            col);
        }
        return left;
    }

    int unary() {
        skip();
        if (i_ >= s_.size()) return fail("expected a value");
        const char c = s_[i_];
        const int col = static_cast<int>(i_);
        if (c == '-' || c == '!' || c == '~' || c == '+') {
            const Nest nest(*this);
            if (too_deep()) return fail_deep();
            ++i_;
            const int a = unary();
            if (a < 0) return -1;
            if (c == '+') return a;
            if (a < 0) return -1;
            return add({c == '-' ? K::Neg : c == '!' ? K::Not : K::Compl, 0, a, -1, col});
        }
        return primary();
    }

    int bracket(K kind, int col) {  // after '['
        const Nest nest(*this);
        if (too_deep()) return fail_deep();
        const int a = binary(0);
        if (a < 0) return -1;
        skip();
        if (i_ >= s_.size() || s_[i_] != ']') return fail("expected ']'");
        ++i_;
        return add({kind, 0, a, -1, col});
    }

    int primary() {
        const char c = s_[i_];
        const int col = static_cast<int>(i_);
        if (c == '(') {
            const Nest nest(*this);
            if (too_deep()) return fail_deep();
            ++i_;
            const int a = binary(0);
            if (a < 0) return -1;
            skip();
            if (i_ >= s_.size() || s_[i_] != ')') return fail("expected ')'");
            ++i_;
            return a;
        }
        if (c == '[') {
            ++i_;
            return bracket(K::Mem8, col);
        }
        if (c == '\'') {
            if (i_ + 2 < s_.size() && s_[i_ + 2] == '\'') {
                const auto v = static_cast<unsigned char>(s_[i_ + 1]);
                i_ += 3;
                return add({K::Number, v, -1, -1, col});
            }
            return fail("a character is written 'A'");
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t j = i_;
            while (j < s_.size() && std::isalnum(static_cast<unsigned char>(s_[j]))) ++j;
            const std::string_view word = s_.substr(i_, j - i_);
            // 0800 would be decimal 800 = 0320H: on an 8085 surely meant as hex (the script language's rule).
            if (word.size() > 1 && word[0] == '0' && std::all_of(word.begin(), word.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); }))
                return fail(fmt::format("'{}' is ambiguous: write {}H for hex or {} for decimal", word, word, word.substr(word.find_first_not_of('0') == std::string_view::npos ? word.size() - 1 : word.find_first_not_of('0'))));
            const auto v = parse_int(word);
            if (!v) return fail(fmt::format("bad number '{}' (hex needs a leading digit and H: 0FFH)", word));
            i_ = j;
            return add({K::Number, *v, -1, -1, col});
        }
        const bool dollar = c == '$', amp = c == '&';
        if (dollar || amp) ++i_;
        std::size_t j = i_;
        if (j < s_.size() && (dollar ? is_name_char(s_[j]) : is_name_start(s_[j])))
            while (j < s_.size() && is_name_char(s_[j])) ++j;
        if (j == i_) return fail(i_ < s_.size() ? fmt::format("unexpected '{}'", s_.substr(i_, 1)) : "expected a value");
        const std::string name = to_upper(s_.substr(i_, j - i_));
        i_ = j;
        skip();
        if (!dollar && !amp && i_ < s_.size() && s_[i_] == '[' && (name == "BYTE" || name == "WORD")) {
            ++i_;
            return bracket(name == "BYTE" ? K::Mem8 : K::Mem16, col);
        }
        auto machine_name = [&]() -> int {
            if (const cpu::Register* r = cpu::description().find(name)) return register_node(*r, col);
            if (const auto f = flag_named(name)) return add({K::Flag, *f, -1, -1, col});
            if (dollar && read_only_named(name)) return add({K::Time, 0, -1, -1, col});
            return -1;
        };
        auto symbol = [&]() -> int {
            if (!symbols_) {  // shape: resolved later
                deferred_->push_back({name, base_ + col + 1, amp,
                                      cpu::description().find(name) != nullptr || flag_named(name).has_value()});
                return add({K::Number, 0, -1, -1, col});
            }
            if (const auto v = symbols_->value_of(name)) return add({K::Number, *v, -1, -1, col});
            return -1;
        };
        if (dollar) {
            const int n = machine_name();
            if (n >= 0) return n;
            if (vars_ && vars_->contains(name)) {  // read at each evaluation: a condition sees the value of now
                e_->vars_ = vars_;
                e_->var_names_.push_back(name);
                return add({K::Var, static_cast<std::int64_t>(e_->var_names_.size() - 1), -1, -1, col});
            }
            return fail(fmt::format("no register, flag or variable '${}'", name), col);
        }
        if (amp) {
            const int n = symbol();
            return n >= 0 ? n : fail(fmt::format("unknown symbol '{}'", name), col);
        }
        int n = names_ == Expr::Names::SymbolsFirst ? symbol() : machine_name();
        if (n < 0) n = names_ == Expr::Names::SymbolsFirst ? machine_name() : symbol();
        return n >= 0 ? n : fail(fmt::format("unknown symbol '{}'", name), col);
    }

    std::string_view s_;
    const SymbolTable* symbols_;
    Expr::Names names_;
    int base_;
    ExprError& error_;
    const Expr::Variables* vars_;
    Expr* e_ = nullptr;
    std::size_t i_ = 0;
    int nesting_ = 0;
    std::vector<int> depth_;  // of each node's subtree, parallel to e_->nodes_
    std::vector<Expr::Name>* deferred_;
    bool reads_machine_ = false;
};

std::optional<Expr> Expr::parse(std::string_view text, const SymbolTable& symbols, ExprError& error, Names names,
                                int col_base, const Variables* variables) {
    return ExprParser(text, &symbols, names, col_base, error, variables).run();
}

std::optional<Expr::Shape> Expr::shape(std::string_view text, ExprError& error, int col_base) {
    Shape out;
    ExprParser p(text, nullptr, Names::SymbolsFirst, col_base, error, nullptr, &out.names);
    const std::optional<Expr> e = p.run();
    if (!e) return std::nullopt;
    if (out.names.empty() && !p.reads_machine()) {
        try {
            out.constant = e->eval(nullptr, e->root_);
        } catch (const ExprError& x) {
            error = {col_base + x.col, x.message};
            return std::nullopt;
        }
    }
    return out;
}

std::int64_t Expr::eval(const Machine* m, int i) const {
    const Node& n = nodes_[static_cast<std::size_t>(i)];
    auto a = [&] { return eval(m, n.a); };
    auto b = [&] { return eval(m, n.b); };
    switch (n.kind) {
        case Kind::Number: return n.value;
        case Kind::Var: {
            const std::string& name = var_names_[static_cast<std::size_t>(n.value)];
            const auto it = vars_->find(name);
            if (it == vars_->end()) throw ExprError{n.col, fmt::format("no variable '${}'", name)};
            return it->second;
        }
        case Kind::Reg: return cpu::description().registers[static_cast<std::size_t>(n.value)].read(m->cpu().regs());
        case Kind::Flag: return (flag_byte(m->cpu().regs()) & n.value) ? 1 : 0;
        case Kind::Time: return static_cast<std::int64_t>(m->now());
        case Kind::Mem8: return m->peek(static_cast<std::uint16_t>(a()));
        case Kind::Mem16: {
            const auto addr = static_cast<std::uint16_t>(a());
            return m->peek(addr) | m->peek(static_cast<std::uint16_t>(addr + 1)) << 8;
        }
        case Kind::Neg: return wrap(0 - u(a()));
        case Kind::Not: return a() == 0;
        case Kind::Compl: return ~a();
        case Kind::Mul: return wrap(u(a()) * u(b()));
        case Kind::Div:
        case Kind::Mod: {
            const std::int64_t x = a(), y = b();
            if (y == 0) throw ExprError{n.col + 1, "division by zero"};
            // x / -1 is -x, x % -1 is 0: the hardware division of INT64_MIN by -1 traps.
            if (y == -1) return n.kind == Kind::Div ? wrap(0 - u(x)) : 0;
            return n.kind == Kind::Div ? x / y : x % y;
        }
        case Kind::Add: return wrap(u(a()) + u(b()));
        case Kind::Sub: return wrap(u(a()) - u(b()));
        case Kind::Shl: return wrap(u(a()) << (b() & 63));
        case Kind::Shr: return a() >> (b() & 63);
        case Kind::Lt: return a() < b();
        case Kind::Le: return a() <= b();
        case Kind::Gt: return a() > b();
        case Kind::Ge: return a() >= b();
        case Kind::Eq: return a() == b();
        case Kind::Ne: return a() != b();
        case Kind::BitAnd: return a() & b();
        case Kind::BitXor: return a() ^ b();
        case Kind::BitOr: return a() | b();
        case Kind::And: return a() && b();
        case Kind::Or: return a() || b();
    }
    return 0;
}

bool Expr::assignable() const {
    const Kind k = nodes_[static_cast<std::size_t>(root_)].kind;
    return k == Kind::Reg || k == Kind::Flag || k == Kind::Mem8 || k == Kind::Mem16;
}

std::string Expr::assign(Machine& m, std::int64_t v) const {
    const Node& n = nodes_[static_cast<std::size_t>(root_)];
    Registers& x = m.cpu().regs();
    const auto lo = static_cast<std::uint8_t>(v);
    const auto word = static_cast<std::uint16_t>(v);  // a register keeps its width's low bits
    auto poke = [&](std::uint16_t addr, std::uint8_t b) {
        return m.poke(addr, b) ? std::string() : fmt::format("no memory at {:04X}H", addr);
    };
    switch (n.kind) {
        case Kind::Reg:
            cpu::description().registers[static_cast<std::size_t>(n.value)].write(x, word);
            return {};
        case Kind::Flag: {
            const cpu::Register* f = cpu::description().flag_register();
            const std::uint16_t now = f->read(x);
            f->write(x, static_cast<std::uint16_t>(v ? now | n.value : now & ~n.value));
            return {};
        }
        case Kind::Mem8: return poke(static_cast<std::uint16_t>(eval(&m, n.a)), lo);
        case Kind::Mem16: {
            const auto addr = static_cast<std::uint16_t>(eval(&m, n.a));
            std::string e = poke(addr, lo);
            return e.empty() ? poke(static_cast<std::uint16_t>(addr + 1), static_cast<std::uint8_t>(word >> 8)) : e;
        }
        default: return "not something that can be set (a register, a flag or memory)";
    }
}

}  // namespace alp85::debug
