// Helpers for the board tests: a machine with a test program (assembled by asm85) in its EPROMs.
#pragma once

#include <string>

#include "emu/program/image_loader.h"
#include "emu/board/machine.h"

namespace alp85::test {

inline std::string program_path(const std::string& name) { return std::string(ALP85_BOARD_PROGRAMS) + "/" + name; }

// Loads tests/board/programs/<name>, resets the machine and returns the assembly's symbols.
inline LoadedImage boot(Machine& m, const std::string& name) {
    LoadedImage img = load_image(m, program_path(name));
    m.reset();
    return img;
}

inline std::uint64_t ms(double v) { return Machine::tstates_from_ms(v); }

}  // namespace alp85::test
