// The console's looking commands: print, set, display, x, list, disassemble, backtrace, info,
// history. Everything reads the machine through side-effect-free views.
#include <algorithm>
#include <bitset>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "emu/board/board_map.h"
#include "emu/core/cpu_registers.h"
#include "emu/debug/bus_cycles.h"
#include "emu/debug/console.h"
#include "emu/util/text.h"

namespace alp85::debug {

namespace {
std::string file_name(const std::string& f) { return std::filesystem::path(f).filename().string(); }
// "/x" after a command: the format letter, and the rest.
char take_format(std::string_view& a, int& col) {
    if (a.empty() || a.front() != '/') return 0;
    const char f = a.size() > 1 ? static_cast<char>(std::tolower(static_cast<unsigned char>(a[1]))) : 0;
    std::size_t i = 1;
    while (i < a.size() && !std::isspace(static_cast<unsigned char>(a[i]))) ++i;
    col += static_cast<int>(i);
    a = trim_blanks(a.substr(i), &col);
    return f;
}
}  // namespace

std::string Console::format_value(std::int64_t v, int width, char f) const {
    if (width == 8 && (v < -128 || v > 255)) width = 16;  // byte arithmetic that carried beyond a byte
    const auto u = static_cast<std::uint64_t>(v) & (width == 8 ? 0xFFu : 0xFFFFu);
    const bool in_range = v >= -(1 << (width - 1)) && v < (1 << width);
    switch (f) {
        case 'x': return width == 8 ? fmt::format("{:02X}H", u) : fmt::format("{:04X}H", u);
        case 'd': return std::to_string(v);
        case 'u': return std::to_string(u);
        case 'o': return fmt::format("{:o}Q", u);
        case 't': return fmt::format("{:0{}b}B", u, width);
        case 'c': return u >= 0x20 && u < 0x7F ? fmt::format("'{}'", static_cast<char>(u)) : fmt::format("{:02X}H", u);
        default:
            if (!in_range) return std::to_string(v);  // arithmetic beyond 16 bits: the number itself
            return width == 8 ? fmt::format("{:02X}H ({})", u, v) : fmt::format("{:04X}H ({})", u, v);
    }
}

std::string Console::formatted_expression(std::string_view a, int col, std::string_view missing, bool numbered) {
    const char f = take_format(a, col);
    if (a.empty()) return error(col, std::string(missing));
    ExprError err;
    const auto e = Expr::parse(a, d_.program(), err, Expr::Names::RegistersFirst, col - 1, &vars_);
    if (!e) return error(err.col, err.message);
    try {
        const std::string value = format_value(e->eval(d_.machine()), e->width(), f);
        return numbered ? fmt::format("${} = {}\n", ++print_count_, value) : value;
    } catch (const ExprError& x) {
        return error(col + x.col - 1, x.message);
    }
}

std::string Console::cmd_print(std::string_view a, int col) {
    return formatted_expression(a, col, "expected an expression", true);
}

std::string Console::cmd_output(std::string_view a, int col) {
    return formatted_expression(a, col, "expected an expression: output EXPR", false);
}

std::string Console::cmd_echo(std::string_view a, int) {
    std::string out;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] != '\\') {
            out += a[i];
            continue;
        }
        if (++i == a.size()) break;  // a backslash at the end: gdb's way to end without a blank
        switch (a[i]) {
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            default: out += a[i]; break;  // \\ \" and \  (a kept blank)
        }
    }
    return out;
}

