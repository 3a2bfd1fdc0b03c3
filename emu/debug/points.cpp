// Breakpoints and watchpoints: locations, numbers, conditions, ignore counts, commands; frames.
#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "asm/isa.h"
#include "emu/debug/debugger.h"
#include "emu/debug/observer.h"
#include "emu/util/text.h"

namespace alp85::debug {

Debugger::Location Debugger::locate_line(std::string_view file, int line) const {
    Location loc;
    const std::optional<SourceLine> next = program_.next_line_with_code(file, line);
    if (!next) {
        loc.error = fmt::format("no code at or after {}:{} in the loaded programs", file, line);
        return loc;
    }
    loc.addresses = program_.addresses_of(next->file, next->line);
    if (next->line != line) loc.bound = next;
    return loc;
}

Debugger::Location Debugger::locate(std::string_view text) const {
    Location loc;
    std::size_t lead = 0;
    while (lead < text.size() && std::isspace(static_cast<unsigned char>(text[lead]))) ++lead;
    std::string_view t = text.substr(lead);
    while (!t.empty() && std::isspace(static_cast<unsigned char>(t.back()))) t.remove_suffix(1);
    if (t.empty()) {
        loc.error = "expected a location (an address, a symbol or FILE:LINE)";
        loc.col = static_cast<int>(lead) + 1;
        return loc;
    }
    // FILE:LINE (the line a decimal number).
    const auto colon = t.rfind(':');
    if (colon != std::string_view::npos && colon > 0) {
        const std::string_view num = t.substr(colon + 1);
        if (!num.empty() && std::all_of(num.begin(), num.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
            if (num.size() > 9) {  // beyond an int: no source file is that long
                loc.error = fmt::format("line number {} is out of range", num);
                loc.col = static_cast<int>(lead + colon) + 2;
                return loc;
            }
            loc = locate_line(t.substr(0, colon), std::stoi(std::string(num)));
            if (!loc.error.empty()) loc.col = static_cast<int>(lead) + 1;
            return loc;
        }
        loc.error = "expected FILE:LINE with a line number";
        loc.col = static_cast<int>(lead + colon) + 2;
        return loc;
    }
    if (t.front() == '*') {  // gdb's *ADDRESS
        t.remove_prefix(1);
        ++lead;
    }
    ExprError err;
    const auto e = Expr::parse(t, program_, err, Expr::Names::SymbolsFirst, static_cast<int>(lead), &vars_);
    if (!e) {
        loc.error = err.message;
        loc.col = err.col;
        return loc;
    }
    try {
        const std::int64_t v = e->eval(m_);
        if (v < 0 || v > 0xFFFF) {
            loc.error = fmt::format("address {} is outside 0000H-FFFFH", v);
            loc.col = static_cast<int>(lead) + 1;
            return loc;
        }
        loc.addresses.push_back(static_cast<std::uint16_t>(v));
    } catch (const ExprError& x) {
        loc.error = x.message;
        loc.col = static_cast<int>(lead) + x.col;
    }
    return loc;
}

Debugger::Added Debugger::add_breakpoint(std::string_view location, bool temporary, std::string_view condition) {
    Added a;
    const Location loc = locate(location);
    if (!loc.error.empty()) {
        a.error = loc.error;
        a.col = loc.col;
        return a;
    }
    std::optional<Expr> cond;
    if (!condition.empty()) {
        ExprError err;
        cond = Expr::parse(condition, program_, err, Expr::Names::RegistersFirst, 0, &vars_);
        if (!cond) {
            a.error = err.message;
            a.col = err.col;
            a.in_condition = true;
            return a;
        }
    }
    for (std::uint16_t addr : loc.addresses) {
        Breakpoint b;
        b.number = next_number();
        b.address = addr;
        b.location = std::string(location);
        b.line = program_.line_of(addr);
        b.temporary = temporary;
        b.condition = cond;
        breakpoints_.push_back(std::move(b));
        if (!a.number) a.number = breakpoints_.back().number;
    }
    a.bound = loc.bound;
    arm();
    return a;
}

Debugger::Added Debugger::add_breakpoint_at(std::uint16_t address, bool temporary) {
    return add_breakpoint(fmt::format("{:04X}H", address), temporary);
}

Debugger::Added Debugger::add_watchpoint(const WatchSpec& spec, std::string_view condition) {
    Added a;
    Watchpoint w;
    w.kind = spec.kind;
    w.what = spec.what;
    w.first = spec.first;
    w.last = spec.last;
    w.dir = spec.dir;
    w.value = spec.value;
    w.quantity = spec.quantity;
    w.axis = spec.axis;
    w.part = spec.part;
    w.field = spec.field;
    if (w.kind == WatchKind::Part) {
        const periph::Part* p = m_.find_part(w.part);
        const periph::Description d = p ? describe(*p) : periph::Description{};
        const periph::Field* f = d.find_watch(w.field);
        if (!f) {
            a.error = p ? fmt::format("the {} has no '{}' to watch", w.part, w.field) : fmt::format("no part '{}'", w.part);
            return a;
        }
        w.digits = f->digits();
    }
    if (w.last < w.first) std::swap(w.first, w.last);
    if (!condition.empty()) {
        ExprError err;
        w.condition = Expr::parse(condition, program_, err, Expr::Names::RegistersFirst, 0, &vars_);
        if (!w.condition) {
            a.error = err.message;
            a.col = err.col;
            a.in_condition = true;
            return a;
        }
    }
    w.number = next_number();
    a.number = w.number;
    watchpoints_.push_back(std::move(w));
    rebaseline();
    arm();
    return a;
}

Breakpoint* Debugger::find_bp(int n) {
    auto it = std::find_if(breakpoints_.begin(), breakpoints_.end(), [n](const Breakpoint& b) { return b.number == n; });
    return it == breakpoints_.end() ? nullptr : &*it;
}
Watchpoint* Debugger::find_wp(int n) {
    auto it = std::find_if(watchpoints_.begin(), watchpoints_.end(), [n](const Watchpoint& w) { return w.number == n; });
    return it == watchpoints_.end() ? nullptr : &*it;
}
const Breakpoint* Debugger::breakpoint(int n) const { return const_cast<Debugger*>(this)->find_bp(n); }
const Watchpoint* Debugger::watchpoint(int n) const { return const_cast<Debugger*>(this)->find_wp(n); }

bool Debugger::remove(int n) {
    const std::size_t before = breakpoints_.size() + watchpoints_.size();
    std::erase_if(breakpoints_, [n](const Breakpoint& b) { return b.number == n; });
    std::erase_if(watchpoints_, [n](const Watchpoint& w) { return w.number == n; });
    arm();
    return breakpoints_.size() + watchpoints_.size() != before;
}

void Debugger::remove_all() {
    breakpoints_.clear();
    watchpoints_.clear();
    arm();
}

bool Debugger::remove_breakpoints_at(std::uint16_t address) {
    const std::size_t before = breakpoints_.size();
    std::erase_if(breakpoints_, [address](const Breakpoint& b) { return b.address == address; });
    arm();
    return breakpoints_.size() != before;
}

bool Debugger::enable(int n, bool on) {
    if (Breakpoint* b = find_bp(n)) b->enabled = on;
    else if (Watchpoint* w = find_wp(n)) w->enabled = on;
    else return false;
    rebaseline();
    arm();
    return true;
}

std::string Debugger::set_condition(int n, std::string_view condition, int& col) {
    std::optional<Expr> cond;
    if (!condition.empty()) {
        ExprError err;
        cond = Expr::parse(condition, program_, err, Expr::Names::RegistersFirst, 0, &vars_);
        if (!cond) {
            col = err.col;
            return err.message;
        }
    }
    if (Breakpoint* b = find_bp(n)) b->condition = std::move(cond);
    else if (Watchpoint* w = find_wp(n)) w->condition = std::move(cond);
    else return fmt::format("no breakpoint or watchpoint number {}", n);
    return {};
}

bool Debugger::set_ignore(int n, unsigned count) {
    if (Breakpoint* b = find_bp(n)) b->ignore = count;
    else if (Watchpoint* w = find_wp(n)) w->ignore = count;
    else return false;
    return true;
}

bool Debugger::set_hits(int n, unsigned hits) {
    if (Breakpoint* b = find_bp(n)) b->hits = hits;
    else if (Watchpoint* w = find_wp(n)) w->hits = hits;
    else return false;
    return true;
}

bool Debugger::set_commands(int n, std::vector<std::string> commands) {
    if (Breakpoint* b = find_bp(n)) b->commands = std::move(commands);
    else if (Watchpoint* w = find_wp(n)) w->commands = std::move(commands);
    else return false;
    return true;
}

std::string Debugger::set_hit_condition(int n, std::string_view text) {
    std::optional<HitCondition> h;
    if (!text.empty()) {
        h = HitCondition::parse(text);
        if (!h) return fmt::format("hit condition '{}' is not N, ==N, >=N, >N, <N, <=N or %N", text);
    }
    if (Breakpoint* b = find_bp(n)) b->hit_condition = std::move(h);
    else if (Watchpoint* w = find_wp(n)) w->hit_condition = std::move(h);
    else return fmt::format("no breakpoint or watchpoint number {}", n);
    return {};
}

bool Debugger::set_log_message(int n, std::string message) {
    Breakpoint* b = find_bp(n);
    if (!b) return false;
    b->log_message = std::move(message);
    return true;
}

std::string Debugger::interpolate(std::string_view message) const {
    std::string out;
    std::size_t i = 0;
    while (i < message.size()) {
        const std::size_t open = message.find('{', i);
        if (open == std::string_view::npos) break;
        const std::size_t close = message.find('}', open);
        if (close == std::string_view::npos) break;
        out.append(message.substr(i, open - i));
        const Value v = evaluate(message.substr(open + 1, close - open - 1));
        if (!v.error.empty()) out += "<" + v.error + ">";
        else if (v.value < 0 || v.value > 0xFFFF) out += std::to_string(v.value);
        else out += fmt::format("{:0{}X}H ({})", v.value, v.width <= 8 ? 2 : 4, v.value);
        i = close + 1;
    }
    out.append(message.substr(i));
    return out;
}

bool HitCondition::met(std::uint64_t hits) const {
    switch (op) {
        case Op::Eq: return hits == n;
        case Op::Ge: return hits >= n;
        case Op::Gt: return hits > n;
        case Op::Lt: return hits < n;
        case Op::Le: return hits <= n;
        case Op::Every: return n != 0 && hits % n == 0;
    }
    return false;
}

std::optional<HitCondition> HitCondition::parse(std::string_view text) {
    HitCondition h;
    h.text = std::string(text);
    std::string_view s = trim_blanks(text);
    static constexpr std::pair<std::string_view, Op> kOps[] = {{">=", Op::Ge}, {"<=", Op::Le}, {"==", Op::Eq}, {">", Op::Gt},
                                                               {"<", Op::Lt},  {"%", Op::Every}, {"=", Op::Eq}};
    for (const auto& [word, op] : kOps)
        if (s.starts_with(word)) {
            h.op = op;
            s = trim_blanks(s.substr(word.size()));
            break;
        }
    if (s.empty() || s.size() > 19) return std::nullopt;
    std::uint64_t n = 0;
    for (const char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        n = n * 10 + static_cast<std::uint64_t>(c - '0');
    }
    h.n = n;
    return h;
}

std::vector<std::string> Debugger::commands_for(const Stop& s) const {
    if (s.reason == StopReason::Breakpoint)
        if (const Breakpoint* b = breakpoint(s.number)) return b->commands;
    if (s.reason == StopReason::Watchpoint)
        if (const Watchpoint* w = watchpoint(s.number)) return w->commands;
    return {};
}

// ---- frames -----------------------------------------------------------------------------------------
// The stack holds return addresses among pushed data; a word is taken for one when the bytes
// before it are a CALL (or a conditional call), or an RST in code a loaded program placed there.
// That finds every frame of CALL/RET code, including code that leaves without RET (the thesis's
// LEAVE pops its return address); an interrupt's frame has no CALL before it and is not shown.

namespace {
constexpr int kMaxFrames = 64;
// The routine a return address `w` came from: the target of the CALL (or RST) just before it;
// nullopt when no call instruction is there. RST 7 (FFH) is what erased EPROM reads: not a call.
std::optional<std::uint16_t> called_from(const Machine& m, const SymbolTable& program, std::uint16_t w) {
    const bool i8080 = m.cpu().variant() == Variant::I8080;
    const isa::Flow call = isa::flow_of(m.peek(static_cast<std::uint16_t>(w - 3)), i8080);
    if (call == isa::Flow::Call || call == isa::Flow::CallIf)
        return static_cast<std::uint16_t>(m.peek(static_cast<std::uint16_t>(w - 2)) | m.peek(static_cast<std::uint16_t>(w - 1)) << 8);
    const auto at = static_cast<std::uint16_t>(w - 1);
    const std::uint8_t rst = m.peek(at);
    if (rst == 0xFF || !program.line_of(at)) return std::nullopt;
    switch (isa::flow_of(rst, i8080)) {
        case isa::Flow::Restart: return rst & 0x38;
        case isa::Flow::RestartIf: return 0x40;  // RSTV
        default: return std::nullopt;
    }
}
// The CALL (or RST) that pushed the return address `w` (called_from found one there).
std::uint16_t call_site(const Machine& m, std::uint16_t w) {
    const auto call = static_cast<std::uint16_t>(w - 3);
    const isa::Flow f = isa::flow_of(m.peek(call), m.cpu().variant() == Variant::I8080);
    return f == isa::Flow::Call || f == isa::Flow::CallIf ? call : static_cast<std::uint16_t>(w - 1);
}
}  // namespace

std::optional<std::uint16_t> Debugger::return_slot() const {
    const std::vector<Frame> f = backtrace();
    if (f.size() < 2) return std::nullopt;
    return f[1].slot;
}

std::uint16_t Debugger::where() const {
    const std::uint16_t pc = m_.cpu().regs().pc;
    const auto hlt = static_cast<std::uint16_t>(pc - 1);
    return m_.cpu().halted() && m_.peek(hlt) == 0x76 ? hlt : pc;
}

std::vector<Frame> Debugger::backtrace() const {
    std::vector<Frame> frames;
    const Registers& r = m_.cpu().regs();
    const std::uint16_t at = where();
    frames.push_back({at, 0, program_.routine_at(at), program_.line_of(at)});
    // A frame is accepted when its call's target is at or a little before the frame inside it
    // (a routine's code follows its entry); the first call-like word that does not chain ends the
    // stack: above it lie words of an older stack (the monitor's, before LXI SP). So does a gap of
    // more than 16 words without a return address (no routine here keeps that much on the stack).
    constexpr std::uint16_t kRoutineReach = 0x800;
    constexpr std::uint32_t kMaxGap = 32;
    std::uint32_t last_slot = r.sp;
    std::uint16_t inner = r.pc;
    const std::optional<std::uint16_t> base = stack_base();
    std::uint32_t slot = r.sp;
    for (int i = 0; i < 256 && frames.size() < kMaxFrames && slot + 1 <= 0xFFFF; ++i, slot += 2) {
        const auto s = static_cast<std::uint16_t>(slot);
        if (m_.bus().page_kind(s) != Bus::PageKind::Ram) break;  // off the end of the stack's memory
        if (base && slot >= *base) break;           // older code's stack (track_stack_base)
        if (slot - last_slot > kMaxGap) break;
        const auto w = static_cast<std::uint16_t>(m_.peek(s) | m_.peek(static_cast<std::uint16_t>(s + 1)) << 8);
        const auto target = called_from(m_, program_, w);
        if (!target) continue;  // pushed data
        if (*target > inner || inner - *target >= kRoutineReach) break;
        // named as finish names it, at the line of its call (gdb's and DAP's "called from here")
        frames.push_back({w, s, program_.routine_at(w), program_.line_of(call_site(m_, w))});
        inner = w;
        last_slot = slot + 2;
    }
    return frames;
}

}  // namespace alp85::debug
