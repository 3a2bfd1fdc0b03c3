// Interrupts as the 8085 data sheet describes them: TRAP, RST 7.5/6.5/5.5, INTR with INTA,
// priority, masks, SIM/RIM, the EI delay, HLT wake-up, SID/SOD and HOLD/HLDA.
#include <gtest/gtest.h>

#include <vector>

#include "tests/cpu/rig.h"

namespace alp85::test {
namespace {

// A rig whose program at 0100H is a run of NOPs, with SP at 2000H and interrupts unmasked.
struct IrqRig : Rig {
    explicit IrqRig(Variant v = Variant::I8085) : Rig(v) {
        for (unsigned a = 0x0100; a < 0x0200; ++a) ram[a] = 0x00;
        cpu.regs().pc = 0x0100;
        cpu.regs().sp = 0x2000;
    }
    void sim(std::uint8_t a) {  // MVI A,a; SIM
        cpu.regs().a = a;
        ram[0x01F0] = 0x30;
        const std::uint16_t back = cpu.regs().pc;
        cpu.regs().pc = 0x01F0;
        cpu.step();
        cpu.regs().pc = back;
    }
    std::uint8_t rim() {
        ram[0x01F0] = 0x20;
        const std::uint16_t back = cpu.regs().pc;
        cpu.regs().pc = 0x01F0;
        cpu.step();
        cpu.regs().pc = back;
        return cpu.regs().a;
    }
    void ei() {
        cpu.set_debug_hooks(nullptr);
        ram[cpu.regs().pc] = 0xFB;
        cpu.step();
    }
    std::uint16_t pushed_pc() const { return static_cast<std::uint16_t>(ram[cpu.regs().sp] | ram[cpu.regs().sp + 1] << 8); }
};

TEST(Interrupts, ResetMasksAllAndRimShowsIt) {
    IrqRig rig;
    EXPECT_EQ(rig.cpu.masks(), 0x07);
    EXPECT_EQ(rig.rim(), 0x07);  // no SID, nothing pending, IE off, all three masked
}

TEST(Interrupts, SimSetsMasksOnlyWithMse) {
    IrqRig rig;
    rig.sim(0x02);  // MSE clear: masks unchanged
    EXPECT_EQ(rig.cpu.masks(), 0x07);
    rig.sim(0x08 | 0x02);  // MSE, mask 6.5 only
    EXPECT_EQ(rig.cpu.masks(), 0x02);
    EXPECT_EQ(rig.rim() & 0x07, 0x02);
}

TEST(Interrupts, RimShowsPendingLevelsLatchIeAndSid) {
    IrqRig rig;
    rig.cpu.set_rst55(true);
    rig.cpu.set_rst65(true);
    rig.cpu.set_rst75(true);
    rig.cpu.set_sid(true);
    rig.ei();
    EXPECT_EQ(rig.rim(), 0x80 | 0x40 | 0x20 | 0x10 | 0x08 | 0x07);
}

TEST(Interrupts, Rst75EdgeLatchAndSimReset) {
    IrqRig rig;
    rig.cpu.set_rst75(true);
    rig.cpu.set_rst75(false);  // the pulse is gone, the latch holds it
    EXPECT_TRUE(rig.cpu.rst75_latched());
    EXPECT_EQ(rig.rim() & 0x40, 0x40);
    rig.cpu.set_rst75(false);  // no edge: nothing new
    rig.sim(0x10);             // R7.5
    EXPECT_FALSE(rig.cpu.rst75_latched());
    rig.cpu.set_rst75(true);  // a level that stays high is one edge only
    rig.sim(0x10);
    rig.cpu.set_rst75(true);
    EXPECT_FALSE(rig.cpu.rst75_latched());
}

TEST(Interrupts, Rst75TakenAfterUnmaskEvenIfPinFell) {
    IrqRig rig;
    rig.cpu.set_rst75(true);
    rig.cpu.set_rst75(false);
    rig.sim(0x08);  // unmask all
    rig.ei();
    rig.cpu.step();  // the instruction after EI
    const std::uint64_t t0 = rig.cpu.tstates();
    rig.cpu.step();  // acknowledge
    EXPECT_EQ(rig.r().pc, 0x003C);
    EXPECT_EQ(rig.cpu.tstates() - t0, 12u);
    EXPECT_FALSE(rig.cpu.interrupts_enabled());
    EXPECT_FALSE(rig.cpu.rst75_latched());
    EXPECT_EQ(rig.pushed_pc(), 0x0102);
}

TEST(Interrupts, PriorityOrder) {
    IrqRig rig;
    rig.sim(0x08);
    rig.cpu.set_intr(true);
    rig.cpu.set_rst55(true);
    rig.cpu.set_rst65(true);
    rig.cpu.set_rst75(true);
    rig.cpu.set_trap(true);
    rig.cpu.step();  // TRAP first: it needs neither IE nor an unmasked input
    EXPECT_EQ(rig.r().pc, 0x0024);
    const std::uint16_t expect[] = {0x3C, 0x34, 0x2C, 0x38};  // 7.5, 6.5, 5.5, INTR (RST 7)
    for (std::uint16_t vector : expect) {
        rig.ram[rig.r().pc] = 0xFB;  // EI at the handler; the next instruction is a NOP
        rig.cpu.step();
        rig.cpu.step();
        rig.cpu.step();
        EXPECT_EQ(rig.r().pc, vector);
        if (vector == 0x34) rig.cpu.set_rst65(false);
        if (vector == 0x2C) rig.cpu.set_rst55(false);
    }
}

TEST(Interrupts, MaskedLevelsAreNotTaken) {
    IrqRig rig;
    rig.sim(0x08 | 0x03);  // mask 6.5 and 5.5
    rig.cpu.set_rst55(true);
    rig.cpu.set_rst65(true);
    rig.ei();
    for (int i = 0; i < 5; ++i) rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0106);
    rig.sim(0x08 | 0x01);  // unmask 6.5
    rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0034);
}