std::string Console::cmd_set(std::string_view a, int col) {
    const std::string first = to_upper(a.substr(0, a.find(' ')));
    if (first == "HISTORY") {
        const std::string v = to_upper(trim_blanks(a.substr(7)));
        if (v != "ON" && v != "OFF") return error(col + 8, "expected: set history on|off");
        d_.set_history(v == "ON");
        return fmt::format("History {}.\n", v == "ON" ? "on: reverse execution from here" : "off");
    }
    if (first == "LIMIT" && !trim_blanks(a.substr(5)).starts_with('=')) {  // set limit = 5: a symbol LIMIT
        int tcol = col + 5;
        const std::string_view time = trim_blanks(a.substr(5), &tcol);
        const auto t = tstates_of(time);
        if (!t || *t == 0)
            return error(tcol, fmt::format("expected: set limit TIME (10ms, 2s, 3070t; not 0), not '{}'", time));
        d_.set_continue_limit(*t);
        return fmt::format("continue, finish, until and advance give up after {:.3f} s of machine time.\n",
                           board::ms_from_tstates(*t) / 1000.0);
    }
    if (first == "VAR") {
        col += 3;
        a = trim_blanks(a.substr(3), &col);
    }
    const auto eq = a.find('=');
    if (eq == std::string_view::npos || (eq + 1 < a.size() && a[eq + 1] == '=') || (eq > 0 && (a[eq - 1] == '!' || a[eq - 1] == '<' || a[eq - 1] == '>')))
        return error(col, "expected: set LVALUE = EXPR (a register, a flag, [ADDR], byte[ADDR], word[ADDR])");
    ExprError err;
    int lcol = col;
    const std::string_view lhs = trim_blanks(a.substr(0, eq), &lcol);
    int rcol = col + static_cast<int>(eq) + 1;
    const std::string_view rhs = trim_blanks(a.substr(eq + 1), &rcol);
    if (lhs.size() > 1 && lhs.front() == '$' && read_only_named(to_upper(lhs.substr(1))))
        return error(lcol, fmt::format("{} is read-only: the T-state counter, the machine's time since it started", lhs));
    // set $NAME = EXPR: a convenience variable (not a register's or flag's name).
    if (lhs.size() > 1 && lhs.front() == '$' && !cpu::description().find(lhs.substr(1)) && !flag_named(to_upper(lhs.substr(1))) &&
        std::all_of(lhs.begin() + 1, lhs.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; })) {
        const auto value = Expr::parse(rhs, d_.program(), err, Expr::Names::RegistersFirst, rcol - 1, &vars_);
        if (!value) return error(err.col, err.message);
        try {
            vars_[to_upper(lhs.substr(1))] = value->eval(d_.machine());
        } catch (const ExprError& x) {
            return error(rcol + x.col - 1, x.message);
        }
        return {};
    }
    const auto target = Expr::parse(lhs, d_.program(), err, Expr::Names::RegistersFirst, lcol - 1, &vars_);
    if (!target) return error(err.col, err.message);
    if (!target->assignable()) return error(lcol, fmt::format("'{}' cannot be set (a register, a flag or memory can)", lhs));
    const auto value = Expr::parse(rhs, d_.program(), err, Expr::Names::RegistersFirst, rcol - 1, &vars_);
    if (!value) return error(err.col, err.message);
    try {
        const std::string e = target->assign(d_.machine(), value->eval(d_.machine()));
        if (!e.empty()) return error(lcol, e);
    } catch (const ExprError& x) {
        return error(rcol + x.col - 1, x.message);
    }
    d_.state_changed();
    return {};
}

std::string Console::evaluate(std::string_view text, int col, Expr::Names names, std::int64_t& out) {
    ExprError err;
    const auto e = Expr::parse(text, d_.program(), err, names, col - 1, &vars_);
    if (!e) return error(err.col, err.message);
    try {
        out = e->eval(d_.machine());
    } catch (const ExprError& x) {
        return error(col + x.col - 1, x.message);
    }
    return {};
}

std::string Console::address(std::string_view text, int col, std::int64_t& out) {
    if (std::string e = evaluate(text, col, Expr::Names::SymbolsFirst, out); !e.empty()) return e;
    if (out < 0 || out > 0xFFFF) return error(col, fmt::format("address {} is outside 0000H-FFFFH", out));
    return {};
}

std::string Console::cmd_expect(std::string_view a, int col) {
    if (a.empty()) return error(col, "expected an expression: expect EXPR");
    std::int64_t v = 0;
    if (std::string e = evaluate(a, col, Expr::Names::RegistersFirst, v); !e.empty()) return e;
    if (v != 0) return {};
    return error(col, fmt::format("expectation failed: {} is 0 (false) at T = {}, PC = {:04X}H", a, d_.machine().now(),
                                  d_.machine().cpu().regs().pc));
}

// One display: "N: EXPR = VALUE", or for /i and /s (memory at the value, as x shows it)
// "N: x/i EXPR" and the instruction.
std::string Console::show_display(const Display& d) {
    try {
        const std::int64_t v = d.expr.eval(d_.machine());
        if (d.format == 'i' || d.format == 's') {
            std::uint16_t next = 0;
            return fmt::format("{}: x/{} {}\n", d.number, d.format, d.expr.text()) +
                   examine(static_cast<std::uint16_t>(v), 1, d.format, 'b', next);
        }
        return fmt::format("{}: {} = {}\n", d.number, d.expr.text(), format_value(v, d.expr.width(), d.format));
    } catch (const ExprError& x) {
        return fmt::format("{}: {} = <{}>\n", d.number, d.expr.text(), x.message);
    }
}

