// MACRO/ENDM with parameters, <...> arguments, LOCAL, nesting, EXITM, REPT, IRP, IRPC.
#include "helpers.h"

namespace alp85::asm85::test {
namespace {

using V = std::vector<int>;

TEST(Macros, ParametersAreSubstituted) {
    const char* src =
        "LOADP\tMACRO RP,VAL\n\tLXI RP,VAL\n\tENDM\n"
        "\tLOADP H,1234H\n\tLOADP D,5\n";
    EXPECT_EQ(ok_bytes(src), (V{0x21, 0x34, 0x12, 0x11, 0x05, 0x00}));
}

TEST(Macros, MissingArgumentsAreEmptyAndAngleBracketsGroupCommas) {
    const char* src =
        "BYTES\tMACRO LIST,EXTRA\n\tDB LIST\n\tIFNB <EXTRA>\n\tDB EXTRA\n\tENDIF\n\tENDM\n"
        "\tBYTES <1,2,3>\n\tBYTES 4,<5>\n";
    EXPECT_EQ(ok_bytes(src), (V{1, 2, 3, 4, 5}));
}

TEST(Macros, AmpersandJoinsAndReachesIntoStrings) {
    const char* src =
        "MKL\tMACRO N\nL&N:\tDB '&N'\n\tENDM\n"
        "\tMKL 7\n\tDW L7\n";
    EXPECT_EQ(ok_bytes(src), (V{'7', 0x00, 0x00}));
}

TEST(Macros, ParametersInStringsWithoutAmpersandStay) {
    EXPECT_EQ(ok_bytes("M\tMACRO X\n\tDB 'X'\n\tENDM\n\tM 5\n"), (V{'X'}));
}

TEST(Macros, LocalLabelsAreUniquePerExpansion) {
    const char* src =
        "WAIT\tMACRO\n\tLOCAL LOOP\nLOOP:\tDCR A\n\tJNZ LOOP\n\tENDM\n"
        "\tWAIT\n\tWAIT\n";
    // DCR A = 3DH; JNZ = C2H: first loop at 0000H, second at 0004H.
    EXPECT_EQ(ok_bytes(src), (V{0x3D, 0xC2, 0x00, 0x00, 0x3D, 0xC2, 0x04, 0x00}));
}

TEST(Macros, MacrosCallMacrosAndDefineMacros) {
    const char* src =
        "INNER\tMACRO V\n\tDB V\n\tENDM\n"
        "OUTER\tMACRO V\n\tINNER V+1\n\tINNER V+2\n\tENDM\n"
        "MAKER\tMACRO NAME,V\nNAME\tMACRO\n\tDB V\n\tENDM\n\tENDM\n"
        "\tOUTER 10\n\tMAKER NINE,9\n\tNINE\n\tNINE\n";
    EXPECT_EQ(ok_bytes(src), (V{11, 12, 9, 9}));
}

TEST(Macros, ExitmLeavesTheExpansion) {
    const char* src =
        "UPTO\tMACRO N\n\tDB 1\n\tIF N LT 2\n\tEXITM\n\tENDIF\n\tDB 2\n\tENDM\n"
        "\tUPTO 1\n\tUPTO 5\n";
    EXPECT_EQ(ok_bytes(src), (V{1, 1, 2}));
}

TEST(Macros, RecursionWithACondition) {
    const char* src =
        "COUNT\tMACRO N\n\tIF N GT 0\n\tDB N\n\tCOUNT %N-1\n\tENDIF\n\tENDM\n\tCOUNT 3\n";
    EXPECT_EQ(ok_bytes(src), (V{3, 2, 1}));
}

TEST(Macros, Rept) {
    EXPECT_EQ(ok_bytes("N SET 0\n\tREPT 4\nN SET N+1\n\tDB N\n\tENDM\n"), (V{1, 2, 3, 4}));
    EXPECT_EQ(ok_bytes("\tREPT 0\n\tDB 1\n\tENDM\n\tDB 2\n"), (V{2}));
    EXPECT_EQ(ok_bytes("\tREPT 2\n\tREPT 3\n\tNOP\n\tENDM\n\tHLT\n\tENDM\n"), (V{0, 0, 0, 0x76, 0, 0, 0, 0x76}));
}

TEST(Macros, IrpAndIrpc) {
    EXPECT_EQ(ok_bytes("\tIRP R,<B,D,H>\n\tPUSH R\n\tENDM\n"), (V{0xC5, 0xD5, 0xE5}));
    EXPECT_EQ(ok_bytes("\tIRP X,<1,<2,3>,4>\n\tDB X\n\tENDM\n"), (V{1, 2, 3, 4}));
    EXPECT_EQ(ok_bytes("\tIRPC C,HEY\n\tDB '&C'\n\tENDM\n"), (V{'H', 'E', 'Y'}));
}

TEST(Macros, MacroMayReplaceAnInstruction) {
    EXPECT_EQ(ok_bytes("NOP\tMACRO\n\tDB 99\n\tENDM\n\tNOP\n"), (V{99}));
}

TEST(Macros, UnusedMacroWarning) {
    Options o;
    auto r = assemble_string("NEVER\tMACRO\n\tNOP\n\tENDM\n\tHLT\n", o);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.warning_count(), 1);
    EXPECT_EQ(r.diagnostics[0].message, "macro 'NEVER' is defined but never used");
    EXPECT_EQ(r.diagnostics[0].line, 1);
}

TEST(Macros, ExpansionBytesMapToTheInvocationLine) {
    auto r = assemble("TWO\tMACRO\n\tNOP\n\tNOP\n\tENDM\n\tHLT\n\tTWO\n");
    ASSERT_TRUE(r.ok());
    auto* s = r.origin(2);
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->line, 6);
    EXPECT_EQ(s->address, 1);
    EXPECT_EQ(s->length, 2);
}

}  // namespace
}  // namespace alp85::asm85::test
