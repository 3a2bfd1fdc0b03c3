// Intel HEX and raw binary output.
#include <fmt/format.h>

#include "asm/asm85.h"

namespace alp85::asm85 {
namespace {

void record(std::string& out, std::uint16_t addr, std::uint8_t type, const std::uint8_t* data, std::size_t n) {
    unsigned sum = static_cast<unsigned>(n) + (addr >> 8) + (addr & 0xFF) + type;
    out += fmt::format(":{:02X}{:04X}{:02X}", n, addr, type);
    for (std::size_t i = 0; i < n; ++i) {
        out += fmt::format("{:02X}", data[i]);
        sum += data[i];
    }
    out += fmt::format("{:02X}\n", (0x100 - (sum & 0xFF)) & 0xFF);
}

}  // namespace

std::string write_intel_hex(const Image& image, int per_record) {
    if (per_record < 1) per_record = 1;
    if (per_record > 255) per_record = 255;
    std::string out;
    for (const auto& seg : image.segments()) {
        for (std::size_t off = 0; off < seg.bytes.size(); off += static_cast<std::size_t>(per_record)) {
            std::size_t n = std::min(seg.bytes.size() - off, static_cast<std::size_t>(per_record));
            record(out, static_cast<std::uint16_t>(seg.start + off), 0x00, seg.bytes.data() + off, n);
        }
    }
    if (image.start_address) {
        const std::uint8_t cs_ip[4] = {0, 0, static_cast<std::uint8_t>(*image.start_address >> 8),
                                       static_cast<std::uint8_t>(*image.start_address & 0xFF)};
        record(out, 0, 0x03, cs_ip, 4);
    }
    record(out, 0, 0x01, nullptr, 0);
    return out;
}

std::vector<std::uint8_t> write_binary(const Image& image, std::uint16_t first, std::uint16_t last, std::uint8_t fill) {
    std::vector<std::uint8_t> out;
    if (last < first) return out;
    out.reserve(static_cast<std::size_t>(last - first) + 1);
    for (std::uint32_t a = first; a <= last; ++a) out.push_back(image.read(static_cast<std::uint16_t>(a)).value_or(fill));
    return out;
}

}  // namespace alp85::asm85
