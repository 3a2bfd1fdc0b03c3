// The opcode table (asm/isa.h) and the core agree: every opcode of each variant, run from many
// random states, takes the table's T-states (the taken figure exactly when it transfers control),
// is the table's length, writes exactly the flags flags_written() lists, and moves the PC (and the
// stack) as its flow class says. The core is made from the table, so this checks that what it
// made of each entry is what the entry says (all_opcodes_test.cpp checks the table itself against
// the data sheets).
#include <gtest/gtest.h>

#include <iomanip>
#include <random>
#include <sstream>
#include <string>

#include "asm/isa.h"
#include "tests/cpu/both.h"

namespace alp85::test {
namespace {

using isa::Flow;

constexpr std::uint16_t kCode = 0x8000;  // where each instruction is placed
constexpr unsigned kStates = 300;        // random states per opcode

struct Seen {
    std::uint8_t flags_changed = 0;
    unsigned taken = 0, not_taken = 0;
    std::string error;  // the first disagreement
};

std::string hex(unsigned v) {
    std::ostringstream s;
    s << std::hex << std::uppercase << std::setfill('0') << std::setw(v > 0xFF ? 4 : 2) << v << 'H';
    return s.str();
}

// Runs `op` from one random state and checks length, T-states and flow; records what changed.
void run_once(Rig& rig, std::uint8_t op, std::mt19937& rng, Seen& seen) {
    const bool i8080 = rig.is8080();
    const isa::OpInfo& entry = isa::kOpcodes[op];
    const isa::OpInfo& runs = isa::kOpcodes[i8080 ? entry.alias8080 : op];  // what executes
    const Flow flow = isa::flow_of(op, i8080);
    const unsigned length = runs.length;
    const unsigned t_not = i8080 ? entry.t8080 : entry.t8085;
    const unsigned t_taken = i8080 ? entry.t8080_taken : entry.t8085_taken;

    const auto byte = [&] { return static_cast<std::uint8_t>(rng()); };
    rig.cpu.reset();
    Registers& r = rig.r();
    r.a = byte(), r.b = byte(), r.c = byte(), r.d = byte(), r.e = byte(), r.h = byte(), r.l = byte();
    // A flag byte the variant can hold: bit 3 always 0; the 8080's bit 1 always 1 and bit 5 0.
    r.f = i8080 ? static_cast<std::uint8_t>((byte() & 0xD7) | 0x02) : static_cast<std::uint8_t>(byte() & 0xF7);
    r.sp = static_cast<std::uint16_t>(0xC000 + (rng() & 0x3FFF));
    r.pc = kCode;
    for (unsigned k = 0; k < 4; ++k) rig.ram[static_cast<std::uint16_t>(r.sp + k)] = byte();  // the stack wraps at FFFFH
    rig.ram[kCode] = op;
    std::uint16_t target = 0;
    do {  // an operand address that is not the next instruction, so a taken jump shows
        target = static_cast<std::uint16_t>(rng());
    } while (target == kCode + length || (target >= kCode && target < kCode + 3));
    rig.ram[kCode + 1] = static_cast<std::uint8_t>(target);
    rig.ram[kCode + 2] = static_cast<std::uint8_t>(target >> 8);
    if (length < 3) target = 0;  // no address operand

    const Registers before = r;
    const std::uint16_t popped = static_cast<std::uint16_t>(rig.ram[before.sp] | rig.ram[static_cast<std::uint16_t>(before.sp + 1)] << 8);
    const std::uint64_t t = rig.cpu.step();
    const Registers& after = rig.r();
    seen.flags_changed |= static_cast<std::uint8_t>(before.f ^ after.f);

    const std::uint16_t next = static_cast<std::uint16_t>(kCode + length);
    const auto pushed = [&](std::uint16_t ret) {
        return after.sp == static_cast<std::uint16_t>(before.sp - 2) &&
               (rig.ram[static_cast<std::uint16_t>(before.sp - 2)] | rig.ram[static_cast<std::uint16_t>(before.sp - 1)] << 8) == ret;
    };
    // The outcome the flow class allows: taken (control went where the class says), not taken
    // (the next instruction, for the conditional classes), or neither.
    bool taken = false, not_taken = after.pc == next && (flow == Flow::Next || after.sp == before.sp);
    switch (flow) {
        case Flow::Next: taken = false; break;
        case Flow::Jump: case Flow::JumpIf: taken = after.pc == target && after.sp == before.sp; break;
        case Flow::JumpIndirect: taken = after.pc == before.hl() && after.sp == before.sp; break;
        case Flow::Call: case Flow::CallIf: taken = after.pc == target && pushed(next); break;
        case Flow::Restart: taken = after.pc == (runs.operands[0] - '0') * 8 && pushed(next); break;
        case Flow::RestartIf: taken = after.pc == 0x40 && pushed(next); break;  // RSTV: RST 8
        case Flow::Return: case Flow::ReturnIf:
            taken = after.pc == popped && after.sp == static_cast<std::uint16_t>(before.sp + 2);
            break;
        case Flow::Halt: taken = false; not_taken = not_taken && rig.cpu.halted(); break;
    }
    const bool conditional = flow == Flow::JumpIf || flow == Flow::CallIf || flow == Flow::ReturnIf || flow == Flow::RestartIf;
    const bool unconditional = !conditional && flow != Flow::Next && flow != Flow::Halt;
    std::string error;
    if (unconditional) {
        if (!taken) error = "control did not go where flow class " + std::to_string(static_cast<int>(flow)) + " says";
        else if (t != t_not || t != t_taken) error = "T-states " + std::to_string(t) + ", table " + std::to_string(t_not);
    } else if (taken) {
        if (!conditional) error = "transferred control, flow class says it does not";
        else if (t != t_taken) error = "taken in " + std::to_string(t) + " T-states, table " + std::to_string(t_taken);
    } else if (not_taken) {
        if (t != t_not) error = "T-states " + std::to_string(t) + ", table " + std::to_string(t_not);
        else if (flow != Flow::Halt && rig.cpu.halted()) error = "halted, flow class says it does not";
    } else {
        error = "PC " + hex(after.pc) + " SP " + hex(after.sp) + " after it: not the next instruction (length " +
                std::to_string(length) + ") nor where flow class " + std::to_string(static_cast<int>(flow)) + " goes";
    }
    if (taken) ++seen.taken;
    if (not_taken && !taken) ++seen.not_taken;
    if (!error.empty() && seen.error.empty()) seen.error = error + " (from A=" + hex(before.a) + " F=" + hex(before.f) + ")";
}

class TableCore : public Both {};

TEST_P(TableCore, EveryOpcodeAgreesWithItsTableEntry) {
    rig.cpu.set_fast_loops(false);
    std::mt19937 rng(85);
    const bool i8080 = rig.is8080();
    for (unsigned code = 0; code < 256; ++code) {
        const auto op = static_cast<std::uint8_t>(code);
        const isa::OpInfo& runs = isa::kOpcodes[i8080 ? isa::kOpcodes[op].alias8080 : op];
        SCOPED_TRACE(hex(op) + " " + std::string(runs.mnemonic) + " " + std::string(runs.operands));
        Seen seen;
        for (unsigned s = 0; s < kStates; ++s) run_once(rig, op, rng, seen);
        EXPECT_EQ(seen.error, "");
        // Over these states every flag the table lists changes at least once and no other does.
        // SBB A is A - A - CY: it borrows exactly when CY was set, so it writes CY's own value.
        const std::uint8_t unseen = runs.mnemonic == "SBB" && runs.operands == "A" ? isa::F_CY : 0;
        EXPECT_EQ(hex(seen.flags_changed), hex(isa::flags_written(op, i8080) & ~unseen))
            << "flags written (changed, table)";
        const Flow flow = isa::flow_of(op, i8080);
        if (flow == Flow::JumpIf || flow == Flow::CallIf || flow == Flow::ReturnIf || flow == Flow::RestartIf) {
            EXPECT_GT(seen.taken, 0u) << "a conditional transfer never taken";
            EXPECT_GT(seen.not_taken, 0u) << "a conditional transfer always taken";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Variants, TableCore, ::testing::Values(Variant::I8085, Variant::I8080), variant_name);

}  // namespace
}  // namespace alp85::test
