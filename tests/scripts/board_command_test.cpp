// The board a script runs on: `board NAME` as its first command (or --board, RunnerOptions::board),
// `print board` and `option` against the board's own options, and the keys a front end gets for
// the session's board. Expected values are the SDK-85's facts (docs/board.md), not the output of
// the code under test.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "emu/front/keys.h"
#include "emu/script/parser.h"
#include "emu/script/runner.h"

namespace alp85::script {
namespace {

namespace fs = std::filesystem;

struct OneScript {
    // A file of its own: ctest runs each test in its own process, several at once.
    explicit OneScript(const std::string& text)
        : file(fs::temp_directory_path() /
               ("alp85 board command " + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                " " + std::to_string(::getpid()) + " " + std::to_string(++made_) + ".alp")) {
        std::ofstream(file) << text;
    }
    ~OneScript() { fs::remove(file); }
    // prepare() then execute(): the errors, or the run's result and its printed text.
    bool prepare(RunnerOptions& o) {
        o.out = &out;
        return script::prepare(file, commands, errors, o);
    }
    static inline int made_ = 0;  // two scripts in one test are two files
    fs::path file;
    std::vector<Command> commands;
    std::vector<ParseError> errors;
    std::ostringstream out;
};

// `board sdk85` first: the script runs on the SDK-85, where the 8155's RAM is at 2000H and mirrored
// at 2400H (A8-A10 not decoded), and 1000H (the ALP 85's RAM) holds nothing.
TEST(BoardCommand, FirstCommandBuildsTheSdk85) {
    OneScript s("board sdk85\nset mem 2000H 42H\nexpect mem 2400H 42H\nexpect mem 1000H 0FFH\nprint board\n");
    RunnerOptions o;
    ASSERT_TRUE(s.prepare(o)) << (s.errors.empty() ? "" : s.errors[0].message);
    const ScriptResult r = execute(s.file, s.commands, o);
    EXPECT_TRUE(r.passed) << r.failure;
    EXPECT_NE(s.out.str().find("board sdk85"), std::string::npos) << s.out.str();
    EXPECT_NE(s.out.str().find("1800H-1FFFH"), std::string::npos) << s.out.str();  // the 8279's block
}

// Without it the same lines fail on the ALP 85 (its RAM is at 1000H-1FFFH, 2400H is unmapped):
// the board command decides.
TEST(BoardCommand, WithoutItTheAlp85) {
    OneScript s("set mem 2000H 42H\nexpect mem 2400H 42H\n");
    RunnerOptions o;
    ASSERT_TRUE(s.prepare(o));
    EXPECT_FALSE(execute(s.file, s.commands, o).passed);
    // --board sdk85 (RunnerOptions::board) does what the command does.
    o.board = &board::kSdk85;
    OneScript t("set mem 2000H 42H\nexpect mem 2400H 42H\n");
    ASSERT_TRUE(t.prepare(o));
    EXPECT_TRUE(execute(t.file, t.commands, o).passed);
}

TEST(BoardCommand, LaterThanFirstOrUnknownIsAnError) {
    OneScript late("reset\nboard sdk85\n");
    RunnerOptions o;
    EXPECT_FALSE(late.prepare(o));
    ASSERT_FALSE(late.errors.empty());
    EXPECT_EQ(late.errors[0].where.line, 2);
    EXPECT_NE(late.errors[0].message.find("first command"), std::string::npos) << late.errors[0].message;

    std::vector<ParseError> errors;
    parse_line("board sdk86", "t.alp", 1, errors);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].message.find("unknown board 'sdk86' (alp85, sdk85)"), std::string::npos) << errors[0].message;
}

// Keys are the board's: the SDK-85 has no R and no PREV (the ALP 85's), a script pressing one is
// refused before it runs, at the key.
TEST(BoardCommand, KeysAreTheBoards) {
    OneScript s("board sdk85\npress R\n");
    RunnerOptions o;
    EXPECT_FALSE(s.prepare(o));
    ASSERT_EQ(s.errors.size(), 1u);
    EXPECT_EQ(s.errors[0].where.line, 2);
    EXPECT_EQ(s.errors[0].where.col, 7);
    EXPECT_NE(s.errors[0].message.find("the SDK-85 has no key 'R'"), std::string::npos) << s.errors[0].message;
    OneScript t("board sdk85\ntype MEM 2 0 0 0 NEXT\npress RESET\n");
    EXPECT_TRUE(t.prepare(o)) << (t.errors.empty() ? "" : t.errors[0].message);
}

// Options are the board's: the SDK-85 has ram2 (its second 8155), not the ALP 85's expansion EPROM.
TEST(BoardCommand, OptionsAreTheBoards) {
    OneScript s("board sdk85\nexpect mem 2800H 0FFH\noption ram2 on\nset mem 2800H 5AH\nexpect mem 2F00H 5AH\n");
    RunnerOptions o;
    ASSERT_TRUE(s.prepare(o));
    const ScriptResult r = execute(s.file, s.commands, o);
    EXPECT_TRUE(r.passed) << r.failure;
    OneScript t("board sdk85\noption expansion on\n");
    ASSERT_TRUE(t.prepare(o));
    const ScriptResult f = execute(t.file, t.commands, o);
    EXPECT_FALSE(f.passed);
    EXPECT_NE(f.failure.find("no option 'expansion'"), std::string::npos) << f.failure;
}

// The front end's keys come from the session's board: the SDK-85 has 24 (no PREV, no R), its
// SUBST MEM sits in the third row, first column, and "." presses EXEC on it.
TEST(BoardKeys, FromTheSessionsBoard) {
    SessionOptions so;
    so.board = &board::kSdk85;
    Session s(so);
    const auto pads = front::pad_keys(s);
    EXPECT_EQ(pads.size(), 24u);
    EXPECT_FALSE(front::find_pad_key("PREV", s));
    EXPECT_TRUE(front::find_pad_key("PREV"));  // the ALP 85's
    const auto mem = front::find_pad_key("MEM", s);
    ASSERT_TRUE(mem);
    EXPECT_EQ(mem->row, 2);
    EXPECT_EQ(mem->col, 0);
    const auto dot = front::pad_key_for_pc(".", s);
    ASSERT_TRUE(dot);
    EXPECT_EQ(dot->key, periph::Key::Exec);
    EXPECT_EQ(front::cap_label(*dot, s), "EXEC\n.");
    // The ALP 85's keys as they were: 26, RESET first, EXEC labelled Enter.
    EXPECT_EQ(front::pad_keys().size(), 26u);
    EXPECT_EQ(front::pad_keys().front().pad, Button::Reset);
    EXPECT_EQ(front::pc_key_label(*front::find_pad_key("EXEC")), "Enter");
}

}  // namespace
}  // namespace alp85::script