std::string Console::show_displays() {
    std::string out;
    for (const Display& d : displays_) out += show_display(d);
    return out;
}

std::string Console::cmd_display(std::string_view a, int col) {
    const char f = take_format(a, col);
    if (a.empty()) return show_displays();
    ExprError err;
    auto e = Expr::parse(a, d_.program(), err, Expr::Names::RegistersFirst, col - 1, &vars_);
    if (!e) return error(err.col, err.message);
    displays_.push_back({++last_display_, f, std::move(*e)});
    return show_display(displays_.back());
}

std::string Console::cmd_undisplay(std::string_view a, int col) {
    if (a.empty()) {
        displays_.clear();
        return {};
    }
    return for_each_number(a, col, "display",
                           [&](int n) { return std::erase_if(displays_, [n](const Display& d) { return d.number == n; }) > 0; });
}

// x/NFU ADDRESS
std::string Console::cmd_x(std::string_view a, int col) {
    int count = 1;
    if (!a.empty() && a.front() == '/') {
        std::size_t i = 1;
        std::size_t n0 = i;
        while (i < a.size() && std::isdigit(static_cast<unsigned char>(a[i]))) ++i;
        if (i > n0) {  // digits beyond any int are a count out of range too, not a std::stoi error
            const std::string_view digits = a.substr(n0, i - n0);
            if (digits.size() > 4 || (count = std::stoi(std::string(digits))) < 1 || count > 4096)
                return error(col + static_cast<int>(n0), fmt::format("bad count '{}' in x/NFU: a count from 1 to 4096", digits));
        }
        for (; i < a.size() && !std::isspace(static_cast<unsigned char>(a[i])); ++i) {
            const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(a[i])));
            if (std::string_view("xduotcasi").find(c) != std::string_view::npos) x_format_ = c;
            else if (c == 'b' || c == 'h' || c == 'w') x_unit_ = c == 'b' ? 'b' : 'w';
            else return error(col + static_cast<int>(i), fmt::format("unknown format letter '{}' (x d u o t c a s i; b w)", a[i]));
        }
        col += static_cast<int>(i);
        a = trim_blanks(a.substr(i), &col);
    }
    if (count < 1 || count > 4096) return error(col, "a count from 1 to 4096");
    std::uint16_t addr = next_x_;
    if (!a.empty()) {
        std::int64_t v = 0;
        if (std::string e = evaluate(a, col, Expr::Names::SymbolsFirst, v); !e.empty()) return e;
        addr = static_cast<std::uint16_t>(v);
    }
    return examine(addr, count, x_format_, x_unit_, next_x_);
}

std::string Console::examine(std::uint16_t addr, int count, char f, char unit, std::uint16_t& next) {
    const Machine& m = d_.machine();
    std::string out;
    auto label = [&](std::uint16_t at) {
        const auto n = d_.program().data_name_at(at);  // a label or an address EQU, not a constant
        return n ? fmt::format("{} <{}>", hex4h(at), *n) : hex4h(at);
    };
    if (f == 'i') {
        for (int i = 0; i < count; ++i) {
            const auto dis = disassemble(m.bus(), addr, m.cpu().variant(), &d_.program());
            const auto routine = d_.program().routine_at(addr);  // code: named by its routine, as gdb's <main+4>
            out += fmt::format("{}{}:\t{}\n", addr == m.cpu().regs().pc ? "=> " : "   ",
                               routine ? fmt::format("{} <{}>", hex4h(addr), *routine) : hex4h(addr), dis.text);
            addr = static_cast<std::uint16_t>(addr + dis.length);
        }
    } else if (f == 's') {
        for (int i = 0; i < count; ++i) {
            std::string s;
            const std::uint16_t start = addr;
            for (int k = 0; k < 256; ++k) {
                const std::uint8_t b = m.peek(addr);
                addr = static_cast<std::uint16_t>(addr + 1);
                if (b == 0) break;
                s += b >= 0x20 && b < 0x7F ? static_cast<char>(b) : '.';
            }
            out += fmt::format("{}:\t\"{}\"\n", label(start), s);
        }
    } else {
        const int per_line = unit == 'b' ? 8 : 4;
        for (int i = 0; i < count;) {
            const std::uint16_t line_start = addr;
            std::string vals, ascii;
            for (int k = 0; k < per_line && i < count; ++k, ++i) {
                if (unit == 'b') {
                    const std::uint8_t b = m.peek(addr);
                    vals += ' ' + (f == 'a' ? fmt::format("{:02X}", b) : format_value(b, 8, f == 'c' ? 'c' : f));
                    ascii += b >= 0x20 && b < 0x7F ? static_cast<char>(b) : '.';
                    addr = static_cast<std::uint16_t>(addr + 1);
                } else {
                    const auto w = static_cast<std::uint16_t>(m.peek(addr) | m.peek(static_cast<std::uint16_t>(addr + 1)) << 8);
                    vals += ' ' + format_value(w, 16, f == 'a' || f == 'c' ? 'x' : f);
                    addr = static_cast<std::uint16_t>(addr + 2);
                }
            }
            out += fmt::format("{}:{}{}\n", label(line_start), vals, f == 'a' && unit == 'b' ? "  |" + ascii + "|" : "");
        }
    }
    next = addr;
    return out;
}

