// Data transfer group: MOV, MVI, LXI, LDA/STA, LHLD/SHLD, LDAX/STAX, XCHG (8085/8080 data sheets).
#include "tests/cpu/both.h"

namespace alp85::test {
namespace {

class Transfer : public Both {};

TEST_P(Transfer, MovRegisterToRegister) {
    rig.r().c = 0x5A;
    EXPECT_EQ(rig.exec({0x41}), T(4, 5));  // MOV B,C
    EXPECT_EQ(rig.r().b, 0x5A);
    EXPECT_EQ(rig.r().pc, 0x0101);
}

TEST_P(Transfer, MovFromAndToMemory) {
    rig.r().set_hl(0x2345);
    rig.ram[0x2345] = 0x77;
    EXPECT_EQ(rig.exec({0x7E}), 7u);  // MOV A,M
    EXPECT_EQ(rig.r().a, 0x77);
    rig.r().e = 0x19;
    EXPECT_EQ(rig.exec({0x73}), 7u);  // MOV M,E
    EXPECT_EQ(rig.ram[0x2345], 0x19);
}

TEST_P(Transfer, MviRegisterAndMemory) {
    EXPECT_EQ(rig.exec({0x16, 0xC3}), 7u);  // MVI D,0C3H
    EXPECT_EQ(rig.r().d, 0xC3);
    EXPECT_EQ(rig.r().pc, 0x0102);
    rig.r().set_hl(0x3000);
    EXPECT_EQ(rig.exec({0x36, 0x81}), 10u);  // MVI M,81H
    EXPECT_EQ(rig.ram[0x3000], 0x81);
}

TEST_P(Transfer, LxiEveryPair) {
    EXPECT_EQ(rig.exec({0x01, 0x34, 0x12}), 10u);
    EXPECT_EQ(rig.r().bc(), 0x1234);
    EXPECT_EQ(rig.exec({0x11, 0x78, 0x56}), 10u);
    EXPECT_EQ(rig.r().de(), 0x5678);
    EXPECT_EQ(rig.exec({0x21, 0xBC, 0x9A}), 10u);
    EXPECT_EQ(rig.r().hl(), 0x9ABC);
    EXPECT_EQ(rig.exec({0x31, 0xF0, 0xDE}), 10u);
    EXPECT_EQ(rig.r().sp, 0xDEF0);
    EXPECT_EQ(rig.r().pc, 0x0103);
}

TEST_P(Transfer, LdaSta) {
    rig.ram[0x4321] = 0x9C;
    EXPECT_EQ(rig.exec({0x3A, 0x21, 0x43}), 13u);
    EXPECT_EQ(rig.r().a, 0x9C);
    rig.r().a = 0x3D;
    EXPECT_EQ(rig.exec({0x32, 0x00, 0x50}), 13u);
    EXPECT_EQ(rig.ram[0x5000], 0x3D);
}

TEST_P(Transfer, LhldShld) {
    rig.ram[0x2000] = 0x11;
    rig.ram[0x2001] = 0x22;
    EXPECT_EQ(rig.exec({0x2A, 0x00, 0x20}), 16u);
    EXPECT_EQ(rig.r().hl(), 0x2211);
    rig.r().set_hl(0xBEEF);
    EXPECT_EQ(rig.exec({0x22, 0x10, 0x20}), 16u);
    EXPECT_EQ(rig.ram[0x2010], 0xEF);
    EXPECT_EQ(rig.ram[0x2011], 0xBE);
}

TEST_P(Transfer, LdaxStax) {
    rig.r().set_bc(0x2100);
    rig.r().set_de(0x2200);
    rig.ram[0x2100] = 0xA1;
    rig.ram[0x2200] = 0xA2;
    EXPECT_EQ(rig.exec({0x0A}), 7u);
    EXPECT_EQ(rig.r().a, 0xA1);
    EXPECT_EQ(rig.exec({0x1A}), 7u);
    EXPECT_EQ(rig.r().a, 0xA2);
    rig.r().a = 0x5E;
    EXPECT_EQ(rig.exec({0x02}), 7u);
    EXPECT_EQ(rig.ram[0x2100], 0x5E);
    rig.r().a = 0x5F;
    EXPECT_EQ(rig.exec({0x12}), 7u);
    EXPECT_EQ(rig.ram[0x2200], 0x5F);
}

TEST_P(Transfer, Xchg) {
    rig.r().set_de(0x1234);
    rig.r().set_hl(0xABCD);
    EXPECT_EQ(rig.exec({0xEB}), 4u);
    EXPECT_EQ(rig.r().de(), 0xABCD);
    EXPECT_EQ(rig.r().hl(), 0x1234);
}

TEST_P(Transfer, FlagsUntouchedByTransfers) {
    rig.r().f = F(S | Z | AC | P | CY);
    rig.exec({0x78});              // MOV A,B
    rig.exec({0x3E, 0x00});        // MVI A,0
    rig.exec({0x21, 0x00, 0x00});  // LXI H,0
    EXPECT_EQ(rig.r().f, F(S | Z | AC | P | CY));
}

INSTANTIATE_TEST_SUITE_P(Variants, Transfer, ::testing::Values(Variant::I8085, Variant::I8080), variant_name);

}  // namespace
}  // namespace alp85::test
