// Arithmetic and logical groups. Expected flags are worked out by hand from the data sheets'
// definitions (S, Z, AC, P, CY) and, for the 8085, from the V/K rules in docs/cpu.md
// (V = carry into bit 7 XOR carry out of bit 7, K = V XOR S). F(x) is the 8085 flag byte; the
// 8080 shows the same with bit 1 set; F(x, y) gives both where they differ beyond bit 1.
#include "tests/cpu/both.h"

namespace alp85::test {
namespace {

class Arith : public Both {};

TEST_P(Arith, AddToZeroWithCarryAndHalfCarry) {
    rig.r().a = 0x3A;
    rig.r().b = 0xC6;
    EXPECT_EQ(rig.exec({0x80}), 4u);  // ADD B: 3AH + C6H = 100H
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(Z | AC | P | CY));  // +58 + -58: no overflow
}

TEST_P(Arith, AddSignedOverflow) {
    rig.r().a = 0x70;
    rig.r().c = 0x10;
    rig.exec({0x81});  // ADD C: 70H + 10H = 80H, +112 + +16 overflows
    EXPECT_EQ(rig.r().a, 0x80);
    EXPECT_EQ(rig.r().f, F(S | V, S | 0x02));  // 8085: V=1, K = V^S = 0
}

TEST_P(Arith, AdcWithCarryIn) {
    rig.r().a = 0x42;
    rig.r().c = 0x3D;
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0x89}), 4u);  // ADC C: 42H + 3DH + 1 = 80H
    EXPECT_EQ(rig.r().a, 0x80);
    EXPECT_EQ(rig.r().f, F(S | AC | V));
}

TEST_P(Arith, AddMemoryAndImmediate) {
    rig.r().set_hl(0x2000);
    rig.ram[0x2000] = 0x0F;
    rig.r().a = 0x01;
    EXPECT_EQ(rig.exec({0x86}), 7u);  // ADD M: 01H + 0FH = 10H
    EXPECT_EQ(rig.r().a, 0x10);
    EXPECT_EQ(rig.r().f, F(AC));
    EXPECT_EQ(rig.exec({0xC6, 0xF0}), 7u);  // ADI F0H: 10H + F0H = 100H
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(Z | P | CY));
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0xCE, 0x7F}), 7u);  // ACI 7FH: 00H + 7FH + 1 = 80H (overflow)
    EXPECT_EQ(rig.r().a, 0x80);
    EXPECT_EQ(rig.r().f, F(S | AC | V));
}

TEST_P(Arith, SubEqualGivesZeroNoBorrow) {
    rig.r().a = 0x3E;
    rig.r().b = 0x3E;
    EXPECT_EQ(rig.exec({0x90}), 4u);  // SUB B
    EXPECT_EQ(rig.r().a, 0x00);
    // AC is the carry out of bit 3 of A + ~B + 1: E + 1 + 1 carries.
    EXPECT_EQ(rig.r().f, F(Z | AC | P));
}

TEST_P(Arith, SubBorrow) {
    rig.r().a = 0x00;
    rig.r().d = 0x01;
    rig.exec({0x92});  // SUB D: 00H - 01H = FFH with borrow
    EXPECT_EQ(rig.r().a, 0xFF);
    // 0 - 1 = -1: no overflow; K = V^S = 1 (0 < 1 signed).
    EXPECT_EQ(rig.r().f, F(S | K | P | CY, S | P | CY | 0x02));
}

TEST_P(Arith, SbbAndSbi) {
    rig.r().a = 0x10;
    rig.r().e = 0x01;
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0x9B}), 4u);  // SBB E: 10H - 01H - 1 = 0EH
    EXPECT_EQ(rig.r().a, 0x0E);
    EXPECT_EQ(rig.r().f, F(0));  // 0EH: three ones, odd; low digit borrowed -> AC = 0
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0xDE, 0x0D}), 7u);  // SBI 0DH: 0EH - 0DH - 1 = 00H
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(Z | AC | P));
    rig.r().a = 0x05;
    EXPECT_EQ(rig.exec({0xD6, 0x06}), 7u);  // SUI 06H: 05H - 06H = FFH
    EXPECT_EQ(rig.r().a, 0xFF);
    EXPECT_EQ(rig.r().f, F(S | K | P | CY, S | P | CY | 0x02));
}

