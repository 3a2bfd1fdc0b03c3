#include "emu/program/image_loader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>

#include <fmt/format.h>

#include "emu/program/ihex.h"

namespace alp85 {
namespace {

std::string lower_extension(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

std::string read_all(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw LoadError(fmt::format("{}: cannot open file", path.string()));
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

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

LoadedImage read_image(const std::filesystem::path& path, const LoadOptions& options) {
    LoadedImage img;
    const std::string ext = lower_extension(path);
    if (ext == ".asm" || ext == ".a85" || ext == ".s" || ext == ".mac") {
        asm85::Result r = asm85::assemble_file(path, options.assembler);
        std::string errors;
        for (const asm85::Diagnostic& d : r.diagnostics) {
            if (d.severity == asm85::Severity::Error)
                errors += asm85::format_diagnostic(d);
            else if (d.severity == asm85::Severity::Warning)
                img.warnings.push_back(asm85::format_diagnostic(d));
        }
        if (!r.ok())
            throw LoadError(fmt::format("{}: {} error(s) in assembly\n{}", path.string(), r.error_count(), errors));
        for (const asm85::Segment& s : r.image.segments()) img.segments.push_back({s.start, s.bytes});
        img.symbols = r.symbols;
        img.start = r.image.start_address;
        img.assembly = std::move(r);
    } else if (ext == ".hex" || ext == ".ihx" || ext == ".ihex") {
        std::map<std::uint16_t, std::uint8_t> bytes;
        const auto err = read_intel_hex(read_all(path), [&](std::uint16_t a, std::uint8_t v) { bytes[a] = v; });
        if (err) throw LoadError(fmt::format("{}:{}:{}: error: {}", path.string(), err->line, err->col, err->message));
        img.segments = runs(bytes);
    } else if (ext == ".bin" || ext == ".rom" || ext == ".com") {
        // A CP/M .COM file runs at 0100H, its TPA, unless told otherwise.
        const auto address = ext == ".com" ? options.address.value_or(0x0100) : options.address;
        if (!address) throw LoadError(fmt::format("{}: a binary image needs a load address", path.string()));
        const std::string data = read_all(path);
        if (data.size() + *address > 0x10000)
            throw LoadError(fmt::format("{}: {} bytes at {:04X}H run past FFFFH", path.string(), data.size(), *address));
        img.segments.push_back({*address, {data.begin(), data.end()}});
    } else {
        throw LoadError(fmt::format("{}: unknown image type '{}' (expected .asm, .hex or .bin)", path.string(), ext));
    }
    return img;
}

LoadedImage load_image(Machine& machine, const std::filesystem::path& path, const LoadOptions& options) {
    LoadedImage img = read_image(path, options);
    try {
        machine.load(img.segments);  // checks every byte before placing any
    } catch (const std::out_of_range& e) {
        throw LoadError(fmt::format("{}: {}", path.string(), e.what()));
    }
    return img;
}

}  // namespace alp85
