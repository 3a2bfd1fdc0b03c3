#include "emu/core/cpu_registers.h"

#include <cctype>

#include "asm/isa.h"

namespace alp85::cpu {

namespace {
bool same_register_name(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
    return true;
}
}  // namespace

const Register* Description::find(std::string_view name) const {
    for (const Register& r : registers)
        if (same_register_name(r.name, name)) return &r;
    return nullptr;
}

const Flag* Description::find_flag(std::string_view name) const {
    for (const Flag& f : flags)
        if (same_register_name(f.name, name) || (!f.alias.empty() && same_register_name(f.alias, name))) return &f;
    return nullptr;
}

std::string Register::hex(std::uint16_t value) const {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string out;
    for (int shift = (width > 8 ? 16 : 8) - 4; shift >= 0; shift -= 4) out += kDigits[(value >> shift) & 0xF];
    return out + 'H';
}

bool Description::in_pair(const Register& r) const {
    for (const Register& p : registers)
        if (p.kind == Register::Kind::Pair && (p.high == r.name || p.low == r.name)) return true;
    return false;
}

const Register* Description::flag_register() const {
    for (const Register& r : registers)
        if (r.kind == Register::Kind::Flags) return &r;
    return nullptr;
}

// Intel's 8085 programming model (MCS-80/85 User's Manual): A and the flags, B C, D E, H L, the
// stack pointer and the program counter; the pairs as the instructions name them (PUSH PSW, LXI B,
// DAD D, M); the flags as PUSH PSW stores them (S Z K AC 0 P V CY from bit 7; docs/cpu.md).
Description i8085_description() {
    using K = Register::Kind;
    Description d;
    d.registers = {
        byte<&Registers::a>("A", "accumulator"),
        byte<&Registers::f>("F", "flags", K::Flags),
        byte<&Registers::b>("B"),
        byte<&Registers::c>("C"),
        byte<&Registers::d>("D"),
        byte<&Registers::e>("E"),
        byte<&Registers::h>("H"),
        byte<&Registers::l>("L"),
        pair<&Registers::a, &Registers::f>("PSW", "A", "F", false, "program status word"),
        pair<&Registers::b, &Registers::c>("BC", "B", "C", true),
        pair<&Registers::d, &Registers::e>("DE", "D", "E", true),
        pair<&Registers::h, &Registers::l>("HL", "H", "L", true),
        word<&Registers::sp>("SP", "stack pointer"),
        word<&Registers::pc>("PC", "program counter"),
        {"M", K::Memory, 8, nullptr, nullptr, "HL", {}, false, "the byte at HL"},
    };
    d.flags = {
        {"S", isa::F_S, true, {}},
        {"Z", isa::F_Z, true, {}},
        {"AC", isa::F_AC, true, {}},
        {"P", isa::F_P, true, {}},
        {"CY", isa::F_CY, true, "C"},
        {"V", isa::F_V, false, {}},
        {"K", isa::F_K, false, "X5"},
    };
    return d;
}

}  // namespace alp85::cpu
