#include "emu/debug/trace_csv.h"

#include <fmt/format.h>

#include "asm/disasm.h"

namespace alp85 {

std::string_view trace_csv_header() { return "tstate,pc,opcode,instruction,a,f,b,c,d,e,h,l,sp\n"; }

std::string trace_csv_line(const I8085& cpu, const std::function<std::uint8_t(std::uint16_t)>& peek) {
    const Registers& r = cpu.regs();
    asm85::DisasmOptions o;
    o.cpu8080 = cpu.variant() == Variant::I8080;
    const auto d = asm85::disassemble(peek, r.pc, o);
    return fmt::format("{},{:04X},{:02X},\"{}\",{:02X},{:02X},{:02X},{:02X},{:02X},{:02X},{:02X},{:02X},{:04X}\n",
                       cpu.tstates(), r.pc, d.bytes[0], d.text, r.a, r.f, r.b, r.c, r.d, r.e, r.h, r.l, r.sp);
}

}  // namespace alp85
