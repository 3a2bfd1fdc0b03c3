// The command language's executor on a real machine: key presses in simulated time, waits,
// breakpoints, registers, and the failure report's contents.
#include <gtest/gtest.h>

#include "emu/script/parser.h"
#include "tests/scripts/parse_helpers.h"
#include "emu/script/runner.h"
#include "emu/script/session.h"

namespace alp85::script {
namespace {

using SessionTest = test::SessionLines;

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

TEST_F(SessionTest, FirmwareMasterFitsTheExpansionEpromAndBringsItsSymbols) {
    EXPECT_FALSE(s.machine().expansion_eprom());  // the thesis board as built
    ok("firmware master");
    EXPECT_TRUE(s.machine().expansion_eprom());
    ok("expect mem 3000H 31H 0B0H 20H");  // MSTR: LXI SP,20B0H (firmware/master/master.asm)
    ok("expect mem MSTR 31H");
    ok("expect mem HAND 0DBH 0FAH");      // the hand-over: IN 0FAH
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

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace alp85::script {
namespace {

namespace fs = std::filesystem;

// A folder of its own for scripts and the files they name.
class ScriptFolder : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("alp85_scripts_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir / name, std::ios::binary) << text; }
    // prepare + execute, as `alp85 script` does; the script's folder is not the working directory.
    bool run(const std::string& name, std::string& report) {
        std::vector<Command> cmds;
        std::vector<ParseError> errors;
        std::ostringstream out, err;
        RunnerOptions o;
        o.out = &out;
        o.err = &err;
        const bool ok = prepare(dir / name, cmds, errors, o);
        warnings = err.str();
        report.clear();
        for (const auto& e : errors) report += e.format();
        if (!ok) return false;
        const ScriptResult r = execute(dir / name, cmds, o);
        report += r.failure;
        return r.passed;
    }
    fs::path dir;
    std::string warnings;
};

// Issue #11, 2: the warnings of a source a script loads are shown, with file:line:col.
TEST_F(ScriptFolder, AssemblerWarningsOfLoadedSourcesAreShown) {
    write("overlap.asm", "\tORG 0800H\n\tNOP\n\tORG 0800H\n\tHLT\n");
    write("t.alp", "load overlap.asm\nexpect mem 0800H 76H\n");
    std::string report;
    EXPECT_TRUE(run("t.alp", report)) << report;
    EXPECT_NE(warnings.find("overlap.asm:4:2: warning: overlapping ORG regions"), std::string::npos) << warnings;
}

// Issue #11, 6: a binary image that runs out of its memory region into the next is refused; a
// source that does so is loaded with a warning.
TEST_F(ScriptFolder, AnImageThatCrossesMemoryRegionsIsRefusedOrWarnedAbout) {
    write("big.bin", std::string(3000, '\x76'));
    write("big.alp", "load big.bin at 0800H\n");
    std::string report;
    EXPECT_FALSE(run("big.alp", report));
    // 0800H + 3000 - 1 = 13B7H; the user EPROM ends at 0FFFH, RAM starts at 1000H.
    EXPECT_NE(report.find("big.alp:1:6: error: "), std::string::npos) << report;
    EXPECT_NE(report.find("3000 bytes at 0800H-13B7H run past the end of the 'user' region (0800H-0FFFH) into the "
                          "'ram' region at 1000H; refused"),
              std::string::npos)
        << report;
    write("fits.bin", std::string(2048, '\x76'));
    write("fits.alp", "load fits.bin at 0800H\nexpect mem 0FFFH 76H\nexpect mem 1000H 0\n");
    EXPECT_TRUE(run("fits.alp", report)) << report;
    // A source whose bytes run from 0FFEH to 1001H: loaded, with a warning.
    write("edge.asm", "\tORG 0FFEH\n\tDB 1,2,3,4\n");
    write("edge.alp", "load edge.asm\nexpect mem 0FFEH 1 2 3 4\n");
    EXPECT_TRUE(run("edge.alp", report)) << report;
    EXPECT_NE(warnings.find("edge.asm: warning: 4 bytes at 0FFEH-1001H run past the end of the 'user' region "
                            "(0800H-0FFFH) into the 'ram' region at 1000H"),
              std::string::npos)
        << warnings;
}

// Issue #11, 7: save and restore name files relative to the script's folder, like load.
TEST_F(ScriptFolder, SnapshotsAreRelativeToTheScriptsFolder) {
    ASSERT_NE(fs::current_path(), dir);
    write("save.alp", "set mem 1000H 42H\nsave state.snap\n");
    write("restore.alp", "restore state.snap\nexpect mem 1000H 42H\n");
    std::string report;
    EXPECT_TRUE(run("save.alp", report)) << report;
    EXPECT_TRUE(fs::is_regular_file(dir / "state.snap"));
    EXPECT_FALSE(fs::exists(fs::current_path() / "state.snap"));
    EXPECT_TRUE(run("restore.alp", report)) << report;
}

// Issue #11, 10 (docs/scripting.md, docs/board.md): `expect port` checks the output latch even on
// a port programmed as input, while IN reads the undriven inputs: FFH on A, and on C its six pins
// (3FH) with PC6-PC7 reading 1, so FFH too. (Port B carries the machine tool's transducers.)
TEST_F(ScriptFolder, ExpectPortChecksTheLatchOfAnInputPort) {
    write("ports.asm",
          "\tORG 0800H\n"
          "\tMVI A,00H\n\tOUT 0F8H\n"   // ports A, B, C input (ALT1)
          "\tMVI A,5AH\n\tOUT 0F9H\n"   // into port A's latch, not driven
          "\tMVI A,25H\n\tOUT 0FBH\n"   // port C's latch
          "\tIN 0F9H\n\tSTA 1000H\n\tIN 0FBH\n\tSTA 1001H\n\tHLT\n");
    write("ports.alp",
          "load ports.asm\nset reg PC 0800H\nrun 1ms\nexpect halted\n"
          "expect port A 5AH\nexpect port C 25H\nexpect mem 1000H 0FFH 0FFH\n");
    std::string report;
    EXPECT_TRUE(run("ports.alp", report)) << report;
}

// The typed API does the work itself: no command, no script line in between.
TEST_F(SessionTest, TypedCallsWorkWithoutAScriptLine) {
    ASSERT_EQ(s.load_image("hello.asm").status, Session::Status::Ok);
    EXPECT_EQ(s.set_mem(0x1000, {0x12, 0x34}).status, Session::Status::Ok);
    EXPECT_EQ(s.expect_word(0x1000, 0x3412).status, Session::Status::Ok);  // little-endian
    const auto o = s.expect_mem(0x1000, {0x12, 0x35});
    EXPECT_EQ(o.status, Session::Status::Failed);
    EXPECT_EQ(o.message, "expectation failed: expected: 12H 35H at 1000H; actual: 12H 34H");
    EXPECT_EQ(s.set_reg(*cpu::description().find("HL"), 0x1234).status, Session::Status::Ok);
    EXPECT_EQ(s.expect_reg(*cpu::description().find("H"), 0x12).status, Session::Status::Ok);
    EXPECT_EQ(s.reset().status, Session::Status::Ok);
    // hello.asm shows HELL0 within 2 ms of RESET (WaitDisplayStopsWhenTheTextAppears above).
    EXPECT_EQ(s.wait_display("HELL0", 30720).status, Session::Status::Ok);
    EXPECT_EQ(s.expect_display("HELL0").status, Session::Status::Ok);
    const auto late = s.run_until(0x0003, 3072);  // never reached: the JMP at 0000H jumps over it
    EXPECT_EQ(late.status, Session::Status::Failed);
    EXPECT_EQ(late.message, "the PC did not reach 0003H within 1.000 ms (3072 T-states)");
}

}  // namespace
}  // namespace alp85::script
