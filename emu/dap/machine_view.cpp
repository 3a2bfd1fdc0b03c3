#include "emu/dap/machine_view.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "asm/isa.h"
#include "emu/script/session.h"  // the CPU's description (cpu::description) with the rest of the board
#include "emu/util/text.h"

namespace alp85::dap {
namespace {

using cpu::Register;

std::string h2(std::uint8_t v) { return fmt::format("{:02X}H", v); }
std::string h4(std::uint16_t v) { return fmt::format("{:04X}H", v); }
std::string word_text(std::uint16_t v) { return fmt::format("{:04X}H ({})", v, v); }

// RAM symbols by address (the first name defined wins among equals, as SymbolTable::name_at).
std::map<std::uint16_t, std::string> ram_symbols(const debug::Debugger& d, const SymbolTable& t) {
    std::map<std::uint16_t, std::string> out;
    for (const auto& [name, value] : t.names())
        if (d.in_ram(value) && !out.contains(value)) out[value] = t.name_at(value).value_or(name);
    return out;
}

std::uint16_t read_word(const debug::Debugger& d, std::uint16_t a) {
    return static_cast<std::uint16_t>(d.peek(a) | d.peek(static_cast<std::uint16_t>(a + 1)) << 8);
}

// The flags in the order of their bits in F, from bit 7 (S Z K AC P V CY).
std::vector<cpu::Flag> flags_by_bit() {
    std::vector<cpu::Flag> f = cpu::description().flags;
    std::stable_sort(f.begin(), f.end(), [](const cpu::Flag& x, const cpu::Flag& y) { return x.bit > y.bit; });
    return f;
}

std::string flags_text(std::uint8_t f) {
    std::string s;
    for (const cpu::Flag& fl : flags_by_bit())
        if (f & fl.bit) s += std::string(s.empty() ? "" : " ") + std::string(fl.name);
    return fmt::format("{:02X}H [{}]", f, s);
}

// A register a client may read and set by name: any but memory (M), which the memory view shows.
const Register* register_named(std::string_view name) {
    const Register* r = cpu::description().find(name);
    return r && r->kind != Register::Kind::Memory ? r : nullptr;
}

Variable ro(std::string name, std::string value) { return {std::move(name), std::move(value), {}, 0, {}, true}; }

// The CPU's description (emu/core/cpu_registers.h): the byte registers, the flag register (its
// flags expand), then the registers that hold an address, with the memory there; a pair that
// holds no address (PSW) is its two bytes.
std::vector<Variable> registers(const debug::Debugger& d) {
    const cpu::Description& desc = cpu::description();
    std::vector<Variable> v;
    for (const Register& x : desc.registers)
        if (x.kind == Register::Kind::Byte) v.push_back({std::string(x.name), x.hex(d.reg(x)), "byte", 0, {}, false});
    for (const Register& x : desc.registers)
        if (x.kind == Register::Kind::Flags)
            v.push_back({std::string(x.name), flags_text(static_cast<std::uint8_t>(d.reg(x))), "flags", kFlagScope, {}, false});
    for (const Register& x : desc.registers) {
        if (x.width <= 8 || !x.address) continue;
        const std::uint16_t value = d.reg(x);
        v.push_back({std::string(x.name), x.kind == Register::Kind::Pair ? word_text(value) : h4(value), "word", 0, value, false});
    }
    const debug::CpuStatus c = d.cpu_status();
    v.push_back({"interrupts", fmt::format("{} masks {:03b}{}", c.interrupts_enabled ? "EI" : "DI",
                                           c.masks, c.halted ? " HALTED" : ""),
                 "", kInterruptScope, {}, true});
    return v;
}

std::vector<Variable> interrupts(const debug::Debugger& d) {
    const debug::CpuStatus c = d.cpu_status();
    return {ro("IE", c.interrupts_enabled ? "1" : "0"),
            ro("M7.5", c.masks & 4 ? "1 (masked)" : "0"),
            ro("M6.5", c.masks & 2 ? "1 (masked)" : "0"),
            ro("M5.5", c.masks & 1 ? "1 (masked)" : "0"),
            ro("RST 7.5 latch", c.rst75_latched ? "1" : "0"),
            ro("TRAP latch", c.trap_latched ? "1" : "0"),
            ro("SOD", c.sod ? "1" : "0"),
            ro("halted", c.halted ? "yes" : "no"),
            ro("T-states", std::to_string(d.now()))};
}

std::vector<Variable> firmware_variables(const debug::Debugger& d, const SymbolTable& t) {
    std::vector<Variable> v;
    for (const auto& [addr, name] : ram_symbols(d, t)) {
        const std::uint16_t size = variable_size(t, addr);
        Variable x{name, size == 1 ? h2(d.peek(addr)) : word_text(read_word(d, addr)), size == 1 ? "byte" : "word", 0, addr, false};
        x.type += " at " + h4(addr);
        v.push_back(std::move(x));
    }
    return v;
}

// A part's values as its description gives them; a value with fields expands to them (`ref`).
Variable part_variable(const periph::Field& f, std::int64_t ref) {
    return {f.name, f.shown_value(), f.watch.empty() ? "" : "watch: " + f.watch, f.fields.empty() ? 0 : ref, {}, true};
}

std::vector<Variable> part_variables(const debug::Debugger& d, std::int64_t ref) {
    const auto& parts = d.parts();
    const std::int64_t index = ref / kPartScope - 1, item = ref % kPartScope - 1;
    if (index < 0 || index >= static_cast<std::int64_t>(parts.size())) return {};
    const periph::Description desc = d.describe(*parts[static_cast<std::size_t>(index)]);
    std::vector<Variable> v;
    if (item < 0) {
        for (std::size_t j = 0; j < desc.fields.size(); ++j)
            v.push_back(part_variable(desc.fields[j], kPartScope * (index + 1) + static_cast<std::int64_t>(j) + 1));
    } else if (item < static_cast<std::int64_t>(desc.fields.size())) {
        for (const periph::Field& f : desc.fields[static_cast<std::size_t>(item)].fields) v.push_back(part_variable(f, 0));
    }
    return v;
}

std::vector<Variable> display(const debug::Debugger& d) {
    const auto digits = d.display();
    std::vector<Variable> v = {ro("text", "\"" + d.display_text() + "\"")};
    for (std::size_t i = 0; i < digits.size(); ++i) v.push_back(ro(fmt::format("digit {}", i), h2(digits[i])));
    return v;
}

}  // namespace

std::vector<ScopeInfo> scope_list(const debug::Debugger& d) {
    std::vector<ScopeInfo> out = {{"Registers", kRegisterScope, "registers"}, {"Firmware variables", kFirmwareScope, "locals"}};
    const auto& parts = d.parts();
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (d.describe(*parts[i]).fields.empty()) continue;
        std::string name(parts[i]->name());
        name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));  // "Machine tool"
        out.push_back({name, kPartScope * static_cast<std::int64_t>(i + 1), ""});
    }
    out.push_back({"Display", kDisplayScope, ""});
    return out;
}

