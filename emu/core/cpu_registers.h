// What the 8085 shows a debugger: its registers, register pairs and flags, each with its name,
// width and how it is read and written, in the order of Intel's programming model (A and the
// flags, B C, D E, H L, SP, PC). The CPU owns the list and every front end renders it, as a part's
// periph::Description: the expression evaluator (`print`, `set`, conditions), the console's
// `info registers`, DAP's registers scope and setVariable, the GUI's Registers pane and the
// script's `expect reg` / `set reg`. A register added here in one line shows up in all of them.
//
//   d.registers.push_back(cpu::byte<&Registers::a>("A", "accumulator"));
//   d.registers.push_back({"SPH", Kind::Byte, 8, read, write});  // any read and write of the register file
//
// Reading and writing go through the register file (Registers, i8085.h) only: describing and
// reading never change the CPU.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "emu/core/i8085.h"

namespace alp85::cpu {

struct Register {
    enum class Kind : std::uint8_t {
        Byte,    // an 8-bit register: A B C D E H L
        Flags,   // the flag byte F: its bits are the description's flags
        Pair,    // two byte registers read as one word, `high` the high byte: PSW BC DE HL
        Word,    // a 16-bit register of its own: SP PC
        Memory,  // M: the byte at the address the pair `high` holds; memory, read and written by the bus
    };

    std::string_view name;  // "A", "BC", "SP": upper case, as the data sheet writes it
    Kind kind = Kind::Byte;
    int width = 8;          // bits
    std::uint16_t (*read)(const Registers&) = nullptr;   // nullptr for Memory
    void (*write)(Registers&, std::uint16_t) = nullptr;  // stores the low `width` bits
    std::string_view high, low;  // Pair: its byte registers; Memory: `high` names the pair (HL)
    bool address = false;        // holds a memory address (BC DE HL SP PC): a debugger may show the memory there
    std::string_view text;       // what it is: "accumulator", "stack pointer"

    std::uint16_t mask() const { return width >= 16 ? 0xFFFF : static_cast<std::uint16_t>((1u << width) - 1); }
    // "0DH", "1B30H": the value in hex digits for the width, as every front end shows it.
    std::string hex(std::uint16_t value) const;
};

struct Flag {
    std::string_view name;   // S Z AC P CY V K
    std::uint8_t bit = 0;    // its mask in F (isa::Flag)
    bool documented = true;  // in Intel's data sheet; V and K are not (docs/cpu.md)
    std::string_view alias;  // the other name it goes by: C for CY (JC, JNC), X5 for K
};

struct Description {
    std::vector<Register> registers;  // in the order of the programming model
    std::vector<Flag> flags;          // the data sheet's S Z AC P CY, then the undocumented V and K

    // The register of that name (case-insensitive), or nullptr.
    const Register* find(std::string_view name) const;
    // The flag of that name or alias (case-insensitive), or nullptr.
    const Flag* find_flag(std::string_view name) const;
    // The position of `r` in `registers` (a front end's compact reference to it).
    std::size_t index_of(const Register& r) const { return static_cast<std::size_t>(&r - registers.data()); }
    // The flag byte's register (F).
    const Register* flag_register() const;
    // True when `r` is the high or low byte of a pair (A, F, B ... L).
    bool in_pair(const Register& r) const;
    // Neither a pair, nor half of one, nor memory: a register shown by itself (SP, PC).
    bool standalone(const Register& r) const {
        return r.kind != Register::Kind::Pair && r.kind != Register::Kind::Memory && !in_pair(r);
    }
};

// The 8085's description, built afresh.
Description i8085_description();
// The description every front end reads (emu/core/cpu_description.cpp: the 8085's).
const Description& description();

// Entries of the common shapes, read and written through a member of the register file.
template <std::uint8_t Registers::*R>
Register byte(std::string_view name, std::string_view text = {}, Register::Kind kind = Register::Kind::Byte) {
    return {name, kind, 8, [](const Registers& r) -> std::uint16_t { return r.*R; },
            [](Registers& r, std::uint16_t v) { r.*R = static_cast<std::uint8_t>(v); }, {}, {}, false, text};
}
template <std::uint16_t Registers::*R>
Register word(std::string_view name, std::string_view text = {}) {
    return {name, Register::Kind::Word, 16, [](const Registers& r) -> std::uint16_t { return r.*R; },
            [](Registers& r, std::uint16_t v) { r.*R = v; }, {}, {}, true, text};
}
template <std::uint8_t Registers::*H, std::uint8_t Registers::*L>
Register pair(std::string_view name, std::string_view high, std::string_view low, bool address, std::string_view text = {}) {
    return {name, Register::Kind::Pair, 16,
            [](const Registers& r) -> std::uint16_t { return static_cast<std::uint16_t>(r.*H << 8 | r.*L); },
            [](Registers& r, std::uint16_t v) {
                r.*H = static_cast<std::uint8_t>(v >> 8);
                r.*L = static_cast<std::uint8_t>(v);
            },
            high, low, address, text};
}

}  // namespace alp85::cpu
