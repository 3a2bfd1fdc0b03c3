#include "asm/disasm.h"

#include <fmt/format.h>

#include "asm/isa.h"

namespace alp85::asm85 {

std::string hex_operand(unsigned value, int digits) {
    std::string h = fmt::format("{:0{}X}", value, digits);
    if (h[0] >= 'A') h = "0" + h;
    return h + "H";
}

Disassembly disassemble(const std::function<std::uint8_t(std::uint16_t)>& read, std::uint16_t address,
                        const DisasmOptions& options) {
    Disassembly d;
    std::uint8_t op = read(address);
    d.bytes[0] = op;
    const isa::OpInfo& info = isa::kOpcodes[op];
    if (options.cpu8080 && info.set != isa::Set::Common) {
        d.text = "DB " + hex_operand(op, 2);
        return d;
    }
    d.length = info.length;
    for (int i = 1; i < info.length; ++i) d.bytes[i] = read(static_cast<std::uint16_t>(address + i));
    std::string operands;
    std::string_view tmpl = info.operands;
    while (!tmpl.empty()) {
        auto comma = tmpl.find(',');
        std::string_view slot = tmpl.substr(0, comma);
        if (!operands.empty()) operands += ',';
        if (slot == "d8" || slot == "p8") {
            operands += hex_operand(d.bytes[1], 2);
        } else if (slot == "d16" || slot == "a16") {
            auto w = static_cast<std::uint16_t>(d.bytes[1] | (d.bytes[2] << 8));
            std::optional<std::string> name;
            const auto& lookup = slot == "d16" && options.data_symbol ? options.data_symbol : options.symbol;
            if (lookup) name = lookup(w);
            operands += name ? *name : hex_operand(w, 4);
        } else {
            operands += slot;  // register, pair or RST number
        }
        if (comma == std::string_view::npos) break;
        tmpl.remove_prefix(comma + 1);
    }
    d.text = std::string(info.mnemonic);
    if (!operands.empty()) d.text += " " + operands;
    return d;
}

}  // namespace alp85::asm85
