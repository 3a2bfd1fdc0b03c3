// libFuzzer target: the emulator's inputs must be accepted or refused with an error, never crash
// or hang. The first byte picks the input: a script, Intel HEX, an asm85 map, a raw snapshot
// file, a snapshot with valid framing but fuzzed section contents (restored, then run), or an
// image to disassemble, or a sequence of drive levels for the machine tool (both motor models,
// both feedback sources), with its sensing, snapshot round trip and views.
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
#include "peripherals/machine_tool.h"

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

// [model/feedback byte] then events of 3 bytes: T-states to wait (16 bits, so up to 21 ms), and
// the six port A bits (X/Y/Z pulse and direction); every event also reads the transducers.
void fuzz_machine_tool(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return;
    using periph::MachineTool;
    MachineTool m(3.072e6);  // T-states per second: the ALP 85's CPU clock
    m.set_model(data[0] & 1 ? MachineTool::MotorModel::Physical : MachineTool::MotorModel::Ideal);
    if (data[0] & 2) m.set_feedback(MachineTool::Feedback::Commanded);
    std::uint64_t t = 0;
    for (std::size_t i = 1; i + 3 <= size && i < 3 * 4096; i += 3) {
        t += static_cast<std::uint64_t>(data[i] | data[i + 1] << 8);
        const std::uint8_t bits = data[i + 2];
        for (int a = 0; a < 3; ++a) {
            const auto axis = static_cast<MachineTool::Axis>(a);
            m.set_drive(axis, (bits >> (2 * a)) & 1, (bits >> (2 * a + 1)) & 1, t);
            (void)m.sense(axis, t + 1);
        }
        if (bits & 0x40) m.set_model(bits & 0x80 ? MachineTool::MotorModel::Physical : MachineTool::MotorModel::Ideal);
    }
    m.advance(t + 3'072'000);  // a second more: everything settles or rings down
    std::vector<std::uint8_t> saved;
    m.save(saved);
    MachineTool copy;
    copy.load(saved);  // what it saved, it must load
    std::vector<std::uint8_t> again;
    copy.save(again);
    if (again != saved) __builtin_trap();
    for (int a = 0; a < 3; ++a) {
        const auto axis = static_cast<MachineTool::Axis>(a);
        (void)m.table_mm(axis), (void)m.lost_steps(axis), (void)m.transducer_count(axis);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 64 * 1024) return 0;
    const unsigned mode = data[0] % 7;
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
        case 6:
            fuzz_machine_tool(data, size);
            break;
    }
    return 0;
}
