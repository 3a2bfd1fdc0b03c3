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

}  // namespace
}  // namespace alp85::dap
