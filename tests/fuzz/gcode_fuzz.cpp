// libFuzzer target: G-code (docs/contours.md's subset) is accepted or refused with line:col and a
// message; whatever is accepted becomes a path table (both methods) and its Intel HEX, every
// point of it on the table's travel.
//
// An input whose first byte is 01H or 02H is read after "G91" or "G20 G91" (a line of its own), so
// that mutations reach incremental programs and their exact accumulation often, not only when
// the fuzzer happens to spell G91.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "emu/gcode/gcode.h"
#include "emu/gcode/path_table.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;
    using namespace alp85::gcode;
    std::string_view in(reinterpret_cast<const char*>(data), size);
    std::string text;
    if (!in.empty() && (in[0] == '\x01' || in[0] == '\x02')) {
        text = in[0] == '\x01' ? "G91\n" : "G20 G91\n";
        in.remove_prefix(1);
    }
    text += in;
    const Parsed p = parse(text);
    if (p.error) {
        if (p.error->line < 1 || p.error->column < 1 || p.error->message.empty()) __builtin_trap();
        return 0;
    }
    for (const Entry& e : p.entries) {
        if (e.x > kTravel[0] || e.y > kTravel[1] || e.z > kTravel[2]) __builtin_trap();
        if (e.feed < 6 || e.feed > 1500) __builtin_trap();
    }
    const auto bytes = table_bytes({p.entries});
    if (bytes.size() <= kTableSize) (void)intel_hex(kTableBase, bytes);
    (void)table_bytes({sampling_path(p.entries, true)});
    return 0;
}
