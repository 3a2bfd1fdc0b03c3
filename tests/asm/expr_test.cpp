// Expressions: numbers, strings, $, operators and Intel's precedence (ASM80 manual):
// ( ) > HIGH LOW > * / MOD SHL SHR > + - > EQ NE LT LE GT GE > NOT > AND > OR XOR.
#include "helpers.h"

namespace alp85::asm85::test {
namespace {

// The 16-bit value of an expression, via DW.
int value(const std::string& e) {
    auto r = assemble("\tDW " + e + "\n");
    EXPECT_TRUE(r.ok()) << e << "\n" << diags(r);
    auto b = bytes(r, 0, 2);
    return b[0] | b[1] << 8;
}

TEST(Expr, NumberBases) {
    EXPECT_EQ(value("1234"), 1234);
    EXPECT_EQ(value("1234D"), 1234);
    EXPECT_EQ(value("0FFH"), 0xFF);
    EXPECT_EQ(value("0ffh"), 0xFF);
    EXPECT_EQ(value("17O"), 15);
    EXPECT_EQ(value("17Q"), 15);
    EXPECT_EQ(value("1011B"), 11);
    EXPECT_EQ(value("0BH"), 11);   // H wins: B is a hex digit here
    EXPECT_EQ(value("1$000$0000B"), 0x80);  // DR ASM: '$' separates digits
}

TEST(Expr, StringsAndLocationCounter) {
    EXPECT_EQ(value("'A'"), 0x41);
    EXPECT_EQ(value("'AB'"), 0x4142);
    EXPECT_EQ(value("''''"), 0x27);   // doubled quote
    EXPECT_EQ(value("\"\"\"\""), 0x22);
    auto r = assemble("\tORG 1000H\n\tDW $, $+2\n");
    EXPECT_EQ(bytes(r, 0x1000, 4), (std::vector<int>{0x00, 0x10, 0x04, 0x10}));
}

TEST(Expr, ArithmeticIs16BitUnsigned) {
    EXPECT_EQ(value("-1"), 0xFFFF);
    EXPECT_EQ(value("0FFFFH+2"), 1);
    EXPECT_EQ(value("7/2"), 3);
    EXPECT_EQ(value("7 MOD 2"), 1);
    EXPECT_EQ(value("1 SHL 15"), 0x8000);
    EXPECT_EQ(value("8000H SHR 15"), 1);
    EXPECT_EQ(value("1 SHL 16"), 0);
    EXPECT_EQ(value("0FFFEH/2"), 0x7FFF);  // unsigned
    EXPECT_EQ(value("-2/2"), 0xFFFF);      // unary minus is at the + - level: -(2/2)
    EXPECT_EQ(value("NOT 0"), 0xFFFF);
    EXPECT_EQ(value("HIGH 1234H"), 0x12);
    EXPECT_EQ(value("LOW 1234H"), 0x34);
    EXPECT_EQ(value("0F0H AND 3CH"), 0x30);
    EXPECT_EQ(value("0F0H OR 0FH"), 0xFF);
    EXPECT_EQ(value("0FFH XOR 0FH"), 0xF0);
}

TEST(Expr, RelationsGiveAllOnesOrZero) {
    EXPECT_EQ(value("1 EQ 1"), 0xFFFF);
    EXPECT_EQ(value("1 NE 1"), 0);
    EXPECT_EQ(value("1 LT 2"), 0xFFFF);
    EXPECT_EQ(value("2 LE 2"), 0xFFFF);
    EXPECT_EQ(value("2 GT 2"), 0);
    EXPECT_EQ(value("2 GE 3"), 0);
    EXPECT_EQ(value("-1 GT 1"), 0xFFFF);  // unsigned comparison
}

TEST(Expr, IntelPrecedence) {
    EXPECT_EQ(value("2+3*4"), 14);             // * before +
    EXPECT_EQ(value("(2+3)*4"), 20);           // parentheses first
    EXPECT_EQ(value("10-4-3"), 3);             // left to right
    EXPECT_EQ(value("100/10/5"), 2);
    EXPECT_EQ(value("HIGH 1234H*2"), 0x24);    // HIGH binds tighter than *: (12H)*2
    EXPECT_EQ(value("HIGH 1280H*2"), 0x24);    // (HIGH 1280H)*2 = 24H, not HIGH 2500H = 25H
    EXPECT_EQ(value("HIGH 1280H+1"), 0x13);    // (HIGH 1280H)+1 = 13H, not HIGH 1281H = 12H
    EXPECT_EQ(value("LOW 1234H SHR 4"), 0x03); // (LOW 1234H) SHR 4 = 34H SHR 4
    EXPECT_EQ(value("1+1 SHL 2"), 5);          // SHL is multiplicative: 1+(1 SHL 2)
    EXPECT_EQ(value("1+2 EQ 3"), 0xFFFF);      // + before EQ
    EXPECT_EQ(value("NOT 1 EQ 2"), 0xFFFF);    // EQ before NOT: NOT (1 EQ 2)
    EXPECT_EQ(value("NOT 0 AND 0FH"), 0x0F);   // NOT before AND
    EXPECT_EQ(value("1 OR 2 AND 0"), 1);       // AND before OR
    EXPECT_EQ(value("3 XOR 1 AND 1"), 2);      // AND before XOR
    EXPECT_EQ(value("1 XOR 1 OR 1"), 1);       // OR and XOR equal, left to right: (1 XOR 1) OR 1
    EXPECT_EQ(value("-2*3"), 0xFFFA);
    EXPECT_EQ(value("2*-3"), 0xFFFA);
    EXPECT_EQ(value("5 MOD 3*2"), 4);          // same level, left to right
}

TEST(Expr, ForwardReferences) {
    auto r = assemble("\tJMP LATER\n\tDW LATER-$\nLATER:\tNOP\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (std::vector<int>{0xC3, 0x05, 0x00, 0x02, 0x00, 0x00}));
}

TEST(Expr, ForwardReferenceInOrgAndDsSettles) {
    // The size of DS depends on a later EQU: a third pass makes the labels right.
    auto r = assemble("\tDS SIZE\nHERE:\tDW HERE\nSIZE\tEQU 4\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(bytes(r, 4, 2), (std::vector<int>{0x04, 0x00}));
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

TEST(Expr, ParenthesizedInstructionIsItsOpcode) {
    // ASM80: MVI A,(JMP X) loads C3H; CPI (DI) compares with F3H; (RST 0) is C7H.
    EXPECT_EQ(ok_bytes("X:\tMVI A,(JMP X)\n\tCPI (DI)\n\tDB (RST 0),(MOV A,B)+1\n"),
              (std::vector<int>{0x3E, 0xC3, 0xFE, 0xF3, 0xC7, 0x79}));
}

TEST(Expr, RegisterNamesAreValues) {
    EXPECT_EQ(ok_bytes("UR\tEQU B\nLR\tEQU C\n\tMOV UR,A\n\tDB A,LR,PSW\n"), (std::vector<int>{0x47, 7, 1, 6}));
}

TEST(Expr, SixSignificantCharactersWhenAsked) {
    Options o;
    o.name_length = 6;
    auto r = assemble_string("RESTART:\tNOP\n\tJMP RESTAR\n", o);
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (std::vector<int>{0x00, 0xC3, 0x00, 0x00}));
    EXPECT_FALSE(assemble("RESTART:\tNOP\n\tJMP RESTAR\n").ok());
}

TEST(Expr, IdenticalEquRedefinitionIsAccepted) {
    EXPECT_TRUE(assemble("K EQU 2\nK EQU 2\n").ok());
    EXPECT_FALSE(assemble("K EQU 2\nK EQU 3\n").ok());
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

TEST(Expr, ManualExamples) {
    // Intel 8080 Assembly Language Programming Manual, 2-12: three ways to write 'A'.
    EXPECT_EQ(value("5+30*2"), 'A');
    EXPECT_EQ(value("(25/5)+30*2"), 'A');
    EXPECT_EQ(value("5+(-30*-2)"), 'A');
    EXPECT_EQ(value("25 MOD 8"), 1);
    EXPECT_EQ(value("55H SHR 2"), 0x15);
    // CP/M ASM manual 3.3.6: a OR b AND NOT c+d SHL e = a OR (b AND (NOT (c + (d SHL e)))).
    // With a=1, b=0FFH, c=1, d=1, e=2: NOT (1+4) = 0FFFAH; AND 0FFH = 0FAH; OR 1 = 0FBH.
    EXPECT_EQ(value("1 OR 0FFH AND NOT 1+1 SHL 2"), 0xFB);
    // a MOD b*c SHL d = ((a MOD b) * c) SHL d: (7 MOD 4)*2 SHL 1 = 12.
    EXPECT_EQ(value("7 MOD 4*2 SHL 1"), 12);
}

}  // namespace
}  // namespace alp85::asm85::test