// list FIRST,LAST (either may be left out): lines of one file; each end a line number (of the file
// listed last, or the PC's), FILE:LINE, or a location.
std::string Console::list_range(std::string_view a, int col) {
    constexpr std::int64_t kMaxLine = 1'000'000;  // no source here is longer; keeps the arithmetic in range
    const auto comma = a.find(',');
    std::optional<SourceLine> here = next_list_ ? next_list_ : d_.program().line_of(d_.machine().cpu().regs().pc);
    auto end_of = [&](std::string_view t, int at, std::optional<SourceLine>& out) -> std::string {
        t = trim_blanks(t, &at);
        if (t.empty()) return {};
        if (const auto n = parse_int(t); n && t.find_first_not_of("0123456789") == std::string_view::npos) {
            if (*n < 1 || *n > kMaxLine) return error(at, fmt::format("bad line number '{}'", t));
            if (!here) return error(at, "no file to list yet: list FILE:LINE,LINE");
            out = SourceLine{here->file, static_cast<int>(*n)};
            return {};
        }
        const auto loc = d_.locate(t);
        if (!loc.error.empty()) return error(at + std::max(loc.col, 1) - 1, loc.error);
        out = d_.program().line_of(loc.addresses.front());
        if (!out) return error(at, fmt::format("no source line for {}", hex4h(loc.addresses.front())));
        if (const auto colon = t.rfind(':'); colon != std::string_view::npos)
            if (const auto n = parse_int(t.substr(colon + 1)); n && *n >= 1 && *n <= kMaxLine) out->line = static_cast<int>(*n);
        return {};
    };
    std::optional<SourceLine> first, last;
    if (std::string e = end_of(a.substr(0, comma), col, first); !e.empty()) return e;
    if (std::string e = end_of(a.substr(comma + 1), col + static_cast<int>(comma) + 1, last); !e.empty()) return e;
    if (!first && !last) return error(col, "expected FIRST,LAST (line numbers or locations)");
    if (!first) first = SourceLine{last->file, std::max(1, last->line - 9)};
    if (!last) last = SourceLine{first->file, first->line + 9};
    if (first->file != last->file) return error(col, "FIRST and LAST are in different files");
    if (last->line < first->line) return error(col, "a range is FIRST,LAST with FIRST <= LAST");
    return list_lines(first->file, first->line, std::min(last->line, first->line + 9999), col);
}

std::string Console::list_lines(const std::string& file, int first, int last, int col) {
    const auto pc_line = d_.program().line_of(d_.machine().cpu().regs().pc);
    std::string out;
    for (int l = std::max(1, first); l <= last; ++l) {
        const auto src = source_line({file, l});
        if (!src) {
            if (l == std::max(1, first)) return error(col, fmt::format("line {} is beyond {} (or it cannot be read)", l, file_name(file)));
            break;
        }
        const bool here = pc_line && pc_line->file == file && pc_line->line == l;
        bool bp = false;
        for (const Breakpoint& b : d_.breakpoints())
            if (b.line && b.line->file == file && b.line->line == l) bp = true;
        out += fmt::format("{}{}{:>5}\t{}\n", here ? "=>" : "  ", bp ? 'B' : ' ', l, *src);
    }
    next_list_ = SourceLine{file, last + 1};  // a plain list goes on after LAST
    return out;
}

