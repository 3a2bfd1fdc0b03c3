// The CPU's part of a machine snapshot: one field list (fields) for save and load.
#include "emu/core/i8085.h"
#include "peripherals/state_io.h"

namespace alp85 {
namespace {
constexpr std::uint8_t kVersion = 2;

// Everything the CPU remembers, as plain data for the field list.
struct CpuState {
    Variant variant = Variant::I8085;
    Registers r;
    std::uint64_t t = 0, instructions = 0;
    bool ie = false, ei_delay = false, trap_ie = false, trap_rim = false, halted = false;
    bool rst75_latch = false, rst75_pin = false, trap_latch = false, trap_pin = false;
    bool rst65_pin = false, rst55_pin = false, intr_pin = false, sid = false, sod = false, hold = false, hlda = false;
    std::uint8_t masks = 0;

    template <class S, class Io>
    static void fields(S& s, Io& io) {
        io(s.variant, Variant::I8080);
        io(s.r.a), io(s.r.f), io(s.r.b), io(s.r.c), io(s.r.d), io(s.r.e), io(s.r.h), io(s.r.l), io(s.r.sp), io(s.r.pc);
        io(s.t), io(s.instructions);
        io(s.ie), io(s.ei_delay), io(s.trap_ie), io(s.trap_rim), io(s.halted), io(s.rst75_latch), io(s.rst75_pin);
        io(s.trap_latch), io(s.trap_pin), io(s.rst65_pin), io(s.rst55_pin), io(s.intr_pin), io(s.sid), io(s.sod);
        io(s.hold), io(s.hlda), io(s.masks, 7);
    }
};
}  // namespace

void I8085::save(std::vector<std::uint8_t>& out) const {
    const CpuState s{variant_, r_, t_, instructions_, ie_, ei_delay_, trap_ie_, trap_rim_, halted_, rst75_latch_,
                     rst75_pin_, trap_latch_, trap_pin_, rst65_pin_, rst55_pin_, intr_pin_, sid_, sod_, hold_, hlda_,
                     masks_};
    StateWriter w(out);
    w.header('8', '5', kVersion);
    CpuState::fields(s, w);
}

void I8085::load(std::span<const std::uint8_t> in) {
    StateReader r(in, "CPU");
    r.expect_header('8', '5', kVersion);
    CpuState s;
    CpuState::fields(s, r);
    r.expect_end();
    r.check(s.variant == variant_, "CPU variant differs");
    // Valid: commit.
    r_ = s.r;
    t_ = s.t;
    instructions_ = s.instructions;
    ie_ = s.ie, ei_delay_ = s.ei_delay, trap_ie_ = s.trap_ie, trap_rim_ = s.trap_rim, halted_ = s.halted;
    rst75_latch_ = s.rst75_latch, rst75_pin_ = s.rst75_pin, trap_latch_ = s.trap_latch, trap_pin_ = s.trap_pin;
    rst65_pin_ = s.rst65_pin, rst55_pin_ = s.rst55_pin, intr_pin_ = s.intr_pin, sid_ = s.sid, sod_ = s.sod;
    hold_ = s.hold, hlda_ = s.hlda;
    masks_ = s.masks;
    deadline_ = limit_ = t_;
}

}  // namespace alp85
