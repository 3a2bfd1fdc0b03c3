// Loading programs into the machine: .asm (assembled on the fly by asm85's library), .hex (Intel
// HEX) and .bin (raw, at a given address). Every front end loads through here.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "asm/asm85.h"
#include "emu/board/machine.h"
#include "emu/util/input_file.h"

namespace alp85 {

// A load that failed: the message names the file and, for sources, every error as
// file:line:col (asm85's diagnostics).
class LoadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct LoadedImage {
    std::vector<ImageSegment> segments;
    std::vector<asm85::Symbol> symbols;      // .asm only
    std::optional<std::uint16_t> start;      // END's operand (.asm) or a start record (.hex)
    std::optional<asm85::Result> assembly;   // .asm only: the whole result (line map, listing)
    std::vector<std::string> warnings;       // formatted asm85 warnings
};

struct LoadOptions {
    std::optional<std::uint16_t> address;  // where a .bin goes (required for .bin; a .com defaults to 0100H)
    asm85::Options assembler;              // for .asm
};

// The bytes of an image file (a .hex's text, a .bin's bytes), or a LoadError naming why it cannot
// be read (missing, a directory, too large for its kind).
std::string read_image_file(const std::filesystem::path& path, FileKind kind);
// asm85 on a source file: its result, its warnings formatted into `warnings`; its errors a
// LoadError that lists them.
asm85::Result assemble_source(const std::filesystem::path& path, const asm85::Options& options,
                              std::vector<std::string>& warnings);
// Reads and converts the file (by its extension; anything else is refused). Throws LoadError.
LoadedImage read_image(const std::filesystem::path& path, const LoadOptions& options = {});
// For a load onto the board: a part of the image that runs from one memory region of the ALP 85
// into another (board::kMemoryMap: a 3000-byte .bin at 0800H runs past the 2 KB user EPROM into
// RAM) is refused for a raw binary (.bin, .rom, .com: its size is all that places it, so the
// crossing is surely a mistake) - LoadError - and warned about for .hex and .asm, whose addresses
// are the author's own (a warning appended to img.warnings).
void check_board_regions(LoadedImage& img, const std::filesystem::path& path);

// read_image, check_board_regions, then Machine::load; nothing is placed when any byte falls off the board.
LoadedImage load_image(Machine& machine, const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace alp85