TEST(Interrupts, DisabledInterruptsAreNotTaken) {
    IrqRig rig;
    rig.sim(0x08);
    rig.cpu.set_rst55(true);
    rig.cpu.set_intr(true);
    for (int i = 0; i < 5; ++i) rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0105);
}

TEST(Interrupts, EiDelaysByOneInstruction) {
    IrqRig rig;
    rig.cpu.set_intr(true);  // RST 7 from the floating bus
    rig.ram[0x0100] = 0xFB;  // EI
    rig.ram[0x0101] = 0x3C;  // INR A
    rig.r().a = 0;
    rig.cpu.step();  // EI
    EXPECT_EQ(rig.r().pc, 0x0101);
    rig.cpu.step();  // INR A still runs
    EXPECT_EQ(rig.r().a, 1);
    EXPECT_EQ(rig.r().pc, 0x0102);
    rig.cpu.step();  // now the interrupt
    EXPECT_EQ(rig.r().pc, 0x0038);
    EXPECT_EQ(rig.pushed_pc(), 0x0102);
}

TEST(Interrupts, EiDelayHoldsAcrossRunBoundaries) {
    IrqRig rig;
    rig.cpu.set_intr(true);
    rig.ram[0x0100] = 0xFB;
    rig.cpu.run(rig.cpu.tstates() + 1);  // ends right after EI
    rig.cpu.run(rig.cpu.tstates() + 1);  // the next run must execute the NOP first
    EXPECT_EQ(rig.r().pc, 0x0102);
}

TEST(Interrupts, EiHltWakesOnInterrupt) {
    IrqRig rig;
    rig.sim(0x08);
    rig.ram[0x0100] = 0xFB;  // EI
    rig.ram[0x0101] = 0x76;  // HLT
    rig.cpu.run(1000);
    EXPECT_TRUE(rig.cpu.halted());
    EXPECT_EQ(rig.cpu.tstates(), 1000u);  // idled to the deadline
    rig.cpu.set_rst65(true);
    rig.cpu.run(1001);
    EXPECT_FALSE(rig.cpu.halted());
    EXPECT_EQ(rig.r().pc, 0x0034);
    EXPECT_EQ(rig.pushed_pc(), 0x0102);  // returns after the HLT
    EXPECT_EQ(rig.cpu.tstates(), 1012u);
}

TEST(Interrupts, TrapIsNonMaskableAndSavesIe) {
    IrqRig rig;
    rig.ei();
    rig.cpu.set_trap(true);
    rig.cpu.step();  // TRAP ignores the EI delay
    EXPECT_EQ(rig.r().pc, 0x0024);
    EXPECT_FALSE(rig.cpu.interrupts_enabled());
    rig.cpu.set_trap(false);
    EXPECT_EQ(rig.rim() & 0x08, 0x08);  // RIM after TRAP: IE as it was before TRAP
    EXPECT_EQ(rig.rim() & 0x08, 0x00);  // afterwards the current IE
}

TEST(Interrupts, TrapTakenWithInterruptsDisabledAndNotMaskedBySim) {
    IrqRig rig;
    rig.sim(0x08 | 0x07);
    rig.cpu.set_trap(true);
    rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0024);
    EXPECT_EQ(rig.rim() & 0x08, 0x00);  // IE was off before TRAP
}

