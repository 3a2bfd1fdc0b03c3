// The instruction set of the Pisa multi-purpose interpolator (Casarosa, Frosini, Gerace, Maestrini,
// Piram, CNR-IEI Pisa, Nota Interna B69-12, 1969): the one table the assembler (asm/pisa_asm) and the
// machine (emu/pisa) share, as asm/isa.h is for the 8085.
//
// A ROM word is 22 bits (paper §4): a 4-bit operation code (§3: "4 bits have proved to be
// sufficient") and an 18-bit address field (§2.3) read as three 6-bit fields A B C, or as A and a
// 12-bit field F = B:C for jumps and STO:
//
//     21..18 op | 17..12 A | 11..6 B | 5..0 C          (F = bits 11..0)
//
// The paper names no encoding and not all 16 codes; every choice below is listed with the sentence
// it rests on in docs/pisa.md ("The instruction set as reconstructed").
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace alp85::pisa {

inline constexpr int kWordBits = 22;
inline constexpr std::uint32_t kWordMask = (1u << kWordBits) - 1;
inline constexpr int kRwmWords = 64;      // §2.2: "a maximum of 64 words has been assumed"
inline constexpr int kDigits = 8;         // §2.1: "fixed in 8 decimal digits"
inline constexpr int kRomMax = 4096;      // §4: "up to the maximum of 4096"
inline constexpr int kRomPackage = 64;    // §4: "fixed increments of 64 words"
inline constexpr int kIndicators = 64;    // §2.3: six bits address an indicator
inline constexpr int kChannels = 64;      // a 6-bit channel field (choice)

enum class Op : std::uint8_t {
    ADD = 0,   // (C) = (A) + (B)
    SUB = 1,   // (C) = (B) - (A)            "subtract (L1) from (L2)", as ADS
    ADS = 2,   // (C) = (B) +/- (A) by the sign of the fixed location kAdsSign
    MOD = 3,   // sign bit of (C) = sign(A) x sign(B)
    ABS = 4,   // (C) = |(A)|
    MOV = 5,   // (C) = (A)                  transfer between RWM words
    SHF = 6,   // (C) = (A) x 10^n or / 10^n; B = n (0..8) + kShiftRight
    STO = 7,   // three low cells of (A) = the 12 bits F, the five high digits = 0
    JMP = 8,   // next instruction from F
    JMI = 9,   // next instruction from the 12 bits in the three low cells of (A)
    TZE = 10,  // to F if (A) = 0
    TPL = 11,  // to F if (A) >= 0
    TRS = 12,  // to F if indicator A is 1
    SRI = 13,  // indicator A = C (set: C = 1, reset: C = 0)
    IN = 14,   // C digits (1..8) of input channel B into (A), code converted
    OUT = 15,  // C digits (1..8) of (A) to output channel B, code converted
};

// How the operands are written and packed.
enum class Form : std::uint8_t {
    Three,   // OP L1,L2,L3      A B C
    Two,     // OP L1,L2         A C         (ABS, MOV)
    Shift,   // OP L1,n,L3       A B C       (SHL, SHR)
    Store,   // STO c,L          A F         (c: decimal 0..999 in excess-3, or @addr raw 12 bits)
    Jump,    // JMP F            F
    Indir,   // JMI L            A
    Cond,    // TZE F,L / TRS F,S   A F
    Ind,     // SET S / RST S    A C
    Io,      // IN ch,n,L / OUT ch,n,L   B C A
};

struct Mnemonic {
    std::string_view name;
    Op op;
    Form form;
    std::uint8_t fixed = 0;  // SHR: kShiftRight in B; SET: 1 in C
};

inline constexpr std::uint8_t kShiftRight = 0x20;  // bit 5 of the shift field: divide
inline constexpr int kAdsSign = 0;                 // the "fixed location" of ADS: RWM word 0

inline constexpr std::array<Mnemonic, 18> kMnemonics{{
    {"ADD", Op::ADD, Form::Three}, {"SUB", Op::SUB, Form::Three}, {"ADS", Op::ADS, Form::Three},
    {"MOD", Op::MOD, Form::Three}, {"ABS", Op::ABS, Form::Two},   {"MOV", Op::MOV, Form::Two},
    {"SHL", Op::SHF, Form::Shift}, {"SHR", Op::SHF, Form::Shift, kShiftRight},
    {"STO", Op::STO, Form::Store}, {"JMP", Op::JMP, Form::Jump},  {"JMI", Op::JMI, Form::Indir},
    {"TZE", Op::TZE, Form::Cond},  {"TPL", Op::TPL, Form::Cond},  {"TRS", Op::TRS, Form::Cond},
    {"SET", Op::SRI, Form::Ind, 1}, {"RST", Op::SRI, Form::Ind, 0},
    {"IN", Op::IN, Form::Io},      {"OUT", Op::OUT, Form::Io},
}};

inline std::optional<Mnemonic> find_mnemonic(std::string_view upper) {
    for (const auto& m : kMnemonics)
        if (m.name == upper) return m;
    return std::nullopt;
}

// Packing and unpacking of a 22-bit word.
struct Fields {
    Op op = Op::ADD;
    std::uint8_t a = 0, b = 0, c = 0;
    std::uint16_t f() const { return static_cast<std::uint16_t>((b << 6) | c); }
};

inline constexpr std::uint32_t pack(Op op, unsigned a, unsigned b, unsigned c) {
    return (static_cast<std::uint32_t>(op) << 18) | ((a & 63u) << 12) | ((b & 63u) << 6) | (c & 63u);
}
inline constexpr std::uint32_t pack_f(Op op, unsigned a, unsigned f) {
    return (static_cast<std::uint32_t>(op) << 18) | ((a & 63u) << 12) | (f & 4095u);
}
inline constexpr Fields unpack(std::uint32_t w) {
    return {static_cast<Op>((w >> 18) & 15u), static_cast<std::uint8_t>((w >> 12) & 63u),
            static_cast<std::uint8_t>((w >> 6) & 63u), static_cast<std::uint8_t>(w & 63u)};
}

// Timing model (docs/pisa.md "Timing"): one digit step is one micro-order, kStepNs long. Every
// instruction costs the fetch micro-instruction (§4: "consists of one micro-instruction only") plus
// one step per RWM cell access, the RWM being single-ported: a three-address digit is read A,
// read B and add, write C.
inline constexpr int kStepNs = 100;
inline constexpr int kFetch = 1;
inline constexpr int steps(Op op, unsigned io_digits = 8) {
    switch (op) {
        case Op::ADD: case Op::SUB: return kFetch + 3 * kDigits;          // 25
        case Op::ADS: return kFetch + 1 + 3 * kDigits;                     // 26: the sign of word 0
        case Op::MOD: return kFetch + 4;                                   // 5: two signs, C's top cell read and written
        case Op::ABS: return kFetch + 1 + 2 * kDigits;                     // 18: sign, then read/write each digit
        case Op::MOV: return kFetch + 2 * kDigits;                         // 17
        case Op::SHF: return kFetch + 1 + 2 * kDigits;                     // 18: sign, then read/write
        case Op::STO: return kFetch + kDigits;                             // 9: eight cells written
        case Op::JMP: return kFetch + 1;                                   // 2
        case Op::JMI: return kFetch + 3;                                   // 4: three cells read
        case Op::TZE: return kFetch + kDigits;                             // 9: every digit read
        case Op::TPL: return kFetch + 1;                                   // 2: the top digit
        case Op::TRS: return kFetch + 1;                                   // 2
        case Op::SRI: return kFetch + 1;                                   // 2
        case Op::IN: return kFetch + 2 * static_cast<int>(io_digits) + (kDigits - static_cast<int>(io_digits));
        case Op::OUT: return kFetch + 2 * static_cast<int>(io_digits);
    }
    return kFetch;
}

}  // namespace alp85::pisa
