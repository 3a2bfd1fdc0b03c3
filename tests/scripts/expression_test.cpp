// One expression grammar: a script's values are the debugger's expressions (debug::Expr), a bare
// name a symbol first; what was SYMBOL+-N before reads as it did.
#include <gtest/gtest.h>

#include "emu/script/parser.h"
#include "tests/scripts/parse_helpers.h"
#include "emu/script/session.h"

namespace alp85::script {
namespace {

std::optional<Command> parsed(std::string_view line, std::vector<ParseError>& errors) {
    return parse_line(line, "t.alp", 1, errors);
}

TEST(ScriptExpressions, AValueWithBlanksInParenthesesIsOneWord) {
    std::vector<ParseError> errors;
    const auto c = parsed("expect mem 1000H (1 + 2)*3 2", errors);
    ASSERT_TRUE(c && errors.empty()) << (errors.empty() ? "" : errors[0].message);
    ASSERT_EQ(c->values.size(), 2u);
    EXPECT_EQ(c->values[0].number, 9);  // (1 + 2) * 3
    EXPECT_FALSE(c->values[0].expression);
    EXPECT_EQ(c->values[1].number, 2);
    const auto d = parsed("set reg HL (X1 + 1)", errors);
    ASSERT_TRUE(d && errors.empty());
    EXPECT_TRUE(d->values[0].expression);
    ASSERT_EQ(d->values[0].names.size(), 1u);
    EXPECT_EQ(d->values[0].names[0].name, "X1");
    EXPECT_EQ(d->values[0].names[0].col, 2);  // within "(X1 + 1)"
    // A negative constant is a number: the byte range decides (-128..255).
    EXPECT_EQ(parsed("expect reg A -1", errors)->values[0].number, -1);
}

TEST(ScriptExpressions, ErrorsPointIntoTheExpression) {
    std::vector<ParseError> errors;
    EXPECT_FALSE(parsed("run until START+(2", errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].message, "expected ')'");
    EXPECT_EQ(errors[0].where.col, 19);  // just past "START+(2", which stands in columns 11-18
    errors.clear();
    EXPECT_FALSE(parsed("expect mem 1000H 1/0", errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].message, "division by zero");
}

using ScriptExpressionRun = test::SessionLines;

// hello.asm: KEY1 EQU 1000H, KEY2 EQU 1001H, DONE EQU 1002H.
TEST_F(ScriptExpressionRun, SymbolsArithmeticRegistersAndMemory) {
    ok("load hello.asm");
    ok("set reg HL KEY1+2*3");            // 1000H + 6
    ok("expect reg HL 1006H");
    ok("set mem (KEY2 + 1) 12H 34H");     // 1002H, 1003H
    ok("expect mem DONE 12H 34H");
    ok("expect word DONE 3412H");
    ok("set reg A word[DONE]&0FFH");      // the byte at 1002H: 12H
    ok("expect reg A 12H");
    ok("set reg DE HL-KEY1");             // a register read when the line runs: 1006H - 1000H
    ok("expect reg DE 6");
    // A value outside 0000H-0FFFFH is an error at its line, as SYMBOL-N always was.
    const auto o = run("set reg HL KEY1-(5000H)");
    EXPECT_EQ(o.status, Session::Status::Failed);
    EXPECT_NE(o.message.find("KEY1-(5000H) is -16384, outside 0000H-0FFFFH"), std::string::npos) << o.message;  // 1000H - 5000H
}

TEST_F(ScriptExpressionRun, TheCheckNamesAnUnknownSymbolInsideAnExpression) {
    std::vector<ParseError> errors;
    const auto commands = parse_script("load hello.asm\nset reg HL (KEY1 + NOWHERE)\nset reg BC HL+1\n", "t.alp", errors);
    ASSERT_TRUE(errors.empty());
    s.check(commands, errors);
    ASSERT_EQ(errors.size(), 1u);  // HL is a register: no symbol needed
    EXPECT_EQ(errors[0].message, "unknown symbol 'NOWHERE' (no source loaded before this line defines it)");
    EXPECT_EQ(errors[0].where.line, 2);
    EXPECT_EQ(errors[0].where.col, 20);  // "set reg HL (KEY1 + " is 19 columns
}

}  // namespace
}  // namespace alp85::script
