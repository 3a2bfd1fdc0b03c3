#include "emu/gcode/path_table.h"

#include <fmt/format.h>

namespace alp85::gcode {

std::vector<std::uint8_t> table_bytes(const std::vector<std::vector<Entry>>& paths) {
    std::vector<std::uint8_t> out;
    const auto word = [&](std::uint16_t w) {
        out.push_back(static_cast<std::uint8_t>(w & 0xFF));
        out.push_back(static_cast<std::uint8_t>(w >> 8));
    };
    const auto put = [&](const Entry& e) {
        out.push_back(static_cast<std::uint8_t>(e.kind));
        out.push_back(e.cr);
        for (std::uint16_t w : {e.feed, e.x, e.y, e.z, e.cx, e.cy, e.n}) word(w);
    };
    for (const auto& path : paths) {
        for (const Entry& e : path) put(e);
        put(Entry{});
    }
    return out;
}

std::string intel_hex(std::uint16_t base, const std::vector<std::uint8_t>& bytes) {
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 16) {
        const std::size_t n = std::min<std::size_t>(16, bytes.size() - i);
        const unsigned addr = base + static_cast<unsigned>(i);
        unsigned sum = static_cast<unsigned>(n) + (addr >> 8) + (addr & 0xFF);
        out += fmt::format(":{:02X}{:04X}00", n, addr);
        for (std::size_t k = 0; k < n; ++k) {
            out += fmt::format("{:02X}", bytes[i + k]);
            sum += bytes[i + k];
        }
        out += fmt::format("{:02X}\n", (0x100 - (sum & 0xFF)) & 0xFF);
    }
    out += ":00000001FF\n";
    return out;
}

}  // namespace alp85::gcode
