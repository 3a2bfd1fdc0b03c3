#include "emu/dap/breakpoints.h"

#include <algorithm>
#include <charconv>

#include <fmt/format.h>

namespace alp85::dap {

std::vector<Breakpoint*> BreakpointTable::at(std::uint16_t pc) {
    std::vector<Breakpoint*> out;
    auto take = [&](std::vector<Breakpoint>& list) {
        for (Breakpoint& b : list)
            if (b.verified && std::find(b.addresses.begin(), b.addresses.end(), pc) != b.addresses.end()) out.push_back(&b);
    };
    for (auto& [path, list] : source) take(list);
    take(function);
    take(instruction);
    return out;
}

std::string data_id(std::uint16_t address, std::uint16_t length) { return fmt::format("{:04X}H:{}", address, length); }

std::optional<std::pair<std::uint16_t, std::uint16_t>> parse_data_id(const std::string& id) {
    unsigned address = 0, length = 0;
    const auto colon = id.find(':');
    if (colon != 5 || id[4] != 'H') return std::nullopt;
    const auto [p, ec] = std::from_chars(id.data(), id.data() + 4, address, 16);
    if (ec != std::errc{} || p != id.data() + 4) return std::nullopt;
    const auto [q, ec2] = std::from_chars(id.data() + 6, id.data() + id.size(), length);
    if (ec2 != std::errc{} || q != id.data() + id.size() || length == 0 || length > 256) return std::nullopt;
    return std::pair{static_cast<std::uint16_t>(address), static_cast<std::uint16_t>(length)};
}

}  // namespace alp85::dap