TEST_P(Arith, SignedCompareSetsK) {
    // 5 vs -3 (FDH): 5 is greater, K = 0; unsigned 05H < FDH, CY = 1.
    rig.r().a = 0x05;
    rig.r().b = 0xFD;
    EXPECT_EQ(rig.exec({0xB8}), 4u);  // CMP B
    EXPECT_EQ(rig.r().a, 0x05);
    EXPECT_EQ(rig.r().f, F(CY));
    // -3 vs 5: -3 is less, K = 1 (V = 0, S = 1).
    rig.r().a = 0xFD;
    rig.r().b = 0x05;
    rig.exec({0xB8});
    EXPECT_EQ(rig.r().f, F(S | K | AC, S | AC | 0x02));
    // -128 vs 1: 80H - 01H = 7FH overflows (V = 1), S = 0, K = 1: less.
    rig.r().a = 0x80;
    EXPECT_EQ(rig.exec({0xFE, 0x01}), 7u);  // CPI 01H
    EXPECT_EQ(rig.r().f, F(K | V, 0x02));
    rig.r().set_hl(0x2000);
    rig.ram[0x2000] = 0x80;
    EXPECT_EQ(rig.exec({0xBE}), 7u);  // CMP M: equal
    EXPECT_EQ(rig.r().f, F(Z | AC | P));
}

TEST_P(Arith, InrOverflowAt7F) {
    rig.r().b = 0x7F;
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0x04}), T(4, 5));  // INR B
    EXPECT_EQ(rig.r().b, 0x80);
    // S, AC (low digit wrapped), CY kept; 8085: V = 1, K = V^S = 0.
    EXPECT_EQ(rig.r().f, F(S | AC | V | CY, S | AC | CY | 0x02));
}

TEST_P(Arith, DcrOverflowAt80) {
    rig.r().a = 0x80;
    EXPECT_EQ(rig.exec({0x3D}), T(4, 5));  // DCR A
    EXPECT_EQ(rig.r().a, 0x7F);
    // No AC (low digit borrowed); 8085: V = 1, S = 0, K = 1.
    EXPECT_EQ(rig.r().f, F(K | V, 0x02));
}

TEST_P(Arith, InrDcrEveryRegisterAndMemory) {
    Registers& r = rig.r();
    r.b = 1, r.c = 2, r.d = 3, r.e = 4, r.h = 0x20, r.l = 0x00, r.a = 6;
    rig.ram[0x2000] = 0xFF;
    for (std::uint8_t op : {0x04, 0x0C, 0x14, 0x1C, 0x3C}) EXPECT_EQ(rig.exec({op}), T(4, 5));
    EXPECT_EQ(r.b, 2);
    EXPECT_EQ(r.c, 3);
    EXPECT_EQ(r.d, 4);
    EXPECT_EQ(r.e, 5);
    EXPECT_EQ(r.a, 7);
    EXPECT_EQ(rig.exec({0x34}), 10u);  // INR M: FFH -> 00H
    EXPECT_EQ(rig.ram[0x2000], 0x00);
    EXPECT_EQ(r.f, F(Z | AC | P));
    EXPECT_EQ(rig.exec({0x35}), 10u);  // DCR M: 00H -> FFH, CY untouched
    EXPECT_EQ(rig.ram[0x2000], 0xFF);
    EXPECT_EQ(r.f, F(S | K | P, S | P | 0x02));
    for (std::uint8_t op : {0x05, 0x0D, 0x15, 0x1D, 0x3D}) EXPECT_EQ(rig.exec({op}), T(4, 5));
    EXPECT_EQ(r.b, 1);
    EXPECT_EQ(r.e, 4);
    rig.exec({0x24});  // INR H
    rig.exec({0x2C});  // INR L
    EXPECT_EQ(r.hl(), 0x2101);
    rig.exec({0x25});  // DCR H
    rig.exec({0x2D});  // DCR L
    EXPECT_EQ(r.hl(), 0x2000);
}

TEST_P(Arith, InxDcxAndK) {
    rig.r().set_hl(0xFFFF);
    rig.r().f = F(0);
    EXPECT_EQ(rig.exec({0x23}), T(6, 5));  // INX H: FFFFH -> 0000H
    EXPECT_EQ(rig.r().hl(), 0x0000);
    EXPECT_EQ(rig.r().f, F(K, 0x02));  // 8085: K = 16-bit carry; nothing else moves
    rig.r().set_bc(0x00FF);
    EXPECT_EQ(rig.exec({0x03}), T(6, 5));  // INX B: no carry, K cleared
    EXPECT_EQ(rig.r().bc(), 0x0100);
    EXPECT_EQ(rig.r().f, F(0));
    rig.r().set_de(0x0000);
    EXPECT_EQ(rig.exec({0x1B}), T(6, 5));  // DCX D: 0000H -> FFFFH, borrow
    EXPECT_EQ(rig.r().de(), 0xFFFF);
    EXPECT_EQ(rig.r().f, F(K, 0x02));
    rig.r().sp = 0x1000;
    EXPECT_EQ(rig.exec({0x3B}), T(6, 5));  // DCX SP: no borrow
    EXPECT_EQ(rig.r().sp, 0x0FFF);
    EXPECT_EQ(rig.r().f, F(0));
    EXPECT_EQ(rig.exec({0x33}), T(6, 5));  // INX SP
    EXPECT_EQ(rig.r().sp, 0x1000);
    rig.r().set_de(0x1234);
    rig.exec({0x13});
    EXPECT_EQ(rig.r().de(), 0x1235);
    rig.r().set_bc(0x1234);
    rig.exec({0x0B});
    EXPECT_EQ(rig.r().bc(), 0x1233);
    rig.r().set_hl(0x1234);
    rig.exec({0x2B});
    EXPECT_EQ(rig.r().hl(), 0x1233);
}