std::string Console::cmd_list(std::string_view a, int col) {
    if (a.find(',') != std::string_view::npos) return list_range(a, col);
    std::optional<SourceLine> center;
    if (a.empty()) {
        center = next_list_ ? next_list_ : frame_line_ ? frame_line_ : d_.program().line_of(d_.machine().cpu().regs().pc);
        if (next_list_) center->line += 5;  // continues after the last listing
    } else {
        const auto colon = a.rfind(':');
        if (colon != std::string_view::npos && colon > 0 && std::isdigit(static_cast<unsigned char>(a[colon + 1]))) {
            const auto loc = d_.locate(a);  // FILE:LINE names the file as loaded
            if (!loc.error.empty()) return error(col, loc.error);
            center = SourceLine{d_.program().line_of(loc.addresses.front())->file, std::stoi(std::string(a.substr(colon + 1)))};
        } else {
            const auto loc = d_.locate(a);
            if (!loc.error.empty()) return error(col + std::max(loc.col, 1) - 1, loc.error);
            center = d_.program().line_of(loc.addresses.front());
            if (!center) return error(col, fmt::format("no source line for {}", hex4h(loc.addresses.front())));
        }
    }
    if (!center) return error(col, "no source line for the PC (list LOCATION or FILE:LINE)");
    const auto pc_line = d_.program().line_of(d_.machine().cpu().regs().pc);
    std::string out;
    const int first = std::max(1, center->line - 5);
    for (int l = first; l < first + 10; ++l) {
        const auto src = source_line({center->file, l});
        if (!src) {
            if (l == first) return error(col, fmt::format("cannot read the source {}", center->file));
            break;
        }
        const bool here = pc_line && pc_line->file == center->file && pc_line->line == l;
        bool bp = false;
        for (const Breakpoint& b : d_.breakpoints())
            if (b.line && b.line->file == center->file && b.line->line == l) bp = true;
        out += fmt::format("{}{}{:>5}\t{}\n", here ? "=>" : "  ", bp ? 'B' : ' ', l, *src);
    }
    next_list_ = SourceLine{center->file, first + 10};  // a plain list goes on after these ten
    return out;
}

std::string Console::cmd_disassemble(std::string_view a, int col) {
    const Machine& m = d_.machine();
    std::uint16_t addr = m.cpu().regs().pc;
    int count = 12;
    if (!a.empty()) {
        // LOCATION [N]
        std::string_view loc_text = a;
        const auto sp = a.rfind(' ');
        if (sp != std::string_view::npos) {
            const auto n = parse_int(trim_blanks(a.substr(sp + 1)));
            if (n && *n > 0 && *n <= 4096) {
                count = static_cast<int>(*n);
                loc_text = trim_blanks(a.substr(0, sp));
            }
        }
        const auto loc = d_.locate(loc_text);
        if (!loc.error.empty()) return error(col + std::max(loc.col, 1) - 1, loc.error);
        addr = loc.addresses.front();
    } else {
        // From the start of the routine the PC is in (its label), as gdb shows a function.
        for (int back = 0; back < 64 && back <= addr; ++back)
            if (d_.program().label_at(static_cast<std::uint16_t>(addr - back))) {
                addr = static_cast<std::uint16_t>(addr - back);
                break;
            }
    }
    std::string out;
    for (int i = 0; i < count; ++i) {
        if (const auto l = d_.program().label_at(addr)) out += fmt::format("{}:\n", *l);
        const auto dis = disassemble(m.bus(), addr, m.cpu().variant(), &d_.program());
        std::string bytes;
        for (int k = 0; k < dis.length; ++k) bytes += fmt::format("{:02X} ", dis.bytes[k]);
        const auto line = d_.program().line_of(addr);
        bool bp = false;
        for (const Breakpoint& b : d_.breakpoints()) bp = bp || b.address == addr;
        out += fmt::format("{}{} {}  {:<9} {:<20}{}\n", addr == m.cpu().regs().pc ? "=>" : "  ", bp ? 'B' : ' ', hex4h(addr), bytes,
                           dis.text, line ? fmt::format("; {}:{}", file_name(line->file), line->line) : "");
        addr = static_cast<std::uint16_t>(addr + dis.length);
    }
    return out;
}

std::string Console::cmd_backtrace(std::string_view, int) {
    std::string out;
    const auto frames = d_.backtrace();
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const Frame& f = frames[i];
        out += fmt::format("#{:<2} {} in {}", i, hex4h(f.pc), f.routine ? *f.routine : "??");
        if (i > 0) out += fmt::format(" (return address at {})", hex4h(f.slot));
        if (f.line) out += fmt::format(" at {}:{}", file_name(f.line->file), f.line->line);
        out += '\n';
    }
    return out;
}

