// The ten undocumented 8085 instructions (Dehnhardt and Sorensen, 1979; see docs/cpu.md), RIM and
// SIM, and what an 8080 executes for the same twelve bytes.
#include <gtest/gtest.h>

#include "tests/cpu/rig.h"

namespace alp85::test {
namespace {

TEST(Undocumented8085, DsubSubtractsBcFromHl) {
    Rig rig;
    rig.r().set_hl(0x1234);
    rig.r().set_bc(0x0235);
    EXPECT_EQ(rig.exec({0x08}), 10u);
    EXPECT_EQ(rig.r().hl(), 0x0FFF);
    // High byte: 12H - 02H - borrow 1 = 0FH: even parity, no AC (low digit borrowed), no CY.
    EXPECT_EQ(rig.r().f, P);
}

TEST(Undocumented8085, DsubZeroAndOverflow) {
    Rig rig;
    rig.r().set_hl(0x8123);
    rig.r().set_bc(0x8123);
    rig.exec({0x08});
    EXPECT_EQ(rig.r().hl(), 0x0000);
    EXPECT_EQ(rig.r().f, Z | AC | P);  // Z from all 16 bits
    rig.r().set_hl(0x8000);
    rig.r().set_bc(0x0001);
    rig.exec({0x08});  // -32768 - 1 overflows to 7FFFH
    EXPECT_EQ(rig.r().hl(), 0x7FFF);
    EXPECT_EQ(rig.r().f, K | V);
    rig.r().set_hl(0x0001);
    rig.r().set_bc(0x0002);
    rig.exec({0x08});  // 1 - 2 = FFFFH, borrow
    EXPECT_EQ(rig.r().hl(), 0xFFFF);
    EXPECT_EQ(rig.r().f, S | K | P | CY);
}

TEST(Undocumented8085, ArhlShiftsRightKeepingSign) {
    Rig rig;
    rig.r().set_hl(0x8003);
    rig.r().f = S | Z;
    EXPECT_EQ(rig.exec({0x10}), 7u);
    EXPECT_EQ(rig.r().hl(), 0xC001);
    EXPECT_EQ(rig.r().f, S | Z | CY);
    rig.exec({0x10});
    EXPECT_EQ(rig.r().hl(), 0xE000);
    EXPECT_EQ(rig.r().f, S | Z | CY);
    rig.exec({0x10});
    EXPECT_EQ(rig.r().hl(), 0xF000);
    EXPECT_EQ(rig.r().f, S | Z);
}

TEST(Undocumented8085, RdelRotatesDeLeftThroughCarry) {
    Rig rig;
    rig.r().set_de(0x4001);
    rig.r().f = CY;
    EXPECT_EQ(rig.exec({0x18}), 10u);
    EXPECT_EQ(rig.r().de(), 0x8003);
    // CY <- bit 15 (0); V <- bit 15 XOR bit 14 of the old value (the sign changed).
    EXPECT_EQ(rig.r().f, V);
    rig.exec({0x18});
    EXPECT_EQ(rig.r().de(), 0x0006);
    EXPECT_EQ(rig.r().f, CY | V);
    rig.exec({0x18});
    EXPECT_EQ(rig.r().de(), 0x000D);
    EXPECT_EQ(rig.r().f, 0);
}

TEST(Undocumented8085, LdhiLdsiAddAnUnsignedOffsetIntoDe) {
    Rig rig;
    rig.r().set_hl(0x12F5);
    rig.r().f = CY | Z;
    EXPECT_EQ(rig.exec({0x28, 0x10}), 10u);
    EXPECT_EQ(rig.r().de(), 0x1305);
    EXPECT_EQ(rig.r().hl(), 0x12F5);
    EXPECT_EQ(rig.r().pc, 0x0102);
    rig.r().sp = 0xFFFE;
    EXPECT_EQ(rig.exec({0x38, 0x02}), 10u);
    EXPECT_EQ(rig.r().de(), 0x0000);
    EXPECT_EQ(rig.r().f, CY | Z);  // flags untouched
}

TEST(Undocumented8085, RstvOnlyOnOverflow) {
    Rig rig;
    rig.r().sp = 0x2000;
    rig.r().f = 0;
    EXPECT_EQ(rig.exec({0xCB}), 6u);
    EXPECT_EQ(rig.r().pc, 0x0101);
    rig.r().f = V;
    EXPECT_EQ(rig.exec({0xCB}), 12u);
    EXPECT_EQ(rig.r().pc, 0x0040);
    EXPECT_EQ(rig.r().sp, 0x1FFE);
    EXPECT_EQ(rig.ram[0x1FFE], 0x01);
    EXPECT_EQ(rig.ram[0x1FFF], 0x01);
}

TEST(Undocumented8085, ShlxLhlxUseDe) {
    Rig rig;
    rig.r().set_de(0x2000);
    rig.r().set_hl(0xABCD);
    EXPECT_EQ(rig.exec({0xD9}), 10u);
    EXPECT_EQ(rig.ram[0x2000], 0xCD);
    EXPECT_EQ(rig.ram[0x2001], 0xAB);
    rig.ram[0x2000] = 0x34;
    rig.ram[0x2001] = 0x12;
    EXPECT_EQ(rig.exec({0xED}), 10u);
    EXPECT_EQ(rig.r().hl(), 0x1234);
}

TEST(Undocumented8085, JnkJkTestK) {
    Rig rig;
    rig.r().f = 0;
    EXPECT_EQ(rig.exec({0xDD, 0x00, 0x30}), 10u);  // JNK taken
    EXPECT_EQ(rig.r().pc, 0x3000);
    EXPECT_EQ(rig.exec({0xFD, 0x00, 0x30}), 7u);  // JK not taken
    EXPECT_EQ(rig.r().pc, 0x0103);
    rig.r().f = K;
    EXPECT_EQ(rig.exec({0xDD, 0x00, 0x30}), 7u);
    EXPECT_EQ(rig.r().pc, 0x0103);
    EXPECT_EQ(rig.exec({0xFD, 0x00, 0x30}), 10u);
    EXPECT_EQ(rig.r().pc, 0x3000);
}

TEST(Undocumented8085, SignedLoopWithCmpAndJk) {
    // Count A from -3 up while A < 2 (signed): CPI 2; JK back. Ends at A = 2 after 5 passes.
    Rig rig;
    rig.load(0x0100, {0x3E, 0xFD,         // MVI A,-3
                      0x06, 0x00,         // MVI B,0
                      0x04,               // 0104: INR B
                      0x3C,               //       INR A
                      0xFE, 0x02,         //       CPI 2
                      0xFD, 0x04, 0x01,   //       JK 0104H
                      0x76});             //       HLT
    rig.r().pc = 0x0100;
    rig.cpu.run(10000);
    EXPECT_TRUE(rig.cpu.halted());
    EXPECT_EQ(rig.r().a, 0x02);
    EXPECT_EQ(rig.r().b, 5);
}

TEST(Alias8080, UndocumentedBytesAreNopJmpRetCall) {
    Rig rig(Variant::I8080);
    for (std::uint8_t op : {0x08, 0x10, 0x18, 0x20, 0x28, 0x30, 0x38}) {
        rig.r().set_hl(0x1234);
        rig.r().a = 0x55;
        EXPECT_EQ(rig.exec({op, 0x00}), 4u) << int(op);  // NOP, one byte
        EXPECT_EQ(rig.r().pc, 0x0101);
        EXPECT_EQ(rig.r().hl(), 0x1234);
        EXPECT_EQ(rig.r().a, 0x55);
    }
    EXPECT_EQ(rig.exec({0xCB, 0x00, 0x30}), 10u);  // JMP
    EXPECT_EQ(rig.r().pc, 0x3000);
    rig.r().sp = 0x2000;
    for (std::uint8_t op : {0xDD, 0xED, 0xFD}) {
        EXPECT_EQ(rig.exec({op, 0x00, 0x40}), 17u) << int(op);  // CALL
        EXPECT_EQ(rig.r().pc, 0x4000);
        rig.load(0x4000, {0xD9});
        EXPECT_EQ(rig.cpu.step(), 10u);  // D9: RET
        EXPECT_EQ(rig.r().pc, 0x0103);
        EXPECT_EQ(rig.r().sp, 0x2000);
    }
}

}  // namespace
}  // namespace alp85::test