TEST_P(Arith, DadEveryPair) {
    rig.r().set_hl(0xFFFF);
    rig.r().set_bc(0x0001);
    rig.r().f = F(Z | S);
    EXPECT_EQ(rig.exec({0x09}), 10u);  // DAD B
    EXPECT_EQ(rig.r().hl(), 0x0000);
    EXPECT_EQ(rig.r().f, F(Z | S | CY));  // only CY changes
    rig.r().set_de(0x1234);
    rig.exec({0x19});  // DAD D
    EXPECT_EQ(rig.r().hl(), 0x1234);
    EXPECT_EQ(rig.r().f, F(Z | S));
    rig.exec({0x29});  // DAD H
    EXPECT_EQ(rig.r().hl(), 0x2468);
    rig.r().sp = 0x0100;
    rig.exec({0x39});  // DAD SP
    EXPECT_EQ(rig.r().hl(), 0x2568);
}

TEST_P(Arith, DaaAfterBcdAdd) {
    rig.r().a = 0x38;
    rig.exec({0xC6, 0x45});  // ADI 45H: 7DH
    EXPECT_EQ(rig.r().a, 0x7D);
    EXPECT_EQ(rig.exec({0x27}), 4u);  // DAA: +06H -> 83H
    EXPECT_EQ(rig.r().a, 0x83);
    // 7DH + 06H = 83H: AC, S; 8085: the correction add overflows, V = 1, K = 0.
    EXPECT_EQ(rig.r().f, F(S | AC | V));
}

TEST_P(Arith, DaaBothDigitsAndCarry) {
    rig.r().a = 0x99;
    rig.exec({0xC6, 0x01});  // ADI 01H: 9AH
    rig.exec({0x27});        // DAA: +66H -> 00H, CY
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(Z | AC | P | CY));
    rig.r().a = 0x9B;
    rig.r().f = F(0);
    rig.exec({0x27});  // DAA: 9BH + 66H = 101H
    EXPECT_EQ(rig.r().a, 0x01);
    EXPECT_EQ(rig.r().f, F(AC | CY));
    rig.r().a = 0x12;
    rig.r().f = F(AC);  // AC set alone: +06H
    rig.exec({0x27});
    EXPECT_EQ(rig.r().a, 0x18);
    EXPECT_EQ(rig.r().f, F(P));
    rig.r().a = 0x12;
    rig.r().f = F(CY);  // CY set alone: +60H, CY stays
    rig.exec({0x27});
    EXPECT_EQ(rig.r().a, 0x72);
    EXPECT_EQ(rig.r().f, F(P | CY));
}

TEST_P(Arith, AnaAuxiliaryCarryDiffersBetweenVariants) {
    rig.r().a = 0xF0;
    rig.r().b = 0x80;
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0xA0}), 4u);  // ANA B: 80H
    EXPECT_EQ(rig.r().a, 0x80);
    // 8085: AC always set. 8080: AC = bit 3 of (F0H OR 80H) = 0. CY cleared on both.
    EXPECT_EQ(rig.r().f, F(S | AC, S | 0x02));
    rig.r().a = 0xF0;
    rig.r().c = 0x0F;
    rig.exec({0xA1});  // ANA C: 00H; 8080: bit 3 of FFH = 1
    EXPECT_EQ(rig.r().f, F(Z | AC | P, Z | AC | P | 0x02));
}

TEST_P(Arith, AniAuxiliaryCarry) {
    rig.r().a = 0x0C;
    EXPECT_EQ(rig.exec({0xE6, 0x04}), 7u);  // ANI 04H: 04H; 8080: bit 3 of 0CH = 1
    EXPECT_EQ(rig.r().a, 0x04);
    EXPECT_EQ(rig.r().f, F(AC));
    rig.r().a = 0x30;
    rig.exec({0xE6, 0x21});  // ANI 21H: 20H; 8080: bit 3 of 31H = 0
    EXPECT_EQ(rig.r().a, 0x20);
    EXPECT_EQ(rig.r().f, F(AC, 0x02));
}

