// Intel ASM80 source as its manual (8080/8085 Assembly Language Programming Manual, 9800301)
// describes it: IF/ELSE/ENDIF with SET, MACRO with parameters, LOCAL, nested calls and EXITM, an
// instruction in parentheses as a value, NAME, comments and '$' control lines. The sources are
// written for these tests; each expected byte is worked out by hand next to it.
#include "helpers.h"

namespace alp85::asm85::test {
namespace {

using V = std::vector<int>;

TEST(Asm80, NestedIfElseEndifWithSet) {
    const char* src =
        "DEBUG\tSET\t1\n"
        "LEVEL\tSET\t2\n"
        "\tIF\tDEBUG\n"
        "\tIF\tLEVEL GT 1\n"
        "\tDB\t11H\t\t; DEBUG and LEVEL 2: this one\n"
        "\tELSE\n"
        "\tDB\t12H\n"
        "\tENDIF\n"
        "\tELSE\n"
        "\tDB\t13H\n"
        "\tENDIF\n"
        "DEBUG\tSET\t0\t\t; SET may give the name a new value\n"
        "\tIF\tDEBUG\n"
        "\tDB\t14H\n"
        "\tELSE\n"
        "\tDB\t15H\t\t; DEBUG is 0 now: the ELSE branch\n"
        "\tENDIF\n"
        "N\tSET\t1\n"
        "N\tSET\tN+N\t\t; 2\n"
        "N\tSET\tN*3\t\t; 6\n"
        "\tDB\tN\n";
    EXPECT_EQ(ok_bytes(src), (V{0x11, 0x15, 6}));
}

// ASM80 tests bit 0 of an IF's value; asm85 any bit (as M80 and DR ASM). Where they part, a warning.
TEST(Asm80, AnEvenIfValueIsTrueWithAWarning) {
    auto r = assemble("\tIF\t2\n\tDB\t1\n\tENDIF\n\tIF\t0FFFFH\n\tDB\t2\n\tENDIF\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{1, 2}));
    ASSERT_EQ(r.warning_count(), 1) << diags(r);  // 0FFFFH is odd: true to both
    EXPECT_EQ(r.diagnostics[0].line, 1);
    EXPECT_EQ(r.diagnostics[0].col, 5);
    EXPECT_EQ(r.diagnostics[0].message, "IF value 0002H is even: true here (non-zero), but false to Intel's ASM80, which tests only bit 0");
}

TEST(Asm80, MacroParametersLocalAndNestedCalls) {
    const char* src =
        "DELAY\tMACRO\tCOUNT\n"
        "\tLOCAL\tAGAIN\n"
        "\tMVI\tC,COUNT\n"
        "AGAIN:\tDCR\tC\n"
        "\tJNZ\tAGAIN\n"
        "\tENDM\n"
        "PAIR\tMACRO\tN1,N2\n"
        "\tDELAY\tN1\n"
        "\tDELAY\tN2\n"
        "\tENDM\n"
        "\tORG\t100H\n"
        "\tPAIR\t5,0AH\n";
    // MVI C = 00 001 110 = 0EH, DCR C = 00 001 101 = 0DH, JNZ = 0C2H. The first AGAIN is at
    // 0102H, the second (a new LOCAL name) at 0108H.
    EXPECT_EQ(ok_bytes(src), (V{0x0E, 0x05, 0x0D, 0xC2, 0x02, 0x01, 0x0E, 0x0A, 0x0D, 0xC2, 0x08, 0x01}));
}

TEST(Asm80, ExitmEndsARecursiveMacro) {
    const char* src =
        "DOWN\tMACRO\tN\n"
        "\tIF\tN EQ 0\n"
        "\tEXITM\n"
        "\tENDIF\n"
        "\tDB\tN\n"
        "\tDOWN\t%N-1\n"
        "\tENDM\n"
        "\tDOWN\t3\n";
    EXPECT_EQ(ok_bytes(src), (V{3, 2, 1}));
}

TEST(Asm80, NulTestsForAMissingArgument) {
    const char* src =
        "OPT\tMACRO\tX\n"
        "\tIF\tNUL X\n"
        "\tDB\t0EEH\n"
        "\tELSE\n"
        "\tDB\tX\n"
        "\tENDIF\n"
        "\tENDM\n"
        "\tOPT\n"
        "\tOPT\t5\n";
    EXPECT_EQ(ok_bytes(src), (V{0xEE, 0x05}));
}

// The value of an instruction in parentheses is its first byte (the opcode).
TEST(Asm80, InstructionInParenthesesIsItsFirstByte) {
    const char* src =
        "\tCPI\t(DI)\n"            // CPI = 0FEH; DI = 1111 0011 = 0F3H
        "\tDB\t(MOV A,B)\n"        // 01 111 000 = 78H
        "\tMVI\tA,(RST 7)\n"       // MVI A = 3EH; RST 7 = 11 111 111 = 0FFH
        "\tDB\t(LXI H,1234H)\n"    // LXI H = 21H; the data bytes are not part of the value
        "\tDB\t(JMP 0)+1\n"        // 0C3H + 1 = 0C4H
        "\tDW\t(INR A) SHL 8\n";   // INR A = 00 111 100 = 3CH; 3C00H, low byte first
    EXPECT_EQ(ok_bytes(src), (V{0xFE, 0xF3, 0x78, 0x3E, 0xFF, 0x21, 0xC4, 0x00, 0x3C}));
}

// NAME, comments of any length and content, and '$' control lines change no byte.
TEST(Asm80, NameCommentsAndControlsChangeNoByte) {
    std::string src =
        "$MOD85 NOLIST\n"
        "$TITLE('SELF TEST (INCLUDE NOTHING)')\n"  // INCLUDE inside a TITLE's text is no control
        "\tNAME\tSELFT\n";
    src += ";" + std::string(200, '-') + " 'quotes\" ; more ; (parens) $ MACRO ENDM IF <,>\n";
    src +=
        "\tMVI\tA,''''\t; a doubled quote in a string: 27H. The comment's apostrophe isn't one\n"
        "\tNOP\t\t; nor a < or , or ! here\n"
        "$EJECT\n"
        "SHOW\tMACRO\tP\n"
        "\tDB\tP\t; P's value: a comment in a body, copied\n"
        ";; P in a ;; comment: not copied, isn't seen\n"
        "\tENDM\n"
        "\tSHOW\t7\t; a call's comment, with a comma, isn't an argument\n"
        "\tEND\n";
    // MVI A = 3EH, then 27H; NOP = 00H; SHOW 7 = DB 7.
    auto r = assemble(src);
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(r.warning_count(), 0) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{0x3E, 0x27, 0x00, 0x07}));
}

TEST(Asm80, LocationCounterOperatorsDsAndEndStart) {
    const char* src =
        "\tORG\t800H\n"
        "START:\tJMP\t$+3\t\t\t; 0C3H, 0803H low byte first\n"
        "\tDB\tHIGH 1234H,LOW 1234H\t; 12H 34H\n"
        "\tDB\t1 SHL 4,80H SHR 3\t; 10H 10H\n"
        "\tDB\t17 MOD 5\t\t; 2\n"
        "\tDB\tNOT 0 AND 0FH\t\t; NOT before AND: 0FFFFH AND 0FH = 0FH\n"
        "\tDB\t1 OR 2 XOR 7\t\t; one level, left to right: 3 XOR 7 = 4\n"
        "\tDS\t2\t\t\t; 080AH-080BH reserved, not written\n"
        "\tDB\t$ AND 0FFH\t\t; at 080CH: 0CH\n"
        "\tEND\tSTART\n"
        "\tDB\t99H\t\t\t; after END: not assembled\n";
    auto r = assemble(src);
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(bytes(r, 0x800, 13), (V{0xC3, 0x03, 0x08, 0x12, 0x34, 0x10, 0x10, 2, 0x0F, 4, -1, -1, 0x0C}));
    EXPECT_EQ(r.image.size(), 11u);
    ASSERT_TRUE(r.image.start_address.has_value());
    EXPECT_EQ(*r.image.start_address, 0x800);
}

// A label on IF, ELSE or ENDIF is the address of its line, where the line is assembled.
TEST(Asm80, ALabelOnAConditionalLineIsDefined) {
    // HERE = 0, THERE = 1 (after the NOP); JMP = 0C3H.
    EXPECT_EQ(ok_bytes("HERE:\tIF\t1\n\tNOP\nTHERE:\tENDIF\n\tJMP\tHERE\n\tDB\tTHERE\n"), (V{0x00, 0xC3, 0x00, 0x00, 0x01}));
    // Inside a false branch the line is skipped, its label too.
    auto r = assemble("\tIF\t0\nSKIP:\tIF\t1\n\tENDIF\n\tENDIF\n\tDW\tSKIP\n");
    EXPECT_EQ(first_error(r).message, "undefined symbol 'SKIP'");
    EXPECT_EQ(first_error(r).line, 5);
}

struct Misuse {
    const char* src;
    int line, col;
    const char* message;
};

// Each misuse: its message at the file:line:col of the word at fault.
TEST(Asm80, MisusesNameTheirPlace) {
    const Misuse cases[] = {
        {"\tNOP\n\tIF\t1\n\tNOP\n", 2, 2, "IF without ENDIF"},
        {"\tNOP\n  ENDIF\n", 2, 3, "ENDIF without IF"},
        {"\tNOP\n\tENDM\n", 2, 2, "ENDM without MACRO, REPT, IRP or IRPC"},
        {"TWO\tMACRO\tA1,A2\n\tDB\tA1,A2\n\tENDM\n\tTWO\t1,2,3\n", 4, 6, "macro TWO takes 2 argument(s), 3 given"},
        {"K\tEQU\t1\nK\tSET\t2\n", 2, 1, "'K' is an EQU constant (first defined at t.asm:1); SET can't redefine it"},
        {"K\tSET\t1\nK\tEQU\t2\n", 2, 1, "'K' is a SET symbol (first defined at t.asm:1); EQU can't redefine it"},
        // An IF left open in a body: at the IF, not at the call.
        {"OPEN\tMACRO\n\tNOP\n    IF\t1\n\tENDM\n\tOPEN\n", 3, 5, "IF without ENDIF in the expansion of OPEN"},
        // An ENDIF in a body can't close an IF outside it.
        {"SHUT\tMACRO\n  ENDIF\n\tENDM\n\tIF\t1\n\tSHUT\n\tENDIF\n", 2, 3,
         "ENDIF without IF in the expansion of SHUT (an IF opened outside a macro or repeat block must end outside it)"},
        {"ALT\tMACRO\n  ELSE\n\tENDM\n\tIF\t1\n\tALT\n\tENDIF\n", 2, 3,
         "ELSE without IF in the expansion of ALT (an IF opened outside a macro or repeat block must end outside it)"},
        {"\tIF\t1\n\tREPT\t1\n  ENDIF\n\tENDM\n\tENDIF\n", 3, 3,
         "ENDIF without IF in the expansion of REPT (an IF opened outside a macro or repeat block must end outside it)"},
        {"$INCLUDE\n", 1, 2, "$INCLUDE needs (filename)"},
    };
    for (const auto& c : cases) {
        auto r = assemble(c.src);
        ASSERT_FALSE(r.ok()) << c.src;
        const Diagnostic e = first_error(r);
        EXPECT_EQ(e.message, c.message) << c.src;
        EXPECT_EQ(e.file, "t.asm") << c.src;
        EXPECT_EQ(e.line, c.line) << c.src;
        EXPECT_EQ(e.col, c.col) << c.src;
        EXPECT_EQ(r.error_count(), 1) << diags(r);
    }
}

TEST(Asm80, AnOpenIfInAMacroNotesTheCall) {
    auto r = assemble("OPEN\tMACRO\n    IF\t1\n\tENDM\n\tNOP\n\tOPEN\n");
    ASSERT_EQ(r.diagnostics.size(), 2u) << diags(r);
    EXPECT_EQ(format_diagnostic(r.diagnostics[0]),
              "t.asm:2:5: error: IF without ENDIF in the expansion of OPEN\n    IF\t1\n    ^\n");
    EXPECT_EQ(r.diagnostics[1].severity, Severity::Note);
    EXPECT_EQ(r.diagnostics[1].line, 5);
}

// A macro that calls itself with no end stops at the depth limit with an error, promptly.
TEST(Asm80, EndlessRecursionIsADepthError) {
    auto r = assemble("DEEP\tMACRO\tN\n\tDB\tN\n\tDEEP\t%N+1\n\tENDM\n\tDEEP\t0\n");
    ASSERT_FALSE(r.ok());
    const Diagnostic e = first_error(r);
    EXPECT_EQ(e.message, "macros nested more than 100 deep (a macro that calls itself?)");
    EXPECT_EQ(e.line, 3);
    EXPECT_EQ(e.col, 7);
    EXPECT_EQ(r.error_count(), 1) << diags(r).substr(0, 2000);
    // Two macros calling each other: the same limit.
    r = assemble("PING\tMACRO\n\tPONG\n\tENDM\nPONG\tMACRO\n\tPING\n\tENDM\n\tPING\n");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(first_error(r).message, "macros nested more than 100 deep (a macro that calls itself?)");
}

}  // namespace
}  // namespace alp85::asm85::test
