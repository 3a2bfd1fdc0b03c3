// libFuzzer target: any bytes as assembly source must assemble or fail cleanly, never crash or
// hang. INCLUDE/MACLIB can only name a small in-memory file, so the file system stays out of it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "asm/asm85.h"
#include "asm/disasm.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;
    using namespace alp85::asm85;
    Options o;
    std::uint8_t sel = size ? data[0] : 0;
    o.cpu = sel % 3 == 0 ? Cpu::i8085 : sel % 3 == 1 ? Cpu::i8080 : Cpu::i8085u;
    o.name_length = (sel & 0x10) ? 6 : 0;
    o.defines = {{"FUZZ", "1"}};
    o.read_file = [](const std::filesystem::path& p) -> std::optional<std::string> {
        if (p.filename() == "inc.asm") return std::string("K EQU 1\nM MACRO X\n DB X\n ENDM\n");
        return std::nullopt;
    };
    std::string_view src(reinterpret_cast<const char*>(data), size);
    Result r = assemble_string(src, o, "fuzz.asm");
    for (auto& d : r.diagnostics) (void)format_diagnostic(d);
    (void)write_intel_hex(r.image);
    (void)write_listing(r);
    (void)write_json_map(r);
    if (!r.image.empty()) {
        (void)write_binary(r.image, r.image.lowest(), r.image.highest(), 0);
        auto read = [&](std::uint16_t a) { return r.image.read(a).value_or(0); };
        std::uint32_t a = r.image.lowest();
        for (int i = 0; i < 64 && a <= 0xFFFF; ++i) a += disassemble(read, static_cast<std::uint16_t>(a)).length;
    }
    return 0;
}
