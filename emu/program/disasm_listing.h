// Disassembly of whole images (the segments of a .hex, .bin, .asm or the monitor ROM) into a
// listing or into source that asm85 assembles back to the same bytes. One instruction at a time
// is asm85's disassembler (asm/disasm.h); this layer walks the segments, places labels from a
// SymbolTable and decides what to do at a segment's end.
//
// It decodes linearly from the first byte (or `from`): it does not trace code from entry points,
// so data tables come out as instructions; a label inside an instruction cuts it short (its
// bytes become DB) so that decoding restarts at the label. Either way the source form assembles
// back to exactly the same bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "emu/core/i8085.h"
#include "emu/core/image.h"
#include "emu/program/symbols.h"

namespace alp85 {

struct DisasmLine {
    std::uint16_t address = 0;
    std::vector<std::uint8_t> bytes;
    std::string text;   // "MVI A,05H"; "DB 0CDH,34H" where an instruction would run off the block
    std::string label;  // a label defined exactly here, or empty
};

// A contiguous run of bytes, decoded.
struct DisasmBlock {
    std::uint16_t start = 0;
    std::vector<DisasmLine> lines;
};

struct ImageDisasmOptions {
    Variant variant = Variant::I8085;
    const SymbolTable* symbols = nullptr;  // names for labels and 16-bit operands; may be null
    std::optional<std::uint16_t> from;     // first address decoded (decoding starts exactly here)
    std::optional<std::uint16_t> to;       // last address at which an instruction starts (decoded whole)
    // For source a person reads: every JMP, CALL and conditional target that is the start of a
    // decoded line gets a label (L0802, where the symbols have none), and so does the first line
    // (START), which END then names.
    bool label_targets = false;
};

struct DisasmResult {
    std::vector<DisasmBlock> blocks;
    std::set<std::string> names_used;  // symbols printed as operands
    std::size_t bytes = 0;             // bytes covered
};

// Decodes the bytes of `segments` (overlapping segments: the later one wins) from `from`; the
// instruction that starts at `to` is decoded whole (its operand bytes may lie beyond `to`).
// An instruction whose operand bytes are not all in the image, or which a label cuts, is DB.
DisasmResult disassemble_image(const std::vector<ImageSegment>& segments, const ImageDisasmOptions& options);

// "0800  31 00 20   LXI SP,2000H" lines, a "NAME:" line before each labelled address, and a
// blank line between blocks.
std::string format_listing(const DisasmResult& result);

// asm85 source: a header naming `origin`, EQU lines for every name used as an operand but not
// placed as a label, ORG per block, labels, instructions, END (naming the first line's label, if
// it has one, as the start address).
std::string format_source(const DisasmResult& result, const ImageDisasmOptions& options, const std::string& origin);

}  // namespace alp85
