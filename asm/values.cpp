// Values and bytes: diagnostics, symbol lookup and definition, expressions, emission.
#include <algorithm>
#include <tuple>

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
    if (it != syms_.end() && it->second.pass >= pass_ - 1) {
        if (refs_) refs_->push_back(it->first);
        return {it->second.value, it->second.known};
    }
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

void Assembler::define(const std::string& full_name, int col, std::uint16_t value, SymbolKind kind, bool known,
                       std::vector<std::string> deps) {
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
            e.col = col + 1;
            e.known = known;
            e.deps = std::move(deps);
            return;
        }
        std::string where = e.file >= 0 ? fmt::format(" (first defined at {}:{})", files_[static_cast<std::size_t>(e.file)].name, e.line) : "";
        // SET and EQU don't mix (ASM80): a SET symbol is a variable, an EQU one a constant.
        if (kind == SymbolKind::Set && e.kind == SymbolKind::Equ)
            error(col, "'" + name + "' is an EQU constant" + where + "; SET can't redefine it");
        else if (kind == SymbolKind::Equ && e.kind == SymbolKind::Set)
            error(col, "'" + name + "' is a SET symbol" + where + "; EQU can't redefine it");
        else
            error(col, "'" + name + "' is already defined" + where);
        return;
    }
    // A value that is not known yet counts only when it becomes known: a circle's value (A EQU A+1)
    // changes every pass but is an error, not a reason for another pass.
    bool changed = false;
    if (inserted || e.pass < pass_ - 1) changed = pass_ > 1;
    else if (kind != SymbolKind::Set) changed = known != e.known || (known && e.value != value);
    if (changed && !changed_) changed_name_ = name;
    changed_ = changed_ || changed;
    e = {value, kind, pass_, file, line, col + 1, known, std::move(deps)};
}

// After a pass (the second on): the EQU and SET symbols still unknown that lead back to themselves,
// each reported at its definition with the circle it is on (Tarjan's strongly connected components
// over the symbols read, without recursion: a circle may be thousands of symbols long).
void Assembler::report_circles() {
    std::vector<std::string> names;
    for (const auto& [name, e] : syms_)
        if (e.pass == pass_ && !e.known && e.file >= 0) names.push_back(name);
    std::sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
        const SymEntry &x = syms_.at(a), &y = syms_.at(b);
        return std::tie(x.file, x.line, a) < std::tie(y.file, y.line, b);
    });
    std::unordered_map<std::string, std::size_t> id;
    for (std::size_t i = 0; i < names.size(); ++i) id.emplace(names[i], i);
    std::vector<std::vector<std::size_t>> next(names.size());
    for (std::size_t i = 0; i < names.size(); ++i)
        for (const std::string& d : syms_.at(names[i]).deps)
            if (auto it = id.find(d); it != id.end()) next[i].push_back(it->second);

    constexpr std::size_t kNone = ~std::size_t{0};
    std::vector<std::size_t> index(names.size(), kNone), low(names.size()), comp(names.size(), kNone), stack;
    std::vector<bool> on_stack(names.size());
    std::vector<std::vector<std::size_t>> comps;
    std::size_t counter = 0;
    for (std::size_t root = 0; root < names.size(); ++root) {
        if (index[root] != kNone) continue;
        std::vector<std::pair<std::size_t, std::size_t>> calls{{root, 0}};  // node, next edge
        index[root] = low[root] = counter++;
        stack.push_back(root);
        on_stack[root] = true;
        while (!calls.empty()) {
            auto& [v, k] = calls.back();
            if (k < next[v].size()) {
                const std::size_t w = next[v][k++];
                if (index[w] == kNone) {
                    index[w] = low[w] = counter++;
                    stack.push_back(w);
                    on_stack[w] = true;
                    calls.emplace_back(w, 0);
                } else if (on_stack[w]) {
                    low[v] = std::min(low[v], index[w]);
                }
                continue;
            }
            const std::size_t done = v;
            calls.pop_back();
            if (!calls.empty()) low[calls.back().first] = std::min(low[calls.back().first], low[done]);
            if (low[done] != index[done]) continue;
            comps.emplace_back();
            std::size_t w = kNone;
            do {
                w = stack.back();
                stack.pop_back();
                on_stack[w] = false;
                comp[w] = comps.size() - 1;
                comps.back().push_back(w);
            } while (w != done);
        }
    }
    const auto where = [&](std::size_t i) {
        const SymEntry& e = syms_.at(names[i]);
        return fmt::format("{} ({}:{})", names[i], files_[static_cast<std::size_t>(e.file)].name, e.line);
    };
    for (const auto& members : comps) {
        const std::size_t first = *std::min_element(members.begin(), members.end());
        const bool self = std::find(next[first].begin(), next[first].end(), first) != next[first].end();
        if (members.size() == 1 && !self) continue;
        // One circle through the first member, found breadth-first inside the component.
        std::vector<std::size_t> from(names.size(), kNone), queue{first};
        std::size_t last = self ? first : kNone;
        for (std::size_t q = 0; q < queue.size() && last == kNone; ++q)
            for (std::size_t w : next[queue[q]]) {
                if (comp[w] != comp[first]) continue;
                if (w == first) {
                    last = queue[q];
                    break;
                }
                if (from[w] == kNone) {
                    from[w] = queue[q];
                    queue.push_back(w);
                }
            }
        std::vector<std::size_t> circle;
        for (std::size_t v = last; v != first; v = from[v]) circle.push_back(v);
        circle.push_back(first);
        std::reverse(circle.begin(), circle.end());
        std::string text;
        constexpr std::size_t kShown = 8;
        for (std::size_t k = 0; k < circle.size() && k < kShown; ++k) text += where(circle[k]) + " -> ";
        if (circle.size() > kShown) text += fmt::format("... ({} symbols) -> ", circle.size());
        text += names[first];
        std::vector<std::size_t> sorted = members;
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i : sorted) {
            const SymEntry& e = syms_.at(names[i]);
            const SourceFile& f = files_[static_cast<std::size_t>(e.file)];
            Line at;
            at.file = e.file;
            at.line = e.line;
            if (e.line >= 1 && static_cast<std::size_t>(e.line) <= f.lines.size()) at.text = f.lines[static_cast<std::size_t>(e.line - 1)];
            cur_line_ = &at;
            error(e.col - 1, fmt::format("circular definition: {}", text));
            cur_line_ = nullptr;
        }
    }
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