// The CPU's description (emu/core/cpu_registers.h) as rows: each pair's two bytes, then the pair
// (an address register's value; the flag register's flags) and the memory it addresses ([HL]);
// then the registers that stand alone (SP, PC) and where the PC is in the source.
std::string Console::info_registers() {
    const cpu::Description& desc = cpu::description();
    const I8085& cpu = d_.machine().cpu();
    const Registers& r = cpu.regs();
    const std::uint8_t rim = cpu.rim_value();
    auto shown = [&](const cpu::Register& x) { return fmt::format("{:<2} {}", x.name, x.hex(x.read(r))); };
    std::string out;
    for (const cpu::Register& pair : desc.registers) {
        if (pair.kind != cpu::Register::Kind::Pair) continue;
        const cpu::Register* hi = desc.find(pair.high);
        const cpu::Register* lo = desc.find(pair.low);
        out += shown(*hi) + "   " + shown(*lo) + "   ";
        if (lo->kind == cpu::Register::Kind::Flags) {
            const auto f = static_cast<std::uint8_t>(lo->read(r));
            std::string documented, undocumented;
            for (const cpu::Flag& flag : desc.flags) {
                std::string& group = flag.documented ? documented : undocumented;
                group += fmt::format("{}{}={}", group.empty() ? "" : " ", flag.name, (f & flag.bit) ? 1 : 0);
            }
            out += documented + (undocumented.empty() ? "" : "  " + undocumented);
        } else if (pair.address) {
            out += shown(pair);
        }
        for (const cpu::Register& m : desc.registers)
            if (m.kind == cpu::Register::Kind::Memory && m.high == pair.name)
                out += fmt::format("   [{}] {:02X}H", pair.name, d_.machine().peek(pair.read(r)));
        while (out.back() == ' ') out.pop_back();
        out += '\n';
    }
    std::string alone;
    for (const cpu::Register& x : desc.registers)
        if (desc.standalone(x)) alone += (alone.empty() ? "" : "   ") + shown(x);
    out += alone;
    if (const auto line = d_.program().line_of(r.pc)) out += fmt::format("   {}:{}", file_name(line->file), line->line);
    out += '\n';
    out += fmt::format("interrupts {}  masks M7.5={} M6.5={} M5.5={}  pending I7.5={} I6.5={} I5.5={} TRAP={}\n",
                       cpu.interrupts_enabled() ? "enabled" : "disabled", (rim >> 2) & 1, (rim >> 1) & 1, rim & 1, (rim >> 6) & 1,
                       (rim >> 5) & 1, (rim >> 4) & 1, cpu.trap_latched() ? 1 : 0);
    out += fmt::format("SID={} SOD={}  {}  T = {} ({:.3f} ms)\n", (rim >> 7) & 1, cpu.sod() ? 1 : 0,
                       cpu.halted() ? "HALTED" : "running", d_.machine().now(), board::ms_from_tstates(d_.machine().now()));
    return out;
}

std::string Console::info_breakpoints(bool watchpoints_only) {
    if (watchpoints_only && d_.watchpoints().empty()) return "No watchpoints.\n";
    if (d_.breakpoints().empty() && d_.watchpoints().empty()) return "No breakpoints or watchpoints.\n";
    std::string out = "Num  Type            Enb  Where\n";
    struct Row {
        int number;
        std::string text;
    };
    std::vector<Row> rows;
    for (const Breakpoint& b : d_.breakpoints()) {
        if (watchpoints_only) break;
        std::string s = fmt::format("{:<4} {:<15} {:<4} {}", b.number, b.temporary ? "tbreakpoint" : "breakpoint", b.enabled ? "y" : "n",
                                    hex4h(b.address));
        if (const auto n = d_.program().routine_at(b.address)) s += " in " + *n;
        if (b.line) s += fmt::format(" at {}:{}", file_name(b.line->file), b.line->line);
        s += '\n';
        if (b.condition) s += fmt::format("        stop only if {}\n", b.condition->text());
        if (b.hits) s += fmt::format("        breakpoint already hit {} time{}\n", b.hits, b.hits == 1 ? "" : "s");
        if (b.ignore) s += fmt::format("        will ignore next {} crossings\n", b.ignore);
        for (const std::string& c : b.commands) s += fmt::format("        {}\n", c);
        rows.push_back({b.number, s});
    }
    for (const Watchpoint& w : d_.watchpoints()) {
        const char* type = w.kind == WatchKind::Read ? "read watchpoint" : w.kind == WatchKind::Access ? "acc watchpoint" : "watchpoint";
        std::string s = fmt::format("{:<4} {:<15} {:<4} {}\n", w.number, type, w.enabled ? "y" : "n", w.what);
        if (w.condition) s += fmt::format("        stop only if {}\n", w.condition->text());
        if (w.hits) s += fmt::format("        watchpoint already hit {} time{}\n", w.hits, w.hits == 1 ? "" : "s");
        if (w.ignore) s += fmt::format("        will ignore next {} hits\n", w.ignore);
        for (const std::string& c : w.commands) s += fmt::format("        {}\n", c);
        rows.push_back({w.number, s});
    }
    std::sort(rows.begin(), rows.end(), [](const Row& x, const Row& y) { return x.number < y.number; });
    for (const Row& r : rows) out += r.text;
    return out;
}

