#include "emu/program/image_loader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>

#include <fmt/format.h>

#include "emu/program/ihex.h"
#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85 {
namespace {

// Contiguous runs from a sparse byte map.
std::vector<ImageSegment> runs(const std::map<std::uint16_t, std::uint8_t>& bytes) {
    std::vector<ImageSegment> out;
    for (const auto& [addr, value] : bytes) {
        if (out.empty() || out.back().address + out.back().bytes.size() != addr) out.push_back({addr, {}});
        out.back().bytes.push_back(value);
    }
    return out;
}

}  // namespace

std::string read_image_file(const std::filesystem::path& path, FileKind kind) {
    try {
        return read_input(path, kind);
    } catch (const InputError& e) {
        throw LoadError(e.what());
    }
}

asm85::Result assemble_source(const std::filesystem::path& path, const asm85::Options& options,
                              std::vector<std::string>& warnings) {
    asm85::Result r = asm85::assemble_file(path, options);
    std::string errors;
    for (const asm85::Diagnostic& d : r.diagnostics) {
        if (d.severity == asm85::Severity::Error)
            errors += asm85::format_diagnostic(d);
        else if (d.severity == asm85::Severity::Warning)
            warnings.push_back(asm85::format_diagnostic(d));
    }
    if (!r.ok()) throw LoadError(fmt::format("{}: {} error(s) in assembly\n{}", path.string(), r.error_count(), errors));
    return r;
}

LoadedImage read_image(const std::filesystem::path& path, const LoadOptions& options) {
    LoadedImage img;
    const std::string ext = lower_extension(path);
    if (ext == ".asm" || ext == ".a85" || ext == ".s" || ext == ".mac") {
        asm85::Result r = assemble_source(path, options.assembler, img.warnings);
        for (const asm85::Segment& s : r.image.segments()) img.segments.push_back({s.start, s.bytes});
        img.symbols = r.symbols;
        img.start = r.image.start_address;
        img.assembly = std::move(r);
    } else if (ext == ".hex" || ext == ".ihx" || ext == ".ihex") {
        std::map<std::uint16_t, std::uint8_t> bytes;
        const auto err = read_intel_hex(read_image_file(path, FileKind::HexImage), [&](std::uint16_t a, std::uint8_t v) { bytes[a] = v; });
        if (err) throw LoadError(fmt::format("{}:{}:{}: error: {}", path.string(), err->line, err->col, err->message));
        img.segments = runs(bytes);
    } else if (ext == ".bin" || ext == ".rom" || ext == ".com") {
        // A CP/M .COM file runs at 0100H, its TPA, unless told otherwise.
        const auto address = ext == ".com" ? options.address.value_or(0x0100) : options.address;
        if (!address) throw LoadError(fmt::format("{}: a binary image needs a load address", path.string()));
        const std::string data = read_image_file(path, FileKind::Binary);
        if (data.size() + *address > 0x10000)
            throw LoadError(fmt::format("{}: {} bytes at {:04X}H run past FFFFH", path.string(), data.size(), *address));
        img.segments.push_back({*address, {data.begin(), data.end()}});
    } else {
        throw LoadError(fmt::format("{}: unknown image type '{}' (expected .asm, .hex or .bin)", path.string(), ext));
    }
    return img;
}

void check_board_regions(LoadedImage& img, const std::filesystem::path& path) {
    const auto region_of = [](std::uint32_t a) -> const board::MemoryRegion* {
        for (const auto& r : board::kMemoryMap)
            if (a >= r.base && a < static_cast<std::uint32_t>(r.base) + r.size) return &r;
        return nullptr;
    };
    const std::string ext = lower_extension(path);
    const bool raw = ext == ".bin" || ext == ".rom" || ext == ".com";
    for (const ImageSegment& s : img.segments) {
        if (s.bytes.empty()) continue;
        const board::MemoryRegion* first = region_of(s.address);
        if (!first) continue;  // off the board: Machine::load refuses it
        const std::uint32_t end = static_cast<std::uint32_t>(first->base) + first->size;  // one past the region
        const std::uint32_t last = s.address + static_cast<std::uint32_t>(s.bytes.size()) - 1;
        if (last < end) continue;
        const board::MemoryRegion* next = region_of(end);
        const std::string into = next ? fmt::format("the '{}' region at {:04X}H", next->name, end)
                                      : fmt::format("unmapped memory at {:04X}H", end);
        const std::string what = fmt::format("{} bytes at {:04X}H-{:04X}H run past the end of the '{}' region "
                                             "({:04X}H-{:04X}H) into {}",
                                             s.bytes.size(), s.address, last, first->name, first->base, end - 1, into);
        if (raw) throw LoadError(fmt::format("{}: {}; refused: a binary image must fit its memory region", path.string(), what));
        img.warnings.push_back(fmt::format("{}: warning: {}\n", path.string(), what));
    }
}

LoadedImage load_image(Machine& machine, const std::filesystem::path& path, const LoadOptions& options) {
    LoadedImage img = read_image(path, options);
    check_board_regions(img, path);
    try {
        machine.load(img.segments);  // checks every byte before placing any
    } catch (const std::out_of_range& e) {
        throw LoadError(fmt::format("{}: {}", path.string(), e.what()));
    }
    return img;
}

}  // namespace alp85
