// The launch configuration's names for what to debug (docs/editors.md): `program` a file,
// `firmware` a built-in name, and each taken for the other when that is what it names.
#include <filesystem>

#include <gtest/gtest.h>

#include "emu/dap/launch.h"

namespace alp85::dap {
namespace {

TEST(Launch, BuiltInNameAsProgramIsTheFirmware) {
    const LaunchConfig c = parse_launch(Json{{"program", "thesis-fixed"}, {"cwd", "/"}});
    EXPECT_EQ(c.firmware, "thesis-fixed");
    EXPECT_EQ(c.program, "");
}

TEST(Launch, FileAsFirmwareIsTheProgram) {
    const std::filesystem::path dir = ALP85_SOURCE_DIR;
    const LaunchConfig c = parse_launch(Json{{"firmware", "firmware/demo/hello85.asm"}, {"cwd", dir.string()}});
    EXPECT_EQ(c.program, "firmware/demo/hello85.asm");
    EXPECT_EQ(c.firmware, "");
}

TEST(Launch, EachNameInItsPlaceIsKept) {
    const LaunchConfig c = parse_launch(Json{{"program", "firmware/demo/hello85.asm"}, {"firmware", "thesis"}, {"cwd", "/"}});
    EXPECT_EQ(c.program, "firmware/demo/hello85.asm");
    EXPECT_EQ(c.firmware, "thesis");
}

TEST(Launch, NeitherNameIsStillRefusedWhenLoaded) {
    const LaunchConfig c = parse_launch(Json{{"firmware", "nothere"}, {"cwd", "/"}});
    EXPECT_EQ(c.firmware, "nothere");  // load_program names the built-in firmware
}

// `board` (docs/editors.md): the ALP 85 by default, with its built-in monitor; the SDK-85 has no
// built-in monitor (its ROM is the user's); an unknown board is refused, naming the boards.
TEST(Launch, BoardArgument) {
    const LaunchConfig a = parse_launch(Json{{"program", "thesis-fixed"}, {"cwd", "/"}});
    EXPECT_EQ(a.board, "alp85");
    EXPECT_TRUE(a.monitor);
    const LaunchConfig s = parse_launch(Json{{"program", "thesis-fixed"}, {"cwd", "/"}, {"board", "sdk85"}});
    EXPECT_EQ(s.board, "sdk85");
    EXPECT_FALSE(s.monitor);
    try {
        parse_launch(Json{{"program", "thesis-fixed"}, {"cwd", "/"}, {"board", "kim1"}});
        ADD_FAILURE() << "an unknown board was taken";
    } catch (const RequestError& e) {
        EXPECT_NE(std::string(e.what()).find("no board 'kim1' (alp85, sdk85)"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace alp85::dap