std::string Console::info_displays() {
    if (displays_.empty()) return "There are no auto-display expressions now.\n";
    std::string out = "Auto-display expressions now in effect:\n";
    for (const Display& d : displays_) out += fmt::format("{}:   {}\n", d.number, d.expr.text());
    return out;
}

namespace {
// Entries (the FIFO's, display RAM's: each named by its position, no meaning of its own) are
// listed on their field's line; registers' bit fields and other values get a line each.
bool plain_entries(const periph::Field& f) {
    if (f.fields.empty()) return false;
    for (std::size_t i = 0; i < f.fields.size(); ++i) {
        const periph::Field& c = f.fields[i];
        if (c.name != std::to_string(i) || !c.fields.empty() || !c.text.empty() || c.shown == periph::Field::Shown::Text) return false;
    }
    return true;
}
void render(const std::vector<periph::Field>& fields, int indent, std::string& out) {
    std::size_t w = 0;
    for (const periph::Field& f : fields) w = std::max(w, f.name.size());
    for (const periph::Field& f : fields) {
        std::string line = fmt::format("{:{}}{:<{}}  {}", "", indent, f.name, w, f.shown_value());
        if (plain_entries(f)) {
            std::string list;
            for (const periph::Field& c : f.fields) list += (list.empty() ? "" : " ") + c.number();
            if (list != f.text) line += ": " + list;
        }
        out += line + '\n';
        if (!plain_entries(f)) render(f.fields, indent + 4, out);
    }
}
}  // namespace

std::pair<periph::Part*, std::size_t> Console::part_named(const std::vector<std::string>& words) const {
    periph::Part* best = nullptr;
    std::size_t best_n = 0;
    for (periph::Part* p : d_.machine().parts()) {
        // the part's name word by word (longest match: "machine tool" before a part named "machine")
        std::vector<std::string> name;
        const std::string up = to_upper(p->name());
        for (std::size_t i = 0; i < up.size();) {
            const auto sp = up.find(' ', i);
            name.push_back(up.substr(i, sp == std::string::npos ? std::string::npos : sp - i));
            i = sp == std::string::npos ? up.size() : sp + 1;
        }
        if (name.size() <= words.size() && name.size() > best_n && std::equal(name.begin(), name.end(), words.begin()))
            best = p, best_n = name.size();
    }
    return {best, best_n};
}

std::string Console::info_part(const periph::Part& part) {
    const periph::Description d = d_.describe(part);
    if (d.empty()) return fmt::format("The {} has nothing to show.\n", part.name());
    std::string out = (d.title.empty() ? std::string(part.name()) : d.title) + '\n';
    render(d.fields, 2, out);
    return out;
}

std::string Console::info_axis(std::string_view which, int col) {
    const periph::MachineTool& t = d_.machine().tool();
    std::string up = to_upper(which);
    if (!up.empty() && (up.size() != 1 || up[0] < 'X' || up[0] > 'Z')) return error(col, "expected: info axis [X|Y|Z]");
    std::string out = fmt::format("machine tool: {} motors, transducers read the {}\n",
                                  t.model() == periph::MachineTool::MotorModel::Ideal ? "ideal" : "physical",
                                  t.feedback() == periph::MachineTool::Feedback::Scale ? "scale" : "commanded steps");
    for (int a = 0; a < 3; ++a) {
        if (!up.empty() && up[0] != "XYZ"[a]) continue;
        const auto ax = static_cast<periph::MachineTool::Axis>(a);
        const auto stop = t.end_stop(ax);
        out += fmt::format("  {}  {:6} steps {:9.3f} mm  count {:6}  commanded {:6}  lost {:3}  phases {:X}H  {:.1f} rad/s{}{}\n", "XYZ"[a],
                           std::llround(t.table_steps(ax)), t.table_mm(ax), t.transducer_count(ax), t.commanded_steps(ax), t.lost_steps(ax),
                           t.phase_pattern(ax), t.rotor_speed_rad_s(ax), t.settled(ax) ? "  settled" : "",
                           stop.at ? (stop.at > 0 ? "  at its high end stop" : "  at its low end stop") : "");
    }
    return out;
}

