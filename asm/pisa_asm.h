// pisa-asm: the assembler of the Pisa interpolator (asm/pisa_isa.h; docs/pisa.md "Assembler"),
// the "programming aids (such as a simulator and an assembler)" the 1969 paper promises. It shares
// asm85's line tokenizer, expressions (Intel precedence), diagnostics (file:line:col: error:),
// listing and JSON map (asm85.h), so a Pisa program reads and fails like an 8085 one.
//
//   ; comment                     names are case-insensitive; a label starts in column 1
//   X       EQU 5                 RWM word 5 (addresses are plain numbers or names)
//           ORG 0                 ROM word address
//   LOOP:   ADD X,Y,Z             (Z) = (X) + (Y)
//           STO 125,K             the decimal constant 125 (excess-three) in K
//           STO #RET,R            the 12-bit ROM address RET in R (for JMI R)
//           TPL LOOP,X            to LOOP if (X) >= 0
//           END
//
// Result::out holds what asm85 produces (symbols, line map, listing lines, diagnostics); its image
// keeps each 22-bit word as three bytes, high first, at three times its address.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "asm/asm85.h"

namespace alp85::pisa_asm {

struct Options {
    std::vector<std::pair<std::string, std::string>> defines;  // NAME=VALUE, as EQU before line 1
    std::function<std::optional<std::string>(const std::filesystem::path&)> read_file;  // default: disk
};

struct Result {
    asm85::Result out;
    std::vector<std::uint32_t> rom;  // words 0 .. highest assembled (unassembled words 0)
    bool ok() const { return out.ok(); }
};

Result assemble_file(const std::filesystem::path& path, const Options& options = {});
Result assemble_string(std::string_view source, const Options& options = {}, std::string_view name = "<string>");

// The listing and map layout of Pisa words (three bytes each, addresses in words).
asm85::OutputFormat output_format();
// The ROM as text, one word a line: "AAAA OOOOOOOO" (decimal address, the word in octal).
std::string write_rom_text(const Result& r);

}  // namespace alp85::pisa_asm
