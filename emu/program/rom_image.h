// A ROM image from the user's file, for a board whose ROM is the user's (the SDK-85's 8355:
// `alp85 run --board sdk85 --rom FILE`). FILE is, by its extension:
//   .bin, .rom        a raw dump: exactly the ROM's size (2048 bytes for the 8355), byte 0 at the
//                     ROM's base. Its size is all that places it, so a shorter one (a truncated
//                     dump) or a longer one is refused, as is an empty one or one that is text;
//   .hex, .ihx, .ihex Intel HEX: every data byte inside the ROM; addresses not written read FFH
//                     (an unprogrammed byte of the 8755, the 8355's EPROM twin);
//   .asm, .a85, .s, .mac  source that asm85 assembles; as .hex once assembled.
// Anything else, and a .hex or source with no byte at all, is refused. Every refusal is a
// LoadError naming the file (and line:col for a .hex record or a source line); the front ends
// report it and exit with status 2, as for any bad input (docs/sdk85.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "asm/asm85.h"
#include "emu/program/image_loader.h"

namespace alp85 {

struct RomImage {
    std::vector<std::uint8_t> bytes;        // exactly the ROM's size, from its base
    std::size_t programmed = 0;             // bytes the file gave (the rest are the FFH fill)
    std::vector<asm85::Symbol> symbols;     // source only
    std::optional<asm85::Result> assembly;  // source only: the whole result (line map, listing)
    std::vector<std::string> warnings;      // formatted asm85 warnings
};

struct RomSpec {
    std::uint16_t base = 0x0000;  // where the ROM sits in the CPU's memory
    std::uint16_t size = 0x0800;  // its size in bytes (the 8355: 2048)
};

// Throws LoadError.
RomImage read_rom_image(const std::filesystem::path& path, const RomSpec& rom = {},
                        const asm85::Options& assembler = {});

}  // namespace alp85
