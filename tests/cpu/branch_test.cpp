// Branch, stack, I/O and machine control groups, with the T-states of taken and untaken
// conditions from the 8085 and 8080 data sheets.
#include "tests/cpu/both.h"

namespace alp85::test {
namespace {

class Branch : public Both {};

TEST_P(Branch, Jmp) {
    EXPECT_EQ(rig.exec({0xC3, 0x34, 0x12}), 10u);
    EXPECT_EQ(rig.r().pc, 0x1234);
}

TEST_P(Branch, ConditionalJumpsTakenAndNot) {
    // Each condition once true and once false: opcode, flags that make it true.
    struct Case {
        std::uint8_t op, when_true, when_false;
    };
    const Case cases[] = {{0xC2, 0, Z},  {0xCA, Z, 0},  {0xD2, 0, CY}, {0xDA, CY, 0},
                          {0xE2, 0, P},  {0xEA, P, 0},  {0xF2, 0, S},  {0xFA, S, 0}};
    for (const Case& c : cases) {
        rig.r().f = F(c.when_true);
        EXPECT_EQ(rig.exec({c.op, 0x00, 0x30}), T(10, 10)) << std::hex << int(c.op);
        EXPECT_EQ(rig.r().pc, 0x3000);
        rig.r().f = F(c.when_false);
        EXPECT_EQ(rig.exec({c.op, 0x00, 0x30}), T(7, 10)) << std::hex << int(c.op);
        EXPECT_EQ(rig.r().pc, 0x0103);
    }
}

TEST_P(Branch, CallAndRet) {
    rig.r().sp = 0x2000;
    EXPECT_EQ(rig.exec({0xCD, 0x00, 0x40}), T(18, 17));
    EXPECT_EQ(rig.r().pc, 0x4000);
    EXPECT_EQ(rig.r().sp, 0x1FFE);
    EXPECT_EQ(rig.ram[0x1FFE], 0x03);  // return address 0103H, low byte at the lower address
    EXPECT_EQ(rig.ram[0x1FFF], 0x01);
    rig.load(0x4000, {0xC9});
    EXPECT_EQ(rig.cpu.step(), 10u);
    EXPECT_EQ(rig.r().pc, 0x0103);
    EXPECT_EQ(rig.r().sp, 0x2000);
}

TEST_P(Branch, ConditionalCallsAndReturns) {
    const std::uint8_t calls[] = {0xC4, 0xCC, 0xD4, 0xDC, 0xE4, 0xEC, 0xF4, 0xFC};
    const std::uint8_t rets[] = {0xC0, 0xC8, 0xD0, 0xD8, 0xE0, 0xE8, 0xF0, 0xF8};
    const std::uint8_t flag_true[] = {0, Z, 0, CY, 0, P, 0, S};
    const std::uint8_t flag_false[] = {Z, 0, CY, 0, P, 0, S, 0};
    for (int i = 0; i < 8; ++i) {
        rig.r().sp = 0x2000;
        rig.r().f = F(flag_false[i]);
        EXPECT_EQ(rig.exec({calls[i], 0x00, 0x40}), T(9, 11)) << i;
        EXPECT_EQ(rig.r().pc, 0x0103);
        EXPECT_EQ(rig.r().sp, 0x2000);
        rig.r().f = F(flag_true[i]);
        EXPECT_EQ(rig.exec({calls[i], 0x00, 0x40}), T(18, 17)) << i;
        EXPECT_EQ(rig.r().pc, 0x4000);
        EXPECT_EQ(rig.r().sp, 0x1FFE);
        rig.r().f = F(flag_false[i]);
        EXPECT_EQ(rig.exec({rets[i]}), T(6, 5)) << i;
        EXPECT_EQ(rig.r().pc, 0x0101);
        rig.r().f = F(flag_true[i]);
        EXPECT_EQ(rig.exec({rets[i]}), T(12, 11)) << i;
        EXPECT_EQ(rig.r().pc, 0x0103);
        EXPECT_EQ(rig.r().sp, 0x2000);
    }
}

TEST_P(Branch, RstPushesAndVectors) {
    for (unsigned n = 0; n < 8; ++n) {
        rig.r().sp = 0x2000;
        EXPECT_EQ(rig.exec({static_cast<std::uint8_t>(0xC7 | n << 3)}), T(12, 11));
        EXPECT_EQ(rig.r().pc, n * 8);
        EXPECT_EQ(rig.ram[0x1FFE], 0x01);
        EXPECT_EQ(rig.ram[0x1FFF], 0x01);
    }
}

TEST_P(Branch, PchlSphlXthl) {
    rig.r().set_hl(0x2345);
    EXPECT_EQ(rig.exec({0xE9}), T(6, 5));
    EXPECT_EQ(rig.r().pc, 0x2345);
    EXPECT_EQ(rig.exec({0xF9}), T(6, 5));
    EXPECT_EQ(rig.r().sp, 0x2345);
    rig.ram[0x2345] = 0x11;
    rig.ram[0x2346] = 0x22;
    EXPECT_EQ(rig.exec({0xE3}), T(16, 18));
    EXPECT_EQ(rig.r().hl(), 0x2211);
    EXPECT_EQ(rig.ram[0x2345], 0x45);
    EXPECT_EQ(rig.ram[0x2346], 0x23);
}

TEST_P(Branch, PushPopPairs) {
    rig.r().sp = 0x3000;
    rig.r().set_bc(0x0102);
    rig.r().set_de(0x0304);
    rig.r().set_hl(0x0506);
    EXPECT_EQ(rig.exec({0xC5}), T(12, 11));
    EXPECT_EQ(rig.exec({0xD5}), T(12, 11));
    EXPECT_EQ(rig.exec({0xE5}), T(12, 11));
    EXPECT_EQ(rig.r().sp, 0x2FFA);
    EXPECT_EQ(rig.ram[0x2FFF], 0x01);
    EXPECT_EQ(rig.ram[0x2FFE], 0x02);
    EXPECT_EQ(rig.exec({0xC1}), 10u);  // POP B gets HL's value
    EXPECT_EQ(rig.exec({0xD1}), 10u);
    EXPECT_EQ(rig.exec({0xE1}), 10u);
    EXPECT_EQ(rig.r().bc(), 0x0506);
    EXPECT_EQ(rig.r().de(), 0x0304);
    EXPECT_EQ(rig.r().hl(), 0x0102);
    EXPECT_EQ(rig.r().sp, 0x3000);
}

TEST_P(Branch, PushPopPswUnusedBits) {
    rig.r().sp = 0x3000;
    rig.ram[0x2FFE] = 0xFF;  // flags byte
    rig.ram[0x2FFF] = 0x5A;  // A
    rig.r().sp = 0x2FFE;
    EXPECT_EQ(rig.exec({0xF1}), 10u);  // POP PSW
    EXPECT_EQ(rig.r().a, 0x5A);
    // 8085: bit 3 does not exist (V and K do); 8080: bits 3 and 5 read 0, bit 1 reads 1.
    EXPECT_EQ(rig.r().f, F(0xF7, 0xD7));
    EXPECT_EQ(rig.exec({0xF5}), T(12, 11));  // PUSH PSW
    EXPECT_EQ(rig.ram[0x2FFE], F(0xF7, 0xD7));
    rig.ram[0x2FFE] = 0x00;
    rig.exec({0xF1});
    EXPECT_EQ(rig.r().f, F(0x00, 0x02));
}

TEST_P(Branch, InOutGoThroughPortHandlers) {
    IoFunctions io;
    std::uint8_t seen_port = 0, seen_value = 0;
    std::uint64_t seen_t = 0;
    io.on_out = [&](std::uint8_t p, std::uint8_t v, std::uint64_t t) { seen_port = p, seen_value = v, seen_t = t; };
    io.on_in = [&](std::uint8_t p, std::uint64_t t) -> std::uint8_t {
        seen_port = p, seen_t = t;
        return 0x3C;
    };
    rig.bus.map_io(0xE0, 0xE1, io);
    rig.cpu.reset_counters();
    rig.r().a = 0x99;
    EXPECT_EQ(rig.exec({0xD3, 0xE1}), 10u);
    EXPECT_EQ(seen_port, 0xE1);
    EXPECT_EQ(seen_value, 0x99);
    EXPECT_EQ(seen_t, 7u);  // opcode fetch 4 + port read 3: the I/O cycle starts at T-state 7
    EXPECT_EQ(rig.exec({0xDB, 0xE0}), 10u);
    EXPECT_EQ(seen_port, 0xE0);
    EXPECT_EQ(rig.r().a, 0x3C);
    EXPECT_EQ(seen_t, 17u);
    EXPECT_EQ(rig.exec({0xDB, 0x10}), 10u);  // unmapped port: floating bus
    EXPECT_EQ(rig.r().a, 0xFF);
}

TEST_P(Branch, NopDiEi) {
    EXPECT_EQ(rig.exec({0x00}), 4u);
    EXPECT_EQ(rig.r().pc, 0x0101);
    EXPECT_EQ(rig.exec({0xFB}), 4u);
    EXPECT_TRUE(rig.cpu.interrupts_enabled());
    EXPECT_EQ(rig.exec({0xF3}), 4u);
    EXPECT_FALSE(rig.cpu.interrupts_enabled());
}

TEST_P(Branch, HltStopsTheCpu) {
    EXPECT_EQ(rig.exec({0x76}), T(5, 7));
    EXPECT_TRUE(rig.cpu.halted());
    EXPECT_EQ(rig.r().pc, 0x0101);
    // Halted with interrupts off: time passes, nothing executes.
    EXPECT_EQ(rig.cpu.run(rig.cpu.tstates() + 1000), 1000u);
    EXPECT_EQ(rig.r().pc, 0x0101);
}

INSTANTIATE_TEST_SUITE_P(Variants, Branch, ::testing::Values(Variant::I8085, Variant::I8080), variant_name);

}  // namespace
}  // namespace alp85::test