TEST_P(Arith, XraOraClearCarryAndAc) {
    rig.r().a = 0x5A;
    rig.r().f = F(CY | AC);
    EXPECT_EQ(rig.exec({0xAF}), 4u);  // XRA A
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(Z | P));
    rig.r().a = 0x80;
    rig.r().l = 0x01;
    rig.r().f = F(CY);
    EXPECT_EQ(rig.exec({0xB5}), 4u);  // ORA L: 81H
    EXPECT_EQ(rig.r().a, 0x81);
    EXPECT_EQ(rig.r().f, F(S | P));
    EXPECT_EQ(rig.exec({0xEE, 0xFF}), 7u);  // XRI FFH: 7EH
    EXPECT_EQ(rig.r().a, 0x7E);
    EXPECT_EQ(rig.r().f, F(P));
    EXPECT_EQ(rig.exec({0xF6, 0x80}), 7u);  // ORI 80H: FEH
    EXPECT_EQ(rig.r().a, 0xFE);
    EXPECT_EQ(rig.r().f, F(S));
    rig.r().set_hl(0x2000);
    rig.ram[0x2000] = 0x0F;
    EXPECT_EQ(rig.exec({0xA6}), 7u);  // ANA M: 0EH
    EXPECT_EQ(rig.r().a, 0x0E);
    EXPECT_EQ(rig.exec({0xAE}), 7u);  // XRA M: 01H
    EXPECT_EQ(rig.r().a, 0x01);
    EXPECT_EQ(rig.exec({0xB6}), 7u);  // ORA M: 0FH
    EXPECT_EQ(rig.r().a, 0x0F);
}

TEST_P(Arith, AluEveryRegisterOperand) {
    // ADD r for B C D E H L A with distinct values: each picks its own register.
    Registers& r = rig.r();
    const std::uint8_t ops[] = {0x80, 0x81, 0x82, 0x83, 0x84, 0x85};
    const std::uint8_t vals[] = {0x01, 0x02, 0x04, 0x08, 0x10, 0x20};
    r.b = vals[0], r.c = vals[1], r.d = vals[2], r.e = vals[3], r.h = vals[4], r.l = vals[5];
    for (int i = 0; i < 6; ++i) {
        r.a = 0x40;
        rig.exec({ops[i]});
        EXPECT_EQ(r.a, 0x40 + vals[i]) << "op " << int(ops[i]);
    }
    r.a = 0x21;
    rig.exec({0x87});  // ADD A
    EXPECT_EQ(r.a, 0x42);
}

TEST_P(Arith, Rotates) {
    rig.r().a = 0x81;
    rig.r().f = F(S | Z | P);
    EXPECT_EQ(rig.exec({0x07}), 4u);  // RLC
    EXPECT_EQ(rig.r().a, 0x03);
    EXPECT_EQ(rig.r().f, F(S | Z | P | CY));  // only CY
    rig.r().a = 0x81;
    rig.exec({0x0F});  // RRC
    EXPECT_EQ(rig.r().a, 0xC0);
    EXPECT_EQ(rig.r().f, F(S | Z | P | CY));
    rig.r().a = 0x80;
    rig.r().f = F(0);
    rig.exec({0x17});  // RAL: CY <- 1, bit 0 <- old CY 0
    EXPECT_EQ(rig.r().a, 0x00);
    EXPECT_EQ(rig.r().f, F(CY));
    rig.r().a = 0x01;
    rig.exec({0x1F});  // RAR with CY = 1
    EXPECT_EQ(rig.r().a, 0x80);
    EXPECT_EQ(rig.r().f, F(CY));
}

TEST_P(Arith, CmaStcCmc) {
    rig.r().a = 0x51;
    rig.r().f = F(0);
    EXPECT_EQ(rig.exec({0x2F}), 4u);
    EXPECT_EQ(rig.r().a, 0xAE);
    EXPECT_EQ(rig.r().f, F(0));
    EXPECT_EQ(rig.exec({0x37}), 4u);
    EXPECT_EQ(rig.r().f, F(CY));
    EXPECT_EQ(rig.exec({0x3F}), 4u);
    EXPECT_EQ(rig.r().f, F(0));
    rig.exec({0x3F});
    EXPECT_EQ(rig.r().f, F(CY));
}

INSTANTIATE_TEST_SUITE_P(Variants, Arith, ::testing::Values(Variant::I8085, Variant::I8080), variant_name);

}  // namespace
}  // namespace alp85::test
