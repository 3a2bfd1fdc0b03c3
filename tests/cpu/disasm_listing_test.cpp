// Disassembly of whole images (emu/disasm_listing.h): blocks, ranges, labels, the DB fallbacks
// and the two output forms. Expected texts come from the opcode encodings of the 8085 data sheet.
#include <gtest/gtest.h>

#include "emu/program/disasm_listing.h"

namespace alp85::test {
namespace {

// 0800: MVI A,05H / JMP 0800H / HLT / CD (a CALL with no operand bytes); 0900: NOP
std::vector<ImageSegment> small_image() {
    return {{0x0800, {0x3E, 0x05, 0xC3, 0x00, 0x08, 0x76, 0xCD}}, {0x0900, {0x00}}};
}

TEST(DisasmImage, BlocksFollowTheSegments) {
    const DisasmResult r = disassemble_image(small_image(), {});
    ASSERT_EQ(r.blocks.size(), 2u);
    EXPECT_EQ(r.bytes, 8u);
    const auto& l = r.blocks[0].lines;
    ASSERT_EQ(l.size(), 4u);
    EXPECT_EQ(l[0].text, "MVI A,05H");
    EXPECT_EQ(l[1].address, 0x0802);
    EXPECT_EQ(l[1].text, "JMP 0800H");
    EXPECT_EQ(l[2].text, "HLT");
    // CDH needs two operand bytes the image does not have.
    EXPECT_EQ(l[3].text, "DB 0CDH");
    EXPECT_EQ(l[3].bytes, std::vector<std::uint8_t>{0xCD});
    EXPECT_EQ(r.blocks[1].start, 0x0900);
    EXPECT_EQ(r.blocks[1].lines[0].text, "NOP");
}

TEST(DisasmImage, FromAndToLimitTheRange) {
    ImageDisasmOptions o;
    o.from = 0x0802;
    o.to = 0x0803;  // inside the JMP that starts at 0802H: it is decoded whole (issue 23, 14)
    const DisasmResult r = disassemble_image(small_image(), o);
    ASSERT_EQ(r.blocks.size(), 1u);
    ASSERT_EQ(r.blocks[0].lines.size(), 1u);
    EXPECT_EQ(r.blocks[0].lines[0].text, "JMP 0800H");
    EXPECT_EQ(r.bytes, 3u);
}

TEST(DisasmImage, SourceLabelsEveryTargetItSeesAndEndsWithTheStart) {
    // 0800 MVI A,5 / 0802 DCR A / 0803 JNZ 0802H / 0806 CALL 0800H / 0809 JMP 4000H (outside)
    ImageDisasmOptions o;
    o.label_targets = true;
    const DisasmResult r = disassemble_image(
        {{0x0800, {0x3E, 0x05, 0x3D, 0xC2, 0x02, 0x08, 0xCD, 0x00, 0x08, 0xC3, 0x00, 0x40}}}, o);
    const std::string s = format_source(r, o, "t.hex");
    EXPECT_NE(s.find("START:\n                MVI A,05H"), std::string::npos) << s;
    EXPECT_NE(s.find("L0802:\n                DCR A"), std::string::npos) << s;
    EXPECT_NE(s.find("JNZ L0802"), std::string::npos) << s;
    EXPECT_NE(s.find("CALL START"), std::string::npos) << s;
    EXPECT_NE(s.find("JMP 4000H"), std::string::npos) << s;  // no line there: no label
    EXPECT_NE(s.find("END START\n"), std::string::npos) << s;
}

TEST(DisasmImage, LabelsNameOperandsAndCutInstructions) {
    SymbolTable syms;
    syms.add("START", 0x0800, "label");
    syms.add("MID", 0x0803, "label");  // inside the JMP: decoding restarts there
    syms.add("PORT", 0x0005, "equ");
    ImageDisasmOptions o;
    o.symbols = &syms;
    const DisasmResult r = disassemble_image(small_image(), o);
    const auto& l = r.blocks[0].lines;
    EXPECT_EQ(l[0].label, "START");
    EXPECT_EQ(l[1].text, "DB 0C3H");
    EXPECT_EQ(l[2].address, 0x0803);
    EXPECT_EQ(l[2].label, "MID");
    EXPECT_EQ(l[2].text, "NOP");  // 00H
    EXPECT_EQ(l[3].text, "DSUB");  // 08H on the 8085
    EXPECT_EQ(r.names_used.size(), 0u);  // no complete instruction had a 16-bit operand

    o.symbols = &syms;
    const DisasmResult r2 =
        disassemble_image({{0x0100, {0xCD, 0x05, 0x00, 0xC3, 0x00, 0x08, 0x21, 0x05, 0x00, 0x21, 0x00, 0x08}}}, o);
    EXPECT_EQ(r2.blocks[0].lines[0].text, "CALL PORT");
    EXPECT_EQ(r2.blocks[0].lines[1].text, "JMP START");
    EXPECT_EQ(r2.blocks[0].lines[2].text, "LXI H,0005H");  // a small EQU is not an LXI's name
    EXPECT_EQ(r2.blocks[0].lines[3].text, "LXI H,START");  // a label is
    EXPECT_EQ(r2.names_used, (std::set<std::string>{"PORT", "START"}));
}

TEST(DisasmImage, Cpu8080ShowsThe8085OnlyOpcodesAsData) {
    ImageDisasmOptions o;
    const std::vector<ImageSegment> img{{0x0100, {0x20, 0x08}}};
    EXPECT_EQ(disassemble_image(img, o).blocks[0].lines[0].text, "RIM");
    EXPECT_EQ(disassemble_image(img, o).blocks[0].lines[1].text, "DSUB");
    o.variant = Variant::I8080;
    EXPECT_EQ(disassemble_image(img, o).blocks[0].lines[0].text, "DB 20H");
}

TEST(DisasmImage, ListingColumns) {
    SymbolTable syms;
    syms.add("START", 0x0800, "label");
    ImageDisasmOptions o;
    o.symbols = &syms;
    EXPECT_EQ(format_listing(disassemble_image(small_image(), o)),
              "START:\n"
              "0800  3E 05      MVI A,05H\n"
              "0802  C3 00 08   JMP START\n"
              "0805  76         HLT\n"
              "0806  CD         DB 0CDH\n"
              "\n"
              "0900  00         NOP\n");
}

TEST(DisasmImage, SourceDefinesWhatItUses) {
    SymbolTable syms;
    syms.add("START", 0x0800, "label");
    syms.add("BDOS", 0x0005, "equ");
    syms.add("FAR", 0x4000, "label");  // a label outside the image: needs an EQU
    ImageDisasmOptions o;
    o.symbols = &syms;
    const DisasmResult r =
        disassemble_image({{0x0800, {0xCD, 0x05, 0x00, 0xC3, 0x00, 0x40, 0xC3, 0x00, 0x08}}}, o);
    const std::string s = format_source(r, o, "t.hex");
    EXPECT_NE(s.find("BDOS            EQU 0005H\n"), std::string::npos) << s;
    EXPECT_NE(s.find("FAR             EQU 4000H\n"), std::string::npos) << s;
    EXPECT_EQ(s.find("START           EQU"), std::string::npos) << s;  // placed as a label instead
    EXPECT_NE(s.find("ORG 0800H\nSTART:\n                CALL BDOS"), std::string::npos) << s;
    EXPECT_NE(s.find("JMP START"), std::string::npos) << s;
    EXPECT_NE(s.find("asm85 --cpu 8085u"), std::string::npos) << s;
    EXPECT_NE(s.rfind("END START\n"), std::string::npos) << s;  // the first line's label is the start
}

}  // namespace
}  // namespace alp85::test
