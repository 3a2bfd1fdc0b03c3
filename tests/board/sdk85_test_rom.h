// The project's SDK-85 test program (firmware/sdk85/sdk85test.asm) as the ROM loader reads it, and
// its labels: the tests on the hand-wired chips and on the SDK-85 board share it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "emu/program/rom_image.h"

namespace alp85::test {

inline const RomImage& sdk85_test_rom() {
    static const RomImage image = read_rom_image(std::string(ALP85_SOURCE_DIR) + "/firmware/sdk85/sdk85test.asm");
    return image;
}

// A label's value in the test program (throws when the program has no such label).
inline std::uint16_t sdk85_label(const char* name) {
    const asm85::Symbol* s = sdk85_test_rom().assembly->find_symbol(name);
    if (!s) throw std::runtime_error(std::string("no symbol ") + name);
    return static_cast<std::uint16_t>(s->value);
}

}  // namespace alp85::test
