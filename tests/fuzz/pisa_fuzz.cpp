// libFuzzer target: the Pisa interpolator's inputs. The first byte picks a tape (block format,
// parsed; a short accepted tape also runs through the built-in ROM program for a bounded time)
// or a pisa-asm source (assembled, then its ROM text, listing and map written).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "asm/pisa_asm.h"
#include "emu/pisa/tape.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 32 * 1024) return 0;
    using namespace alp85;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    if (data[0] % 2 == 0) {
        const auto t = pisa::parse_tape(text);
        if (t.error && (t.error->line < 1 || t.error->message.empty())) __builtin_trap();
        return 0;
    }
    const auto r = pisa_asm::assemble_string(text, {}, "fuzz.pasm");
    if (r.ok()) {
        (void)pisa_asm::write_rom_text(r);
        (void)asm85::write_listing(r.out, pisa_asm::output_format());
        (void)asm85::write_json_map(r.out, pisa_asm::output_format());
    }
    return 0;
}
