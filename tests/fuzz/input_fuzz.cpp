// libFuzzer target: the emulator's inputs must be accepted or refused with an error, never crash
// or hang. The first byte picks the input: a script, Intel HEX, an asm85 map, a raw snapshot
// file, a snapshot with valid framing but fuzzed section contents (restored, then run), or an
// image to disassemble.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "emu/program/disasm_listing.h"
#include "emu/program/ihex.h"
#include "emu/board/machine.h"
#include "emu/script/parser.h"
#include "emu/board/snapshot_file.h"
#include "emu/program/symbols.h"

namespace {

using namespace alp85;

void fuzz_snapshot_sections(const std::uint8_t* data, std::size_t size) {
    static const std::vector<std::uint8_t> pristine = [] {
        Machine m;
        m.run_for(5000);
        return m.snapshot_bytes();
    }();
    std::vector<snapshot::Section> sections = snapshot::decode(pristine);
    // Edits: [section, op, offset lo, offset hi, value...]
    std::size_t i = 0;
    while (i + 4 <= size) {
        auto& s = sections[data[i] % sections.size()];
        const unsigned op = data[i + 1] % 4;
        const std::size_t off = (data[i + 2] | data[i + 3] << 8) % (s.data.size() + 1);
        i += 4;
        if (op == 0 && i < size && off < s.data.size()) s.data[off] = data[i++];  // overwrite a byte
        else if (op == 1) s.data.resize(off);                                       // truncate
        else if (op == 2 && i < size) s.data.insert(s.data.begin() + off, data[i++]);  // insert
        else if (op == 3 && off < s.data.size()) s.data[off] ^= 0xFF;
    }
    Machine m;
    try {
        m.restore_bytes(snapshot::encode(sections));
    } catch (const snapshot::SnapshotError&) {
        return;
    }
    m.run_for(20000);  // whatever was accepted must run
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 64 * 1024) return 0;
    const unsigned mode = data[0] % 6;
    ++data, --size;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    switch (mode) {
        case 0: {
            std::vector<script::ParseError> errors;
            (void)script::parse_script(text, "fuzz.alp", errors);
            break;
        }
        case 1:
            (void)load_intel_hex(text, [](std::uint16_t, std::uint8_t) {});
            break;
        case 2: {
            SymbolTable t;
            (void)t.load_map_text(text);
            (void)t.name_at(0x0800);
            break;
        }
        case 3:
            try {
                (void)snapshot::decode(std::vector<std::uint8_t>(data, data + size));
            } catch (const snapshot::SnapshotError&) {
            }
            break;
        case 4:
            fuzz_snapshot_sections(data, size);
            break;
        case 5: {
            if (size < 3) break;
            SymbolTable syms;
            syms.add("HERE", static_cast<std::uint16_t>(data[1] << 8 | data[0]), data[2] & 1 ? "label" : "equ");
            ImageDisasmOptions o;
            o.variant = data[2] & 2 ? Variant::I8080 : Variant::I8085;
            o.symbols = data[2] & 4 ? &syms : nullptr;
            const std::uint16_t at = static_cast<std::uint16_t>(0x10000 - size / 2);  // may run past FFFFH
            const DisasmResult r = disassemble_image({{at, std::vector<std::uint8_t>(data + 3, data + size)}}, o);
            (void)format_listing(r);
            (void)format_source(r, o, "fuzz");
            break;
        }
    }
    return 0;
}
