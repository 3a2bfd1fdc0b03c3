#include "emu/program/rom_image.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "emu/program/ihex.h"
#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85 {
namespace {

std::string read_rom_file(const std::filesystem::path& path, FileKind kind) {
    try {
        return read_input(path, kind);
    } catch (const InputError& e) {
        throw LoadError(e.what());
    }
}

// Text a person would type or a tool would write (tabs, line ends, printable ASCII): a ROM image
// of 8085 code always holds other bytes (00H NOP, C3H JMP, FFH unprogrammed).
bool is_text(const std::string& data) {
    return std::all_of(data.begin(), data.end(), [](char ch) {
        const auto c = static_cast<unsigned char>(ch);
        return c == '\t' || c == '\n' || c == '\r' || (c >= 0x20 && c < 0x7F);
    });
}

std::string first_line(const std::string& data) {
    std::string line = data.substr(0, data.find_first_of("\r\n"));
    if (line.size() > 40) line = line.substr(0, 40) + "...";
    return line;
}

// The 1-based line of the first data record (type 00) holding `address`; 0 if none does (an
// already-checked file always has one).
int hex_record_line(const std::string& text, std::uint16_t address) {
    int line = 0;
    std::size_t at = 0;
    while (at <= text.size()) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        ++line;
        const std::string rec = text.substr(at, end - at);
        const std::size_t colon = rec.find(':');
        if (colon != std::string::npos && rec.size() >= colon + 9 && rec.compare(colon + 7, 2, "00") == 0) {
            const auto count = static_cast<unsigned>(std::stoul(rec.substr(colon + 1, 2), nullptr, 16));
            const auto first = static_cast<unsigned>(std::stoul(rec.substr(colon + 3, 4), nullptr, 16));
            if (address >= first && address < first + count) return line;
        }
        at = end + 1;
    }
    return 0;
}

std::string rom_range(const RomSpec& rom) {
    return fmt::format("{:04X}H-{:04X}H", rom.base, rom.base + rom.size - 1);
}

}  // namespace

RomImage read_rom_image(const std::filesystem::path& path, const RomSpec& rom, const asm85::Options& assembler) {
    RomImage img;
    img.bytes.assign(rom.size, 0xFF);
    const std::uint32_t end = static_cast<std::uint32_t>(rom.base) + rom.size;  // one past the ROM
    const auto inside = [&](std::uint32_t a) { return a >= rom.base && a < end; };
    const std::string name = path.string();
    const std::string ext = lower_extension(path);

    if (ext == ".bin" || ext == ".rom") {
        const std::string data = read_rom_file(path, FileKind::Binary);
        if (data.empty()) throw LoadError(fmt::format("{}: empty file: a ROM image is a {}-byte dump", name, rom.size));
        if (is_text(data))
            throw LoadError(fmt::format("{}: text, not a ROM image (it begins '{}'); Intel HEX goes in a .hex file, "
                                        "assembly source in a .asm file",
                                        name, first_line(data)));
        if (data.size() < rom.size)
            throw LoadError(fmt::format("{}: short: {} bytes, but a ROM image is a dump of the whole {}-byte ROM ({}); "
                                        "a smaller program goes in a .hex or .asm file, whose addresses place it",
                                        name, data.size(), rom.size, rom_range(rom)));
        if (data.size() > rom.size)
            throw LoadError(fmt::format("{}: {} bytes, larger than the {}-byte ROM ({})", name, data.size(), rom.size,
                                        rom_range(rom)));
        std::copy(data.begin(), data.end(), img.bytes.begin());
        img.programmed = data.size();
        return img;
    }

    std::map<std::uint16_t, std::uint8_t> bytes;
    if (ext == ".hex" || ext == ".ihx" || ext == ".ihex") {
        const std::string text = read_rom_file(path, FileKind::HexImage);
        const auto err = read_intel_hex(text, [&](std::uint16_t a, std::uint8_t v) { bytes[a] = v; });
        if (err) throw LoadError(fmt::format("{}:{}:{}: error: {}", name, err->line, err->col, err->message));
        for (const auto& [a, v] : bytes) {
            if (inside(a)) continue;
            // The record's address field (columns 4-7 of ":LLAAAATT").
            throw LoadError(fmt::format("{}:{}:4: error: data at {:04X}H is outside the ROM ({})", name,
                                        hex_record_line(text, a), a, rom_range(rom)));
        }
    } else if (ext == ".asm" || ext == ".a85" || ext == ".s" || ext == ".mac") {
        asm85::Result r = asm85::assemble_file(path, assembler);
        std::string errors;
        for (const asm85::Diagnostic& d : r.diagnostics) {
            if (d.severity == asm85::Severity::Error)
                errors += asm85::format_diagnostic(d);
            else if (d.severity == asm85::Severity::Warning)
                img.warnings.push_back(asm85::format_diagnostic(d));
        }
        if (!r.ok()) throw LoadError(fmt::format("{}: {} error(s) in assembly\n{}", name, r.error_count(), errors));
        for (const asm85::Segment& s : r.image.segments()) {
            for (std::size_t i = 0; i < s.bytes.size(); ++i) {
                const std::uint32_t a = s.start + i;
                if (!inside(a)) {
                    const asm85::LineSpan* at = r.origin(static_cast<std::uint16_t>(a));
                    const std::string where =
                        at ? fmt::format("{}:{}:1", r.files[static_cast<std::size_t>(at->file)], at->line) : name;
                    throw LoadError(fmt::format("{}: error: code at {:04X}H is outside the ROM ({})", where, a, rom_range(rom)));
                }
                bytes[static_cast<std::uint16_t>(a)] = s.bytes[i];
            }
        }
        img.symbols = r.symbols;
        img.assembly = std::move(r);
    } else {
        throw LoadError(fmt::format("{}: unknown ROM image type '{}' (expected .bin or .rom, a dump of the {}-byte ROM; "
                                    ".hex; or .asm source)",
                                    name, ext, rom.size));
    }
    if (bytes.empty()) throw LoadError(fmt::format("{}: no data: the file puts no byte into the ROM ({})", name, rom_range(rom)));
    for (const auto& [a, v] : bytes) img.bytes[a - rom.base] = v;
    img.programmed = bytes.size();
    return img;
}

}  // namespace alp85
