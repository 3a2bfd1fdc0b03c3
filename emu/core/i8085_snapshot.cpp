// The CPU's part of a machine snapshot.
#include "emu/core/i8085.h"
#include "emu/util/state_io.h"

namespace alp85 {
namespace {
constexpr std::uint8_t kTag = 0x85;
constexpr std::uint8_t kVersion = 1;
}  // namespace

void I8085::save(std::vector<std::uint8_t>& out) const {
    ByteWriter w(out);
    w.u8(kTag);
    w.u8(kVersion);
    w.u8(static_cast<std::uint8_t>(variant_));
    for (std::uint8_t v : {r_.a, r_.f, r_.b, r_.c, r_.d, r_.e, r_.h, r_.l}) w.u8(v);
    w.u16(r_.sp);
    w.u16(r_.pc);
    w.u64(t_);
    w.u64(instructions_);
    for (bool b : {ie_, ei_delay_, trap_ie_, trap_rim_, halted_, rst75_latch_, rst75_pin_, trap_latch_, trap_pin_,
                   rst65_pin_, rst55_pin_, intr_pin_, sid_, sod_, hold_, hlda_})
        w.boolean(b);
    w.u8(masks_);
}

void I8085::load(std::span<const std::uint8_t> in) {
    ByteReader r(in, "CPU");
    if (r.u8() != kTag) r.fail("not a CPU record");
    if (r.u8() != kVersion) r.fail("unknown CPU record version");
    if (r.u8() != static_cast<std::uint8_t>(variant_)) r.fail("CPU variant differs");
    Registers regs;
    for (std::uint8_t* p : {&regs.a, &regs.f, &regs.b, &regs.c, &regs.d, &regs.e, &regs.h, &regs.l}) *p = r.u8();
    regs.sp = r.u16();
    regs.pc = r.u16();
    const std::uint64_t t = r.u64();
    const std::uint64_t n = r.u64();
    bool flags[16];
    for (bool& b : flags) b = r.boolean();
    const std::uint8_t masks = r.u8();
    if (masks > 7) r.fail("invalid interrupt masks");
    r.expect_end();
    // Valid: commit.
    r_ = regs;
    t_ = t;
    instructions_ = n;
    bool* dst[16] = {&ie_, &ei_delay_, &trap_ie_, &trap_rim_, &halted_, &rst75_latch_, &rst75_pin_, &trap_latch_,
                     &trap_pin_, &rst65_pin_, &rst55_pin_, &intr_pin_, &sid_, &sod_, &hold_, &hlda_};
    for (int i = 0; i < 16; ++i) *dst[i] = flags[i];
    masks_ = masks;
    deadline_ = limit_ = t_;
}

}  // namespace alp85
