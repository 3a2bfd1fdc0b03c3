// libFuzzer target: G-code (docs/contours.md's subset) is accepted or refused with line:col and a
// message; whatever is accepted becomes a path table and its Intel HEX.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "emu/gcode/gcode.h"
#include "emu/gcode/path_table.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;
    using namespace alp85::gcode;
    const Parsed p = parse(std::string_view(reinterpret_cast<const char*>(data), size));
    if (p.error) {
        if (p.error->line < 1 || p.error->column < 1 || p.error->message.empty()) __builtin_trap();
        return 0;
    }
    const auto bytes = table_bytes({p.entries});
    if (bytes.size() <= kTableSize) (void)intel_hex(kTableBase, bytes);
    return 0;
}
