// The launch configuration's names for what to debug (docs/editors.md): `program` a file,
// `firmware` a built-in name, and each taken for the other when that is what it names.
#include <filesystem>

#include <gtest/gtest.h>

#include "emu/dap/launch.h"
#include "emu/script/session.h"

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

// `rom` (docs/editors.md): the SDK-85's ROM from the user's file, as alp85 run --rom; the project's
// own test program (firmware/sdk85/sdk85test.asm) begins at 0000H with JMP START, C3H.
TEST(Launch, RomArgumentBootsTheBoardFromTheUsersRom) {
    const std::filesystem::path dir = ALP85_SOURCE_DIR;
    const LaunchConfig c =
        parse_launch(Json{{"board", "sdk85"}, {"rom", "firmware/sdk85/sdk85test.asm"}, {"cwd", dir.string()}});
    EXPECT_EQ(c.rom, "firmware/sdk85/sdk85test.asm");
    EXPECT_TRUE(c.program.empty());
    script::SessionOptions so;
    so.board = script::Session::find_board("sdk85");
    script::Session session(so);
    ProgramMap map;
    std::vector<std::string> warnings;
    load_program(c, session, map, warnings);
    EXPECT_EQ(session.peek(0x0000), 0xC3);  // JMP START
    EXPECT_EQ(session.reg(*cpu::description().find("PC")), 0x0000);  // RESET: the ROM runs from 0000H
    EXPECT_TRUE(map.code.test(0x0000));  // the ROM is code: no runaway at its first fetch
    EXPECT_TRUE(map.code.test(0x0024));  // its TRAP entry
}

TEST(Launch, RomArgumentIsRefusedWhereItCannotBe) {
    const auto refused = [](const Json& args, const char* why) {
        try {
            const LaunchConfig c = parse_launch(args);
            script::SessionOptions so;
            so.board = script::Session::find_board(c.board);
            script::Session session(so);
            ProgramMap map;
            std::vector<std::string> warnings;
            load_program(c, session, map, warnings);
            ADD_FAILURE() << args.dump() << " was taken";
        } catch (const RequestError& e) {
            EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
        }
    };
    refused(Json{{"rom", "x.bin"}, {"cwd", "/"}}, "argument 'rom' is for");  // the ALP 85's monitor is built in
    refused(Json{{"board", "sdk85"}, {"rom", "no-such-rom.bin"}, {"cwd", "/"}}, "no-such-rom.bin");
    refused(Json{{"board", "sdk85"}, {"cwd", "/"}}, "or, on a board whose ROM is yours, 'rom'");
}

}  // namespace
}  // namespace alp85::dap