std::vector<Variable> list_variables(const debug::Debugger& d, std::int64_t ref) {
    switch (ref) {
        case kRegisterScope: return registers(d);
        case kFlagScope: {
            const std::uint16_t f = d.reg(*cpu::description().flag_register());
            std::vector<Variable> v;
            for (const cpu::Flag& fl : flags_by_bit()) v.push_back({std::string(fl.name), f & fl.bit ? "1" : "0", "flag", 0, {}, false});
            return v;
        }
        case kInterruptScope: return interrupts(d);
        case kFirmwareScope: return firmware_variables(d, d.program());
        case kDisplayScope: return display(d);
        default: return ref >= kPartScope ? part_variables(d, ref) : std::vector<Variable>{};
    }
}

std::string assign_variable(debug::Debugger& d, std::int64_t ref, const std::string& name, std::int64_t value) {
    if (ref == kFlagScope) {
        const cpu::Flag* f = cpu::description().find_flag(name);
        if (!f) return fmt::format("no flag '{}'", name);
        if (value != 0 && value != 1) return "a flag is 0 or 1";
        const Register* fr = cpu::description().flag_register();
        const std::uint16_t now = d.reg(*fr);
        d.set_reg(*fr, static_cast<std::uint16_t>(value ? now | f->bit : now & ~f->bit));
        return {};
    }
    if (ref == kRegisterScope) {
        const Register* reg = register_named(name);
        if (!reg) return fmt::format("'{}' cannot be set", name);
        if (value < -(std::int64_t{1} << (reg->width - 1)) || value > reg->mask())
            return fmt::format("{} does not fit in {} bits", value, reg->width);
        d.set_reg(*reg, static_cast<std::uint16_t>(value & reg->mask()));
        return {};
    }
    if (ref == kFirmwareScope) {
        const auto addr = d.program().value_of(name);
        if (!addr) return fmt::format("no variable '{}'", name);
        const std::uint16_t size = variable_size(d.program(), *addr);
        if (value < (size == 1 ? -128 : -32768) || value > (size == 1 ? 0xFF : 0xFFFF))
            return fmt::format("{} does not fit in {}", value, size == 1 ? "a byte" : "a word");
        if (!d.poke(*addr, static_cast<std::uint8_t>(value))) return fmt::format("nothing at {:04X}H to write", *addr);
        if (size == 2) d.poke(static_cast<std::uint16_t>(*addr + 1), static_cast<std::uint8_t>(value >> 8));
        return {};
    }
    return "this value is read-only here (the console's commands change the devices)";
}

