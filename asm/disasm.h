// A one-instruction 8080/8085 disassembler over the shared opcode table (asm/isa.h).
//
//     auto d = alp85::asm85::disassemble(read_byte, 0x0100);
//     // d.text == "LXI H,1234H", d.length == 3
//
// Output is text asm85 assembles back to the same bytes: mnemonic, one space, operands separated
// by ',' with no space; numbers in upper-case hex with an H suffix and a leading 0 when they
// start with a letter (0FFH). Bytes an 8080 does not decode as the 8085 does are shown with their
// 8085 mnemonics unless `cpu8080` is set, in which case they show as DB 20H style data bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace alp85::asm85 {

struct Disassembly {
    std::string text;          // e.g. "MVI A,05H", "JMP START"
    std::uint8_t length = 1;   // bytes consumed (1..3)
    std::uint8_t bytes[3]{};   // the instruction's bytes
};

struct DisasmOptions {
    // Name for a 16-bit address/word operand (a16, d16), or nullopt to print it as hex.
    std::function<std::optional<std::string>(std::uint16_t)> symbol;
    bool cpu8080 = false;
    // Name for a 16-bit immediate (d16: LXI) only; when unset, `symbol` names those too. Lets a
    // caller keep small EQU constants (KMODE EQU 0) off LXI H,0000H while CALL 0005H stays BDOS.
    std::function<std::optional<std::string>(std::uint16_t)> data_symbol;
};

// Decodes the instruction at `address`; `read` supplies memory (wrapping at 0FFFFH).
Disassembly disassemble(const std::function<std::uint8_t(std::uint16_t)>& read, std::uint16_t address,
                        const DisasmOptions& options = {});

// Formats a value as asm85 hex: 5H, 0FFH, 1234H, 0C000H.
std::string hex_operand(unsigned value, int digits);

}  // namespace alp85::asm85
