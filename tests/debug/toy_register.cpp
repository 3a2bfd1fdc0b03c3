// The CPU's description with a toy register added in one line, linked by the toy-register tests in
// place of emu/core/cpu_description.cpp (which defines cpu::description() alone, so the linker
// takes this definition and never that one). Nothing else differs from the alp85 build: every
// front end's code is the library's, compiled once.
//
// The toy: SPH, the stack pointer's high byte, an 8-bit register of its own (SP = 20AEH: SPH =
// 20H; SPH = 12H: SP = 12AEH).
#include "emu/core/cpu_registers.h"

namespace alp85::cpu {

namespace {
std::uint16_t read_sph(const Registers& r) { return r.sp >> 8; }
void write_sph(Registers& r, std::uint16_t v) { r.sp = static_cast<std::uint16_t>((v & 0xFF) << 8 | (r.sp & 0xFF)); }
}  // namespace

const Description& description() {
    static const Description d = [] {
        Description x = i8085_description();
        x.registers.push_back({"SPH", Register::Kind::Byte, 8, read_sph, write_sph, {}, {}, false, "the toy"});  // the line
        return x;
    }();
    return d;
}

}  // namespace alp85::cpu
