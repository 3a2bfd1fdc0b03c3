// Each directive, labels, conditionals and INCLUDE.
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "helpers.h"

namespace alp85::asm85::test {
namespace {

using V = std::vector<int>;

TEST(Directives, OrgGivesSparseSegments) {
    auto r = assemble("\tORG 10H\n\tNOP\n\tORG 20H\n\tHLT\n\tRET\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    auto segs = r.image.segments();
    ASSERT_EQ(segs.size(), 2u);
    EXPECT_EQ(segs[0].start, 0x10);
    EXPECT_EQ(segs[0].bytes, (std::vector<std::uint8_t>{0x00}));
    EXPECT_EQ(segs[1].start, 0x20);
    EXPECT_EQ(segs[1].bytes, (std::vector<std::uint8_t>{0x76, 0xC9}));
    EXPECT_EQ(r.image.size(), 3u);
}

TEST(Directives, EquSetAndEquals) {
    auto r = assemble("A1\tEQU 5\nS\tSET 1\nS\tSET S+1\nQ = 7\nQ = Q*2\nDR: EQU 9\n\tDB A1,S,Q,DR\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{5, 2, 14, 9}));
    EXPECT_EQ(r.find_symbol("a1")->kind, SymbolKind::Equ);
    EXPECT_EQ(r.find_symbol("S")->kind, SymbolKind::Set);
    EXPECT_EQ(r.find_symbol("Q")->value, 14);
}

TEST(Directives, DbStringsAndExpressions) {
    EXPECT_EQ(ok_bytes("\tDB 'AB',0,\"C'D\",'''',1+1,-1\n"), (V{0x41, 0x42, 0, 0x43, 0x27, 0x44, 0x27, 2, 0xFF}));
    EXPECT_EQ(ok_bytes("\tDEFB 'A'+80H\n\tDEFM 'xy'\n"), (V{0xC1, 'x', 'y'}));
    EXPECT_EQ(ok_bytes("\tDC 'AB'\n"), (V{0x41, 0xC2}));  // M80: bit 7 on the last character
}

TEST(Directives, DwIsLowByteFirst) {
    EXPECT_EQ(ok_bytes("\tDW 1234H,'AB',5\n\tDEFW 0ABCDH\n"), (V{0x34, 0x12, 0x42, 0x41, 5, 0, 0xCD, 0xAB}));
}

TEST(Directives, DsReservesOrFills) {
    auto r = assemble("\tDB 1\n\tDS 3\n\tDB 2\n\tDEFS 2,0E5H\n\tDB 3\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(bytes(r, 0, 8), (V{1, -1, -1, -1, 2, 0xE5, 0xE5, 3}));
}

TEST(Directives, EndStopsAndNamesTheStart) {
    auto r = assemble("\tORG 100H\nGO:\tNOP\n\tEND GO\n\tDB 99\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{0}));
    ASSERT_TRUE(r.image.start_address.has_value());
    EXPECT_EQ(*r.image.start_address, 0x100);
    EXPECT_FALSE(assemble("\tNOP\n\tEND\n").image.start_address.has_value());
}

TEST(Directives, LabelsWithAndWithoutColon) {
    auto r = assemble("ONE:\tNOP\nTWO\tNOP\nTHREE\n\tNOP\nFOUR: MVI A,1\nFIVE::\tNOP\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(r.find_symbol("ONE")->value, 0);
    EXPECT_EQ(r.find_symbol("TWO")->value, 1);
    EXPECT_EQ(r.find_symbol("THREE")->value, 2);
    EXPECT_EQ(r.find_symbol("FOUR")->value, 3);
    EXPECT_EQ(r.find_symbol("FIVE")->value, 5);
    EXPECT_EQ(r.find_symbol("Two")->kind, SymbolKind::Label);
}

TEST(Directives, DrDollarInNamesAndBangSeparator) {
    auto r = assemble("BDOS$ENTRY EQU 5\n\tCALL BDOSENTRY ! RET\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{0xCD, 5, 0, 0xC9}));
}

TEST(Directives, CommentLines) {
    EXPECT_EQ(ok_bytes("; comment\n* DR comment line\n\tNOP ; trailing\n\n"), (V{0}));
}

TEST(Directives, NestedIfElseEndif) {
    const char* src =
        "T EQU 1\nF EQU 0\n"
        "\tIF T\n\tDB 1\n\tIF F\n\tDB 2\n\tELSE\n\tDB 3\n\tENDIF\n\tELSE\n\tDB 4\n\tIF T\n\tDB 5\n\tENDIF\n\tENDIF\n"
        "\tIF F\n\tIF T\n\tDB 6\n\tELSE\n\tDB 7\n\tENDIF\n\tENDIF\n";
    EXPECT_EQ(ok_bytes(src), (V{1, 3}));
}

TEST(Directives, M80ConditionalForms) {
    const char* src =
        "X EQU 0\n"
        "\tIFE X\n\tDB 1\n\tENDIF\n"
        "\tIFT X\n\tDB 2\n\tENDIF\n"
        "\tIFDEF X\n\tDB 3\n\tENDIF\n"
        "\tIFNDEF Y\n\tDB 4\n\tENDIF\n"
        "\tIFB <>\n\tDB 5\n\tENDIF\n"
        "\tIFNB <A>\n\tDB 6\n\tENDIF\n"
        "\tIFIDN <A>,<A>\n\tDB 7\n\tENDIF\n"
        "\tIFDIF <A>,<B>\n\tDB 8\n\tENDC\n"
        "\tIF2\n\tDB 9\n\tENDIF\n";
    EXPECT_EQ(ok_bytes(src), (V{1, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(Directives, ListingAndSegmentDirectivesChangeNoByte) {
    const char* src =
        "\tTITLE 'T'\n\tSUBTTL x\n\tPAGE 60\n\tEJECT\n\tNAME M\n\t.8080\n\tASEG\n\tCSEG\n\tDSEG\n"
        "\t.LIST\n\t.XLIST\n\tPUBLIC A1\n\t.SALL\n\tSPACE 2\n$MOD85\n$NOLIST\nA1:\tNOP\n";
    auto r = assemble(src);
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{0}));
    EXPECT_EQ(r.title, "T");
}

TEST(Directives, RadixAndComment) {
    EXPECT_EQ(ok_bytes("\t.RADIX 16\n\tDB 10,0FF,11B\n\t.RADIX 10\n\tDB 10\n"), (V{0x10, 0xFF, 0x1B, 10}));
    EXPECT_EQ(ok_bytes("\t.COMMENT *\nanything here\n  even MOV X,Y *\n\tNOP\n"), (V{0}));
}

TEST(Directives, ErrorDirective) {
    auto r = assemble("SIZE EQU 300\n\tIF SIZE GT 255\n\tERROR 'table too big'\n\tENDIF\n");
    ASSERT_EQ(r.error_count(), 1);
    EXPECT_EQ(first_error(r).message, "table too big");
    EXPECT_EQ(first_error(r).line, 3);
    EXPECT_EQ(first_error(r).col, 2);
    EXPECT_FALSE(assemble("\t.ERRNZ 1\n").ok());
    EXPECT_TRUE(assemble("\t.ERRNZ 0\n").ok());
}

class IncludeFiles : public ::testing::Test {
protected:
    // Unique per process and test: CTest runs the tests of this suite in parallel processes,
    // where a seed or an object address can repeat (they did, under ASan).
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("asm85_inc_" + std::to_string(::getpid()) + "_" +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    void SetUp() override { std::filesystem::create_directories(dir / "lib"); }
    void TearDown() override { std::filesystem::remove_all(dir); }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir / name) << text; }
};

TEST_F(IncludeFiles, IncludeMaclibAndIntelControl) {
    write("main.asm", "\tINCLUDE defs.inc\n\tMACLIB MAC\n$INCLUDE(:F1:OTHER.SRC)\n\tDB K\n\tTWICE\n");
    write("defs.inc", "K EQU 42\n");
    write("lib/MAC.LIB", "TWICE MACRO\n\tNOP\n\tNOP\n\tENDM\n");
    write("OTHER.SRC", "\tDB 1\n");
    Options o;
    o.include_dirs.push_back(dir / "lib");
    auto r = assemble_file(dir / "main.asm", o);
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(all_bytes(r), (V{1, 42, 0, 0}));
    ASSERT_EQ(r.files.size(), 4u);
    // The byte 42 comes from main.asm line 4.
    auto* span = r.origin(1);
    ASSERT_NE(span, nullptr);
    EXPECT_EQ(span->file, 0);
    EXPECT_EQ(span->line, 4);
}

TEST_F(IncludeFiles, MissingIncludeIsAnError) {
    write("main.asm", "\tNOP\n\tINCLUDE nothere.inc\n");
    auto r = assemble_file(dir / "main.asm");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(first_error(r).message, "cannot open include file 'nothere.inc'");
    EXPECT_EQ(first_error(r).line, 2);
    EXPECT_EQ(first_error(r).col, 10);
}

TEST(Directives, CommandLineDefines) {
    Options o;
    o.defines = {{"DEBUG", ""}, {"BAUD", "96"}};
    auto r = assemble_string("\tIF DEBUG\n\tDB BAUD\n\tENDIF\nBAUD EQU 12\n", o);
    EXPECT_EQ(all_bytes(r), (V{96}));
    EXPECT_EQ(r.error_count(), 0);
    EXPECT_EQ(r.warning_count(), 1);  // the source's BAUD EQU 12 is ignored, with a warning
}

}  // namespace
}  // namespace alp85::asm85::test

namespace alp85::asm85::test {
namespace {

TEST(Directives, BangInsideAngleBracketsIsNotASeparator) {
    EXPECT_EQ(ok_bytes("M\tMACRO X\n\tDB X\n\tENDM\n\tM <1!,2> ! NOP\n"), (V{1, 2, 0}));
}

TEST(Directives, PhaseAssemblesForAnotherRunAddress) {
    // M80: code stored at 0100H that will run at 0F000H; labels and $ follow the run address.
    auto r = assemble("\tORG 100H\n\t.PHASE 0F000H\nHERE:\tJMP HERE\n\tDW $\n\t.DEPHASE\nBACK:\tDW BACK\n");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_EQ(bytes(r, 0x100, 7), (V{0xC3, 0x00, 0xF0, 0x03, 0xF0, 0x05, 0x01}));
    EXPECT_EQ(r.find_symbol("HERE")->value, 0xF000);
}

TEST(Directives, If1IsFalseInTheFinalPass) {
    EXPECT_EQ(ok_bytes("\tIF1\n\tDB 1\n\tELSE\n\tDB 2\n\tENDIF\n"), (V{2}));
}

TEST(Directives, ListingMarksIncludedLines) {
    Options o;
    o.read_file = [](const std::filesystem::path& p) -> std::optional<std::string> {
        if (p.filename() == "k.inc") return std::string("\tDB 7\n");
        return std::nullopt;
    };
    auto r = assemble_string("\tINCLUDE k.inc\n", o, "m.asm");
    ASSERT_TRUE(r.ok()) << diags(r);
    EXPECT_NE(write_listing(r).find("  0000 07            2 =   \tDB 7\n"), std::string::npos) << write_listing(r);
}

}  // namespace
}  // namespace alp85::asm85::test