std::uint16_t variable_size(const SymbolTable& symbols, std::uint16_t address) {
    std::optional<std::uint16_t> next;
    for (const auto& [name, value] : symbols.names())
        if (value > address && (!next || value < *next)) next = value;
    return next && *next - address == 1 ? 1 : 2;
}

std::optional<std::string> expression_value(const debug::Debugger& d, const std::string& text, std::string& error) {
    std::string t = text;
    while (!t.empty() && t.front() == ' ') t.erase(0, 1);
    while (!t.empty() && t.back() == ' ') t.pop_back();
    // A firmware variable by its bare name shows what it holds (hovering over YAC); the
    // expression YAC is its address, as in the debugger's console.
    const std::string u = to_upper(t);
    if (!register_named(u) && !cpu::description().find_flag(u))
        if (const auto v = d.program().value_of(u); v && d.in_ram(*v)) {
            const std::uint16_t size = variable_size(d.program(), *v);
            return fmt::format("{} at {:04X}H", size == 1 ? h2(d.peek(*v)) : word_text(read_word(d, *v)), *v);
        }
    const debug::Debugger::Value v = d.evaluate(t);
    if (!v.error.empty()) {
        error = v.col > 0 ? fmt::format("{} (column {})", v.error, v.col) : v.error;
        return std::nullopt;
    }
    if (v.value < 0 || v.value > 0xFFFF) return std::to_string(v.value);
    return v.width <= 8 ? fmt::format("{:02X}H ({})", v.value, v.value) : fmt::format("{:04X}H ({})", v.value, v.value);
}

std::vector<CallFrame> call_frames(const debug::Debugger& d) {
    std::vector<CallFrame> out;
    const bool i8080 = d.cpu_status().variant == Variant::I8080;
    for (const debug::Frame& f : d.backtrace()) {
        // A caller is shown at its CALL (or RST), the line the user reads as "called from here".
        std::uint16_t at = f.pc;
        if (!out.empty()) {
            const auto call = static_cast<std::uint16_t>(f.pc - 3);
            const isa::Flow flow = isa::flow_of(d.peek(call), i8080);
            at = flow == isa::Flow::Call || flow == isa::Flow::CallIf ? call : static_cast<std::uint16_t>(f.pc - 1);
        }
        // The routine by its name (a caller's, at its CALL, without an offset); an address that no
        // routine holds is named by the address alone, not twice.
        std::optional<std::string> routine = out.empty() ? f.routine : d.program().routine_at(at);
        if (routine && !out.empty()) routine = routine->substr(0, routine->find('+'));
        out.push_back({routine ? fmt::format("{} ({})", *routine, h4(at)) : h4(at), at, d.program().line_of(at)});
    }
    return out;
}

}  // namespace alp85::dap
