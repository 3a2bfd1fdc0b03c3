// The asm85 executable: outputs, exit status, and no output file when there is an error.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "helpers.h"

namespace alp85::asm85::test {
namespace {

namespace fs = std::filesystem;

class Cli : public ::testing::Test {
protected:
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("asm85_cli_" + std::to_string(::getpid()) + "_" +
                                           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
    std::string read(const std::string& name) {
        std::ifstream in(dir / name, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    int run(const std::string& args) {
        std::string cmd = "cd '" + dir.string() + "' && '" ASM85_EXE "' " + args + " >out.txt 2>err.txt";
        int st = std::system(cmd.c_str());
        return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
};

TEST_F(Cli, WritesHexByDefault) {
    write("p.asm", "\tORG 100H\n\tDB 1,2,3\n");
    EXPECT_EQ(run("p.asm"), 0);
    EXPECT_EQ(read("p.hex"), ":03010000010203F6\n:00000001FF\n");
}

TEST_F(Cli, AllOutputs) {
    write("p.asm", "\tORG 100H\nS:\tDB 1\n\tDS 2\n\tDB 2\n\tEND S\n");
    EXPECT_EQ(run("p.asm -o x.hex --bin x.bin --fill 0FFH --lst x.lst --map x.json"), 0) << read("err.txt");
    EXPECT_EQ(read("x.bin"), std::string("\x01\xFF\xFF\x02", 4));
    EXPECT_NE(read("x.lst").find("LOC  OBJ"), std::string::npos);
    EXPECT_NE(read("x.json").find("\"symbols\""), std::string::npos);
    EXPECT_EQ(read("err.txt"), "");  // the whole program in the binary: nothing to say
    EXPECT_EQ(run("p.asm --bin y.bin --bin-start 0FEH --bin-end 0x101"), 0);
    EXPECT_EQ(read("y.bin"), std::string("\x00\x00\x01\x00", 4));
}

// A range that leaves emitted bytes out (a ROM image cut short) is written as asked, with a
// warning that counts them and names the first.
TEST_F(Cli, ABinaryRangeLeavingBytesOutIsAWarning) {
    write("p.asm", "\tORG 100H\n\tDB 1\n\tDS 2\n\tDB 2,3\n");  // bytes at 100H, 103H, 104H
    EXPECT_EQ(run("p.asm --bin y.bin --bin-start 0FEH --bin-end 0x101"), 0);
    EXPECT_EQ(read("y.bin"), std::string("\x00\x00\x01\x00", 4));
    const std::string err = read("err.txt");
    EXPECT_NE(err.find("warning: 2 bytes outside the binary's 00FEH-0101H left out of y.bin (the first at 0103H"),
              std::string::npos)
        << err;
}

TEST_F(Cli, ErrorsMeanExit1AndNoOutput) {
    write("bad.asm", "\tNOP\n\tJMP NOWHERE\n\tFOO\n");
    write("old.hex", "previous");
    EXPECT_EQ(run("bad.asm -o old.hex --bin b.bin --lst b.lst --map b.json"), 1);
    EXPECT_EQ(read("old.hex"), "previous");
    EXPECT_FALSE(fs::exists(dir / "b.bin"));
    EXPECT_FALSE(fs::exists(dir / "b.lst"));
    EXPECT_FALSE(fs::exists(dir / "b.json"));
    std::string err = read("err.txt");
    EXPECT_NE(err.find("bad.asm:2:6: error: undefined symbol 'NOWHERE'\n\tJMP NOWHERE\n\t    ^\n"), std::string::npos) << err;
    EXPECT_NE(err.find("bad.asm:3:2: error: unknown instruction or directive 'FOO'"), std::string::npos) << err;
}

TEST_F(Cli, DefinesIncludesAndCpu) {
    fs::create_directories(dir / "inc");
    write("inc/k.inc", "K EQU 7\n");
    write("p.asm", "\tINCLUDE k.inc\n\tDB K,V\n\tRIM\n");
    EXPECT_EQ(run("p.asm -I inc -D V=3 -o p.hex"), 0) << read("err.txt");
    // :03 0000 00 07 03 20 -> 03+07+03+20 = 2DH -> D3H.
    EXPECT_EQ(read("p.hex"), ":03000000070320D3\n:00000001FF\n");
    EXPECT_EQ(run("p.asm -I inc -D V=3 --cpu 8080 -o q.hex"), 1);
    EXPECT_FALSE(fs::exists(dir / "q.hex"));
}

TEST_F(Cli, MissingSourceAndHelp) {
    EXPECT_EQ(run("nothere.asm"), 1);
    EXPECT_NE(read("err.txt").find("nothere.asm: error: cannot read source file"), std::string::npos);
    EXPECT_EQ(run("--help"), 0);
    EXPECT_NE(read("out.txt").find("Examples:"), std::string::npos);
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

TEST_F(Cli, LinksAndDevicesAreWrittenThroughNotReplaced) {
    // Output goes through a temporary file and a rename, except into a device or a symbolic
    // link (-o /dev/null must not replace /dev/null). A link stands in for a device here.
    write("p.asm", "\tNOP\n");
    write("real.hex", "");
    fs::create_symlink(dir / "real.hex", dir / "link.hex");
    EXPECT_EQ(run("p.asm -o link.hex"), 0);
    EXPECT_TRUE(fs::is_symlink(dir / "link.hex"));
    EXPECT_EQ(read("real.hex"), ":0100000000FF\n:00000001FF\n");
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

TEST_F(Cli, HexIsTheDefaultOutputUnlessNoHex) {
    write("p.asm", "\tNOP\n");
    EXPECT_EQ(run("p.asm --lst p.lst"), 0);
    EXPECT_TRUE(fs::exists(dir / "p.hex"));
    fs::remove(dir / "p.hex");
    EXPECT_EQ(run("p.asm --no-hex --bin p.bin"), 0);
    EXPECT_FALSE(fs::exists(dir / "p.hex"));
    EXPECT_EQ(read("p.bin"), std::string("\x00", 1));
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

// Issue #11, 1: the outputs appear all together or none does, whichever one cannot be written.
TEST_F(Cli, OneUnwritableOutputMeansNoOutputAtAll) {
    write("p.asm", "\tORG 100H\n\tDB 1,2,3\n");
    write("nodir", "a file, not a folder");
    EXPECT_EQ(run("p.asm --lst nodir/x.lst"), 1);
    EXPECT_FALSE(fs::exists(dir / "p.hex"));
    EXPECT_NE(read("err.txt").find("nodir/x.lst"), std::string::npos) << read("err.txt");
    EXPECT_EQ(run("p.asm -o nodir/x.hex --lst p.lst"), 1);
    EXPECT_FALSE(fs::exists(dir / "p.lst"));
    EXPECT_EQ(run("p.asm --bin p.bin --lst p.lst --map nodir/p.json"), 1);
    EXPECT_FALSE(fs::exists(dir / "p.hex"));
    EXPECT_FALSE(fs::exists(dir / "p.bin"));
    EXPECT_FALSE(fs::exists(dir / "p.lst"));
    // Files from an earlier run stay as they were, and no temporary is left beside them.
    write("p.hex", "old hex");
    write("p.lst", "old listing");
    EXPECT_EQ(run("p.asm --lst p.lst --bin nodir/p.bin"), 1);
    EXPECT_EQ(read("p.hex"), "old hex");
    EXPECT_EQ(read("p.lst"), "old listing");
    // A range error found while making the outputs: nothing is written either.
    EXPECT_EQ(run("p.asm --lst p.lst --bin q.bin --bin-start 200H --bin-end 100H"), 2);  // a usage error
    EXPECT_EQ(read("p.hex"), "old hex");
    EXPECT_FALSE(fs::exists(dir / "q.bin"));
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.path().filename().string().find(".tmp") == std::string::npos ? 0 : 1;
    EXPECT_EQ(files, 0u);
    // And when every output can be written, all are.
    EXPECT_EQ(run("p.asm --lst p.lst --bin p.bin"), 0);
    EXPECT_EQ(read("p.hex"), ":03010000010203F6\n:00000001FF\n");
    EXPECT_EQ(read("p.bin"), std::string("\x01\x02\x03", 3));
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

// A misused ASM80 construct is an error in the source: exit status 1 (as --help says), the
// place on stderr, and no output file.
TEST_F(Cli, AnOpenIfExitsOneWithItsPlaceAndWritesNothing) {
    write("m.asm", "\tNOP\n\tIF\t1\n\tNOP\n");
    EXPECT_EQ(run("m.asm --lst m.lst"), 1);
    EXPECT_NE(read("err.txt").find("m.asm:2:2: error: IF without ENDIF\n"), std::string::npos) << read("err.txt");
    EXPECT_FALSE(fs::exists(dir / "m.hex"));
    EXPECT_FALSE(fs::exists(dir / "m.lst"));
}

// Issue #11, 4: usage errors exit 2, not CLI11's own codes (105, 106, 109, ...); --help says so.
TEST_F(Cli, UsageErrorsExit2AndHelpListsTheExitStatuses) {
    write("p.asm", "\tNOP\n");
    EXPECT_EQ(run(""), 2);                       // no SOURCE
    EXPECT_EQ(run("p.asm --no-such-option"), 2);
    EXPECT_EQ(run("p.asm --cpu 6502"), 2);
    EXPECT_EQ(run("p.asm --name-length 99"), 2);
    EXPECT_EQ(run("p.asm --bin p.bin --bin-start XYZ"), 2);
    EXPECT_FALSE(fs::exists(dir / "p.hex"));
    EXPECT_FALSE(fs::exists(dir / "p.bin"));
    // An empty output name is no file: not the default (-o '' wrote p.hex) nor "no output".
    for (const char* opt : {"-o", "--hex", "--bin", "--lst", "--map"}) {
        EXPECT_EQ(run(std::string("p.asm ") + opt + " ''"), 2) << opt;
        EXPECT_NE(read("err.txt").find("an empty file name"), std::string::npos) << opt << ": " << read("err.txt");
        EXPECT_TRUE(fs::is_empty(dir / "out.txt")) << opt;
        EXPECT_FALSE(fs::exists(dir / "p.hex")) << opt;
    }
    EXPECT_EQ(run("p.asm -D ''"), 2);
    EXPECT_EQ(run("p.asm -D 1X"), 2);
    EXPECT_EQ(run("p.asm -D A-B"), 2);
    EXPECT_FALSE(fs::exists(dir / "p.hex"));
    EXPECT_EQ(run("--help"), 0);
    const std::string help = read("out.txt");
    EXPECT_NE(help.find("Exit status: 0 success; 1 an error in the source"), std::string::npos) << help;
    EXPECT_NE(help.find("2 a usage error"), std::string::npos) << help;
}

}  // namespace
}  // namespace alp85::asm85::test
