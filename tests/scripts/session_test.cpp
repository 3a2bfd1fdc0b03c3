// The command language's executor on a real machine: key presses in simulated time, waits,
// breakpoints, registers, and the failure report's contents.
#include <gtest/gtest.h>

#include "emu/script/parser.h"
#include "emu/script/runner.h"
#include "emu/script/session.h"

namespace alp85::script {
namespace {

class SessionTest : public ::testing::Test {
protected:
    SessionTest() : s(SessionOptions{ALP85_BOARD_PROGRAMS, Variant::I8085, {}, nullptr, false}) {}
    Session::Outcome run(std::string_view line) {
        std::vector<ParseError> errors;
        auto c = parse_line(line, "t.alp", ++n, errors);
        EXPECT_TRUE(errors.empty() && c) << line;
        return c ? s.execute(*c) : Session::Outcome{Session::Status::Failed, "parse"};
    }
    void ok(std::string_view line) {
        const auto o = run(line);
        EXPECT_EQ(o.status, Session::Status::Ok) << line << "\n" << o.message;
    }
    Session s;
    int n = 0;
};

TEST_F(SessionTest, PressAdvancesTimeByHoldAndGap) {
    ok("load hello.asm");
    ok("reset");
    ok("press 5 hold 40ms gap 20ms");
    // 60 ms = 184320 T-states, ended on a whole instruction (at most 18 T-states later).
    EXPECT_GE(s.elapsed(), 184'320u);
    EXPECT_LT(s.elapsed(), 184'320u + 18);
    ok("expect mem KEY1 5");
}

TEST_F(SessionTest, WaitDisplayStopsWhenTheTextAppears) {
    ok("load hello.asm");
    ok("reset");
    ok("wait display \"HELL0\" timeout 1s");
    // The program clears the display (DU for 16 x 31 = 496 T-states) and writes 8 digits: well
    // under 2 ms, far less than the timeout.
    EXPECT_LT(s.elapsed(), 6144u);
    ok("expect display \"HELL0\"");
    const auto o = run("wait display \"NEVER\" timeout 10ms");
    EXPECT_EQ(o.status, Session::Status::Failed);
    EXPECT_NE(o.message.find("did not show \"NEVER\" within 10.000 ms"), std::string::npos) << o.message;
}

TEST_F(SessionTest, RunUntilASymbolAndRegisters) {
    ok("load hello.asm");
    ok("reset");
    ok("run until POLL timeout 10ms");
    ok("expect reg PC POLL");
    ok("expect reg SP 20B0H");
    ok("set reg A 0C3H");

}

TEST_F(SessionTest, BreakpointsStopARunWithoutFailingIt) {
    ok("load hello.asm");
    ok("reset");
    ok("break SHOW");
    ok("run 10ms");
    ok("expect reg PC SHOW");
    ok("expect reg B 8");  // the first pass: 8 digits to go
    ok("run 10ms");
    ok("expect reg B 7");
    ok("delete all");
    ok("run 10ms");
    ok("expect display \"HELL0\"");
}

TEST_F(SessionTest, AFailedExpectationSaysWhatWhereAndWhen) {
    ok("load hello.asm");
    ok("reset");
    ok("run 2ms");
    const auto o = run("expect mem 1002H 55H");
    ASSERT_EQ(o.status, Session::Status::Failed);
    EXPECT_NE(o.message.find("t.alp:4: expectation failed: expect mem 1002H 55H"), std::string::npos) << o.message;
    EXPECT_NE(o.message.find("expected: 55H at 1002H"), std::string::npos) << o.message;
    EXPECT_NE(o.message.find("actual:   00H"), std::string::npos) << o.message;
    EXPECT_NE(o.message.find("at 2.000 ms"), std::string::npos) << o.message;
    EXPECT_NE(o.message.find("display \"HELL0   \""), std::string::npos) << o.message;
}

TEST_F(SessionTest, ResetStartsTheClockForExpectTime) {
    ok("load hello.asm");
    ok("run 5ms");
    ok("reset");
    ok("run 1ms");
    ok("expect time >= 1ms");
    ok("expect time < 1.1ms");
}

TEST(ScriptRunner, CheckFindsMissingFilesAndLateSymbols) {
    std::vector<Command> cmds;
    std::vector<ParseError> errors;
    EXPECT_FALSE(prepare(std::string(ALP85_SCRIPT_CASES) + "/errors.alp", cmds, errors, {}));
    ASSERT_EQ(errors.size(), 4u);
    EXPECT_EQ(errors[2].message, "unknown symbol 'NOSUCHSYMBOL' (no source loaded before this line defines it)");
}

TEST(ScriptRunner, JunitNamesEachScriptAndItsFailure) {
    std::vector<ScriptResult> results{{"a.alp", true, "", 100, 0.5, 3}, {"b.alp", false, "b.alp:2: expect <x>", 5, 0.25, 2}};
    const std::string x = junit_xml(results);
    EXPECT_NE(x.find("<testsuite name=\"alp85 script\" tests=\"2\" failures=\"1\""), std::string::npos) << x;
    EXPECT_NE(x.find("<testcase classname=\"alp85.script\" name=\"a.alp\" time=\"0.500000\">"), std::string::npos) << x;
    EXPECT_NE(x.find("<failure message=\"b.alp:2: expect &lt;x&gt;\">"), std::string::npos) << x;
}

}  // namespace
}  // namespace alp85::script
