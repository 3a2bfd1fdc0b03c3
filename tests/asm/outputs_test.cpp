// Intel HEX records and checksums (computed by hand), binary ranges, the listing and the map.
#include <nlohmann/json.hpp>

#include "helpers.h"

namespace alp85::asm85::test {
namespace {

TEST(Hex, OneRecordAndEof) {
    auto r = assemble("\tORG 100H\n\tDB 1,2,3\n");
    // 03+01+00+00+01+02+03 = 0AH; checksum 100H-0AH = F6H.
    EXPECT_EQ(write_intel_hex(r.image), ":03010000010203F6\n:00000001FF\n");
}

TEST(Hex, SixteenBytesPerRecord) {
    std::string src = "\tORG 0\n";
    for (int i = 0; i <= 16; ++i) src += "\tDB " + std::to_string(i) + "\n";
    auto r = assemble(src);
    // Record 1: 10H + sum(0..15)=78H -> 88H, checksum 78H. Record 2: 01+00+10+00+10 = 21H -> DFH.
    EXPECT_EQ(write_intel_hex(r.image),
              ":10000000000102030405060708090A0B0C0D0E0F78\n"
              ":0100100010DF\n"
              ":00000001FF\n");
}

TEST(Hex, SparseRegionsAndStartAddress) {
    auto r = assemble("\tORG 0\n\tNOP\n\tORG 2000H\nGO:\tJMP GO\n\tEND GO\n");
    // :01 0000 00 00 -> 01H -> FFH.  :03 2000 00 C3 00 20 -> 03+20+C3+20 = 106H -> FAH.
    // Start: :04 0000 03 0000 2000 -> 04+03+20 = 27H -> D9H.
    EXPECT_EQ(write_intel_hex(r.image),
              ":0100000000FF\n"
              ":03200000C30020FA\n"
              ":0400000300002000D9\n"
              ":00000001FF\n");
}

TEST(Hex, RecordLengthOption) {
    auto r = assemble("\tDB 1,2,3\n");
    // :02 0000 00 01 02 -> 05H -> FBH;  :01 0002 00 03 -> 06H -> FAH.
    EXPECT_EQ(write_intel_hex(r.image, 2), ":020000000102FB\n:0100020003FA\n:00000001FF\n");
}

TEST(Binary, RangeAndFill) {
    auto r = assemble("\tORG 10H\n\tDB 1\n\tDS 2\n\tDB 2\n");
    EXPECT_EQ(write_binary(r.image, 0x0F, 0x14, 0xEE), (std::vector<std::uint8_t>{0xEE, 1, 0xEE, 0xEE, 2, 0xEE}));
    EXPECT_EQ(r.image.lowest(), 0x10);
    EXPECT_EQ(r.image.highest(), 0x13);
}

TEST(Listing, Snapshot) {
    const char* src =
        "\tTITLE 'DEMO'\n"
        "CR\tEQU 0DH\n"
        "\tORG 100H\n"
        "START:\tMVI A,CR\n"
        "TWICE\tMACRO\n"
        "\tINR A\n"
        "\tINR A\n"
        "\tENDM\n"
        "\tTWICE\n"
        "MSG:\tDB 'HELLO',0\n"
        "\tEND START\n";
    auto r = assemble(src);
    ASSERT_TRUE(r.ok()) << diags(r);
    // MVI A = 3EH; INR A = 3CH; 'HELLO' = 48 45 4C 4C 4F.
    const char* expected =
        "asm85 8080/8085 MACRO ASSEMBLER    DEMO\n"
        "\n"
        "  LOC  OBJ         LINE        SOURCE STATEMENT\n"
        "\n"
        "                     1     \tTITLE 'DEMO'\n"
        "  000D =             2     CR\tEQU 0DH\n"
        "  0100               3     \tORG 100H\n"
        "  0100 3E0D          4     START:\tMVI A,CR\n"
        "                     5     TWICE\tMACRO\n"
        "                     6     \tINR A\n"
        "                     7     \tINR A\n"
        "                     8     \tENDM\n"
        "                     9     \tTWICE\n"
        "  0102 3C           10 +1  \tINR A\n"
        "  0103 3C           11 +1  \tINR A\n"
        "  0104 48454C4C     12     MSG:\tDB 'HELLO',0\n"
        "  0108 4F00\n"
        "  0100 =            13     \tEND START\n"
        "\n"
        "USER SYMBOLS\n"
        "CR         E 000D   MSG        L 0104   START      L 0100\n"
        "\n"
        "ASSEMBLY COMPLETE, NO ERRORS\n";
    EXPECT_EQ(write_listing(r), expected);
}

TEST(Listing, ErrorsAppearUnderTheirLine) {
    auto r = assemble("\tNOP\n\tJMP NOWHERE\n");
    auto l = write_listing(r);
    EXPECT_NE(l.find("\tJMP NOWHERE\n*** ERROR: undefined symbol 'NOWHERE'\n"), std::string::npos) << l;
    EXPECT_NE(l.find("ASSEMBLY COMPLETE, 1 ERROR\n"), std::string::npos);
}

TEST(Map, SymbolsAndEveryByteSource) {
    auto r = assemble("\tORG 10H\nA1:\tNOP\n\tLXI H,A1\n\tEND A1\n");
    auto j = nlohmann::json::parse(write_json_map(r));
    EXPECT_EQ(j["files"][0], "t.asm");
    EXPECT_EQ(j["start"], 16);
    ASSERT_EQ(j["symbols"].size(), 1u);
    EXPECT_EQ(j["symbols"][0]["name"], "A1");
    EXPECT_EQ(j["symbols"][0]["value"], 16);
    EXPECT_EQ(j["symbols"][0]["kind"], "label");
    EXPECT_EQ(j["symbols"][0]["line"], 2);
    ASSERT_EQ(j["lines"].size(), 2u);
    EXPECT_EQ(j["lines"][0]["address"], 16);
    EXPECT_EQ(j["lines"][0]["length"], 1);
    EXPECT_EQ(j["lines"][0]["line"], 2);
    EXPECT_EQ(j["lines"][1]["address"], 17);
    EXPECT_EQ(j["lines"][1]["length"], 3);
    EXPECT_EQ(j["lines"][1]["line"], 3);
    EXPECT_EQ(j["segments"][0]["start"], 16);
    EXPECT_EQ(j["segments"][0]["length"], 4);
}

}  // namespace
}  // namespace alp85::asm85::test