std::string Console::info_display() {
    std::string out;
    for (const std::string& l : d_.machine().display_art()) out += l + '\n';
    return out + fmt::format("\"{}\"\n", d_.machine().display_text());
}

std::string Console::cmd_info(std::string_view a, int col) {
    int wcol = col;
    const std::string what = to_upper(a.substr(0, a.find(' ')));
    std::string_view rest = a.size() > what.size() ? trim_blanks(a.substr(what.size()), &wcol) : std::string_view{};
    wcol += static_cast<int>(what.size());
    if (what == "R" || what == "REG" || what == "REGISTERS" || what == "ALL-REGISTERS") return info_registers();
    if (what == "B" || what == "BR" || what == "BREAK" || what == "BREAKPOINTS") return info_breakpoints();
    if (what == "WAT" || what == "WATCH" || what == "WATCHPOINTS") return info_breakpoints(true);
    if (what == "SYMBOL" || what == "SYM") return info_symbol(rest, wcol);
    if (what == "DISPLAYS") return info_displays();
    if (what == "DISPLAY") return info_display();
    if (what == "BOARD") return d_.machine().describe_board();
    {
        std::vector<std::string> words;  // a part by its name: info 8155, info machine tool
        for (std::size_t i = 0; i < a.size();) {
            const auto end = std::min(a.find(' ', i), a.size());
            if (end > i) words.push_back(to_upper(a.substr(i, end - i)));
            i = end + 1;
        }
        if (const auto [part, n] = part_named(words); part && n == words.size()) return info_part(*part);
    }
    if (what == "AXIS" || what == "AXES" || what == "TOOL") return info_axis(rest, wcol);
    if (what == "LINE" || what == "FRAME" || what == "F") return location_lines(d_.machine().cpu().regs().pc);
    if (what == "HISTORY") return fmt::format("history {}: {} snapshots from T = {}\n", d_.history() ? "on" : "off",
                                              d_.history_snapshots(), d_.history_start());
    std::string parts;
    for (const periph::Part* p : d_.machine().parts()) parts += fmt::format("{}, ", p->name());
    return error(col, what.empty() ? fmt::format("info what? registers, breakpoints, watchpoints, displays, display, board, {}axis, line, symbol, history", parts)
                                   : fmt::format("no 'info {}' (registers, breakpoints, watchpoints, displays, display, board, {}axis, line, symbol, history)", a, parts));
}

std::string Console::cmd_timing(std::string_view a, int col) {
    if (!a.empty()) return error(col, "timing takes no argument: it shows the next instruction's machine cycles");
    const Machine& m = d_.machine();
    if (m.cpu().variant() != Variant::I8085) return error(col, "timing draws the 8085's machine cycles (this session runs an 8080)");
    const Registers& r = m.cpu().regs();
    const auto dis = disassemble(m.bus(), r.pc, m.cpu().variant(), &d_.program());
    return fmt::format("{}\t{}\n", hex4h(r.pc), dis.text) +
           cycles_text(instruction_cycles(r, [&m](std::uint16_t addr) { return m.peek(addr); }));
}

std::string Console::cmd_history(std::string_view a, int col) {
    std::size_t n = 10;
    if (!a.empty()) {
        std::string err;
        const auto v = number_arg(a, col, err);
        if (!v) return err;
        n = static_cast<std::size_t>(*v);
    }
    if (!d_.history()) return error(col, "history needs the snapshots of reverse execution (set history on)");
    const Machine& m = d_.machine();
    std::string out;
    for (const Executed& e : d_.last_instructions(n)) {
        const auto dis = disassemble(m.bus(), e.pc, m.cpu().variant(), &d_.program());
        std::string changed;
        auto reg8 = [&](const char* name, std::uint8_t x, std::uint8_t y) {
            if (x != y) changed += fmt::format(" {}={:02X}H", name, y);
        };
        reg8("A", e.before.a, e.after.a);
        reg8("F", e.before.f, e.after.f);
        reg8("B", e.before.b, e.after.b);
        reg8("C", e.before.c, e.after.c);
        reg8("D", e.before.d, e.after.d);
        reg8("E", e.before.e, e.after.e);
        reg8("H", e.before.h, e.after.h);
        reg8("L", e.before.l, e.after.l);
        if (e.before.sp != e.after.sp) changed += fmt::format(" SP={:04X}H", e.after.sp);
        out += fmt::format("{:>12}  {}  {:<20}{}\n", e.at, hex4h(e.pc), dis.text, changed);
    }
    if (out.empty()) out = "No instructions in the history.\n";
    return out;
}

}  // namespace alp85::debug
