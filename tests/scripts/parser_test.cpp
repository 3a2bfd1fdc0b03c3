// The command language's parser: every command's shape, numbers, times, keys, and errors with
// their columns (docs/scripting.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "emu/script/parser.h"
#include "tests/scripts/parse_helpers.h"

namespace alp85::script {
namespace {

using test::error_of;
using test::one;

TEST(ScriptNumbers, IntelSuffixesAndCPrefix) {
    EXPECT_EQ(parse_number("1234"), 1234);
    EXPECT_EQ(parse_number("0800H"), 0x800);
    EXPECT_EQ(parse_number("0ffh"), 0xFF);
    EXPECT_EQ(parse_number("0x1B00"), 0x1B00);
    EXPECT_EQ(parse_number("1010B"), 10);
    EXPECT_EQ(parse_number("17O"), 15);
    EXPECT_EQ(parse_number("17Q"), 15);
    EXPECT_EQ(parse_number("99D"), 99);
    EXPECT_FALSE(parse_number("FFH"));   // must start with a digit
    EXPECT_FALSE(parse_number("12G"));
    EXPECT_FALSE(parse_number("102B"));  // 2 is not binary
    EXPECT_FALSE(parse_number(""));
}

TEST(ScriptTimes, UnitsToTStatesAt3072kHz) {
    EXPECT_EQ(parse_time("3070t"), 3070u);
    EXPECT_EQ(parse_time("1ms"), 3072u);       // 3.072 MHz
    EXPECT_EQ(parse_time("1s"), 3'072'000u);
    EXPECT_EQ(parse_time("250us"), 768u);      // 0.25 ms x 3072
    EXPECT_EQ(parse_time("1.5ms"), 4608u);
    EXPECT_EQ(parse_time("1us"), 3u);          // 3.072 rounds to 3
    EXPECT_FALSE(parse_time("10"));            // a unit is required
    EXPECT_FALSE(parse_time("1.5t"));          // T-states are whole
    EXPECT_FALSE(parse_time("5min"));
    EXPECT_FALSE(parse_time("ms"));
}

TEST(ScriptKeys, MatrixKeysAndTheTwoOutsideIt) {
    EXPECT_EQ(parse_key("exec")->key, periph::Key::Exec);
    EXPECT_EQ(parse_key("a")->key, periph::Key::KA);
    EXPECT_EQ(parse_key("7")->key, periph::Key::K7);
    EXPECT_EQ(parse_key("R")->key, periph::Key::R);
    EXPECT_EQ(parse_key("reset")->kind, Button::Reset);
    EXPECT_EQ(parse_key("VECT")->kind, Button::Vect);
    EXPECT_FALSE(parse_key("Q"));
}

TEST(ScriptParser, CommentsAndBlankLinesAreNothing) {
    std::vector<ParseError> errors;
    EXPECT_FALSE(parse_line("", "t", 1, errors));
    EXPECT_FALSE(parse_line("   # note", "t", 1, errors));
    EXPECT_FALSE(parse_line("; note", "t", 1, errors));
    EXPECT_TRUE(errors.empty());
    EXPECT_EQ(one("print \"a # b\"  # not this").text, "a # b");
}

TEST(ScriptParser, EachCommandsShape) {
    Command c = one("load ../fw/thesis.asm");
    EXPECT_EQ(c.op, Op::Load);
    EXPECT_EQ(c.text, "../fw/thesis.asm");
    c = one("LOAD rom.bin at 0800H");
    EXPECT_EQ(c.address->number, 0x800);
    c = one("press EXEC hold 50ms gap 10ms");
    EXPECT_EQ(c.op, Op::Press);
    EXPECT_EQ(c.time, 153'600u);
    EXPECT_EQ(c.gap, 30'720u);
    c = one("press 5");
    EXPECT_EQ(c.time, kDefaultHold);
    EXPECT_EQ(c.gap, kDefaultGap);
    c = one("type R 7 0 8 0 0 EXEC");
    EXPECT_EQ(c.keys.size(), 7u);
    EXPECT_EQ(c.keys[6].key, periph::Key::Exec);
    c = one("run 100ms");
    EXPECT_EQ(c.op, Op::Run);
    EXPECT_EQ(c.time, 307'200u);
    c = one("run until BITTI+3 timeout 2s");
    EXPECT_EQ(c.op, Op::RunUntil);
    EXPECT_EQ(c.address->symbol, "BITTI");
    EXPECT_EQ(c.address->number, 3);
    EXPECT_EQ(c.time, 6'144'000u);
    c = one("wait display \"H1=----\" timeout 1s");
    EXPECT_EQ(c.op, Op::WaitDisplay);
    EXPECT_EQ(c.text, "H1=----");
    c = one("step 12");
    EXPECT_EQ(c.count, 12u);
    EXPECT_EQ(one("delete all").op, Op::DeleteAll);
    c = one("expect mem 1B00H 01H 02H 0FFH");
    EXPECT_EQ(c.op, Op::ExpectMem);
    EXPECT_EQ(c.values.size(), 3u);
    EXPECT_EQ(c.values[2].number, 0xFF);
    c = one("expect reg hl TABLE-1");
    EXPECT_EQ(c.reg->name, "HL");
    EXPECT_EQ(c.values[0].number, -1);
    c = one("expect flag CY 1");
    EXPECT_EQ(c.flag, 0x01);
    c = one("expect port b 3");
    EXPECT_EQ(c.port, 'B');
    c = one("expect time <= 1.5s");
    EXPECT_EQ(c.compare, Compare::Le);
    EXPECT_EQ(c.time, 4'608'000u);
    EXPECT_EQ(one("expect halted").op, Op::ExpectHalted);
    EXPECT_EQ(one("set mem 2000H 1 2").values.size(), 2u);
    EXPECT_EQ(one("set reg PC 0800H").reg->name, "PC");
    EXPECT_EQ(one("save a.snap").op, Op::Save);
    EXPECT_EQ(one("print display").op, Op::PrintDisplay);
    EXPECT_EQ(one("print display text").text, "text");
}

TEST(ScriptParser, ErrorsPointAtTheirColumn) {
    ParseError e = error_of("frobnicate 1");
    EXPECT_EQ(e.where.line, 7);
    EXPECT_EQ(e.where.col, 1);
    EXPECT_EQ(e.message, "unknown command 'frobnicate'");
    e = error_of("run 5 ms");
    EXPECT_EQ(e.where.col, 5);
    e = error_of("expect mem 1000H 12G");
    EXPECT_EQ(e.where.col, 18);
    EXPECT_EQ(e.message, "bad number '12G'");
    e = error_of("press Q");
    EXPECT_EQ(e.where.col, 7);
    e = error_of("expect flag Z 2");
    EXPECT_EQ(e.where.col, 15);
    e = error_of("wait display H1");
    EXPECT_EQ(e.message, "expected the display text in quotes");
    e = error_of("print \"unclosed");
    EXPECT_EQ(e.message, "string has no closing quote");
    e = error_of("reset now");
    EXPECT_EQ(e.where.col, 7);
    EXPECT_EQ(e.message, "unexpected 'now'");
    EXPECT_EQ(e.format(), "t.alp:7:7: error: unexpected 'now'\n reset now\n       ^\n");
}

// include FILE: relative to the including file, its lines with their own places, errors that say
// where they were included from, and a cycle refused at the include.
TEST(ScriptInclude, LinesComeFromTheIncludedFileWithTheirOwnPlaces) {
    const auto dir = std::filesystem::temp_directory_path() / "alp85 include test";
    std::filesystem::create_directories(dir / "sub");
    std::ofstream(dir / "sub" / "start.alp") << "# shared\nreset\nrun 1ms\n";
    std::ofstream(dir / "sub" / "bad.alp") << "reset\nrun 1xs\n";
    std::ofstream(dir / "sub" / "a.alp") << "include b.alp\n";
    std::ofstream(dir / "sub" / "b.alp") << "include \"a.alp\"\n";
    std::vector<ParseError> errors;
    const std::string top = (dir / "top.alp").string();
    auto cmds = parse_script("monitor\ninclude sub/start.alp\nrun 2ms\n", top, errors);
    ASSERT_TRUE(errors.empty()) << errors.front().format();
    ASSERT_EQ(cmds.size(), 4u);
    EXPECT_EQ(cmds[1].op, Op::Reset);
    EXPECT_EQ(cmds[1].where.file, (dir / "sub" / "start.alp").string());
    EXPECT_EQ(cmds[1].where.line, 2);
    EXPECT_EQ(cmds[2].time, 3072u);
    EXPECT_EQ(cmds[3].where.file, top);
    EXPECT_EQ(cmds[3].where.line, 3);
    // A failure report names an included line by its own place and the include line's.
    EXPECT_EQ(place_of(cmds[1]), (dir / "sub" / "start.alp").string() + ":2 (included from " + top + ":2)");
    EXPECT_EQ(place_of(cmds[3]), top + ":3");

    errors.clear();
    cmds = parse_script("reset\n  include sub/bad.alp\n", top, errors);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].where.file, (dir / "sub" / "bad.alp").string());
    EXPECT_EQ(errors[0].where.line, 2);
    EXPECT_NE(errors[0].message.find("(included from " + top + ":2)"), std::string::npos) << errors[0].message;

    errors.clear();
    parse_script("include sub/a.alp\n", top, errors);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].where.file, (dir / "sub" / "b.alp").string());
    EXPECT_EQ(errors[0].where.line, 1);
    EXPECT_EQ(errors[0].where.col, 10);  // the file's name, inside the quotes
    EXPECT_NE(errors[0].message.find("includes itself"), std::string::npos) << errors[0].message;