TEST(Interrupts, TrapNeedsEdgeAndLevel) {
    IrqRig rig;
    rig.cpu.set_trap(true);
    rig.cpu.set_trap(false);  // edge seen but the level has gone
    rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0101);
    rig.cpu.set_trap(true);  // a new edge
    rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0024);
    rig.cpu.step();  // level still high but no new edge: not taken again
    EXPECT_EQ(rig.r().pc, 0x0025);
}

TEST(Interrupts, IntrAcknowledgeWithCall) {
    for (Variant v : {Variant::I8085, Variant::I8080}) {
        IrqRig rig(v);
        std::vector<unsigned> cycles;
        const std::uint8_t bytes[] = {0xCD, 0x34, 0x12};
        rig.cpu.on_inta = [&](unsigned n) {
            cycles.push_back(n);
            return bytes[n];
        };
        rig.cpu.set_intr(true);
        rig.ei();
        rig.cpu.step();
        const std::uint64_t t0 = rig.cpu.tstates();
        rig.cpu.step();
        EXPECT_EQ(rig.r().pc, 0x1234);
        EXPECT_EQ(rig.cpu.tstates() - t0, v == Variant::I8085 ? 18u : 17u);
        EXPECT_EQ(cycles, (std::vector<unsigned>{0, 1, 2}));
        EXPECT_EQ(rig.pushed_pc(), 0x0102);
        EXPECT_FALSE(rig.cpu.interrupts_enabled());
    }
}

TEST(Interrupts, IntrAcknowledgeWithRst) {
    for (Variant v : {Variant::I8085, Variant::I8080}) {
        IrqRig rig(v);
        rig.cpu.on_inta = [](unsigned) -> std::uint8_t { return 0xEF; };  // RST 5
        rig.cpu.set_intr(true);
        rig.ei();
        rig.cpu.step();
        const std::uint64_t t0 = rig.cpu.tstates();
        rig.cpu.step();
        EXPECT_EQ(rig.r().pc, 0x0028);
        EXPECT_EQ(rig.cpu.tstates() - t0, v == Variant::I8085 ? 12u : 11u);
    }
}

TEST(Interrupts, The8080HasOnlyIntr) {
    IrqRig rig(Variant::I8080);
    rig.cpu.set_trap(true);
    rig.cpu.set_rst75(true);
    rig.cpu.set_rst65(true);
    rig.ei();
    rig.cpu.step();
    rig.cpu.step();
    EXPECT_EQ(rig.r().pc, 0x0103);
}

TEST(Interrupts, SodFollowsSimWithSde) {
    IrqRig rig;
    std::vector<bool> levels;
    rig.cpu.on_sod = [&](bool level) { levels.push_back(level); };
    rig.sim(0x80);  // SOD bit without SDE: ignored
    EXPECT_FALSE(rig.cpu.sod());
    rig.sim(0xC0);
    EXPECT_TRUE(rig.cpu.sod());
    rig.sim(0xC0);  // no change, no callback
    rig.sim(0x40);
    EXPECT_FALSE(rig.cpu.sod());
    EXPECT_EQ(levels, (std::vector<bool>{true, false}));
}

TEST(Interrupts, HoldIdlesTheCpuAndRaisesHlda) {
    IrqRig rig;
    std::vector<bool> hlda;
    rig.cpu.on_hlda = [&](bool level) { hlda.push_back(level); };
    rig.cpu.set_hold(true);
    EXPECT_EQ(rig.cpu.run(100), 100u);
    EXPECT_EQ(rig.r().pc, 0x0100);
    rig.cpu.set_hold(false);
    rig.cpu.run(104);
    EXPECT_EQ(rig.r().pc, 0x0101);
    EXPECT_EQ(hlda, (std::vector<bool>{true, false}));
}

TEST(Interrupts, PinChangeFromHandlerIsSeenAfterTheInstruction) {
    // An OUT whose handler raises RST 6.5: taken right after the OUT, within the same run.
    IrqRig rig;
    IoFunctions io;
    io.on_out = [&](std::uint8_t, std::uint8_t, std::uint64_t) { rig.cpu.set_rst65(true); };
    rig.bus.map_io(0x10, 0x10, io);
    rig.sim(0x08);
    rig.ram[0x0100] = 0xFB;  // EI
    rig.ram[0x0101] = 0x00;  // NOP
    rig.ram[0x0102] = 0xD3;  // OUT 10H
    rig.ram[0x0103] = 0x10;
    rig.cpu.run(rig.cpu.tstates() + 4 + 4 + 10 + 12);
    EXPECT_EQ(rig.r().pc, 0x0034);
    EXPECT_EQ(rig.pushed_pc(), 0x0104);
}

}  // namespace
}  // namespace alp85::test
