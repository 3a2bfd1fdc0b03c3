// A program image as the loaders produce it and the machine places it: runs of bytes at
// addresses. Plain data, so byte-to-text code (disassembly, HEX) need not include the board.
#pragma once

#include <cstdint>
#include <vector>

namespace alp85 {

// One contiguous run of bytes to place in a machine's memory.
struct ImageSegment {
    std::uint16_t address = 0;
    std::vector<std::uint8_t> bytes;
};

}  // namespace alp85