    errors.clear();
    parse_script("include sub/none.alp\ninclude\n", top, errors);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0].where.col, 9);
    EXPECT_NE(errors[0].message.find("no such file"), std::string::npos);
    EXPECT_EQ(errors[1].message, "expected: include FILE");
    std::filesystem::remove_all(dir);
}

TEST(ScriptParser, AWholeScriptReportsEveryError) {
    std::vector<ParseError> errors;
    const auto cmds = parse_script("reset\nbogus\nrun 1ms\nrun 1xs\n", "s.alp", errors);
    EXPECT_EQ(cmds.size(), 2u);
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0].where.line, 2);
    EXPECT_EQ(errors[1].where.line, 4);
}

}  // namespace
}  // namespace alp85::script

namespace alp85::script {
namespace {

// Issue #11, 5: where an address is expected, "0800" is refused (it would be decimal 800 =
// 0320H, over the monitor) with the hint to write 0800H; data values and explicit forms are not.
TEST(ScriptAddresses, ALeadingZeroBareNumberIsRefusedWhereAnAddressIsExpected) {
    for (const char* line : {"load x.bin at 0800", "break 0800", "run until 0800", "delete 0800", "expect mem 0800 1",
                             "expect word 0800 1", "set mem 0800 1"}) {
        const ParseError e = error_of(line);
        EXPECT_NE(e.message.find("address '0800' is ambiguous"), std::string::npos) << line << ": " << e.message;
        EXPECT_NE(e.message.find("800 = 0320H"), std::string::npos) << e.message;
        EXPECT_NE(e.message.find("write 0800H for hex or 800 for decimal"), std::string::npos) << e.message;
        EXPECT_EQ(e.where.col, static_cast<int>(std::string_view(line).find("0800")) + 1) << line;
    }
    EXPECT_EQ(one("load x.bin at 0800H").address->number, 0x800);
    EXPECT_EQ(one("load x.bin at 0x800").address->number, 0x800);
    EXPECT_EQ(one("load x.bin at 2048").address->number, 2048);
    EXPECT_EQ(one("load x.bin at 0800D").address->number, 800);  // decimal, said so
    EXPECT_EQ(one("load x.bin at 0").address->number, 0);
    EXPECT_EQ(one("expect mem 1000H 01 02").values[0].number, 1);  // data, not an address
    EXPECT_EQ(ambiguous_address("0800H"), "");
    EXPECT_EQ(ambiguous_address("800"), "");
    EXPECT_NE(ambiguous_address("00"), "");
}

}  // namespace
}  // namespace alp85::script
