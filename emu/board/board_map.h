// The boards ALP85 knows (--board NAME), and the clock every one of them runs at. Each board is a
// description (emu/board/board_description.h): the ALP 85 in emu/board/alp85.h, Intel's SDK-85 in
// emu/board/sdk85.h. The names below the list are the ALP 85's tables as older code and the tests
// know them.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "emu/board/alp85.h"
#include "emu/board/sdk85.h"

namespace alp85::board {

// Every board, the default (the ALP 85) first.
inline constexpr std::array<const Board*, 2> kBoards{&kAlp85, &kSdk85};
// The board with that name (alp85, sdk85), or nullptr.
constexpr const Board* find_board(std::string_view name) {
    for (const Board* b : kBoards)
        if (b->name == name) return b;
    return nullptr;
}
// "alp85, sdk85": the names, for messages.
inline std::string board_names() {
    std::string out;
    for (const Board* b : kBoards) out += (out.empty() ? "" : ", ") + std::string(b->name);
    return out;
}
static_assert(kAlp85.clock.cpu_hz() == 3'072'000 && kSdk85.clock.cpu_hz() == 3'072'000);

// The ALP 85's memory as built (its expansion EPROM is the option kExpansionEprom) and its options.
inline constexpr std::span<const MemoryRegion> kMemoryMap{alp85::kMemory.data(), 4};
inline constexpr const MemoryRegion& kExpansionEprom = alp85::kMemory[4];
inline constexpr std::span<const BoardOption> kBoardOptions{alp85::kOptions};
static_assert(kExpansionEprom.option == "expansion" && kMemoryMap.back().option.empty());

// Every board runs its 8085 at 3.072 MHz (a 6.144 MHz crystal; each board's description checks
// it): time in T-states converts to milliseconds the same way on all of them.
inline constexpr std::uint32_t kCrystalHz = kAlp85.clock.crystal_hz;
inline constexpr std::uint32_t kCpuHz = kCrystalHz / 2;

// T-states of a duration on the board's clock, rounded to the nearest, and back: the one
// conversion between simulated time and milliseconds (scripts, reports, tests).
constexpr std::uint64_t tstates_from_ms(double ms) { return static_cast<std::uint64_t>(ms * kCpuHz / 1000.0 + 0.5); }
constexpr double ms_from_tstates(std::uint64_t t) { return static_cast<double>(t) * 1000.0 / kCpuHz; }

}  // namespace alp85::board
