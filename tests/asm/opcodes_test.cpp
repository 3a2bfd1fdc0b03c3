// All 256 opcodes through the shared table: text -> asm85 -> bytes -> disassembler -> same text.
#include <fmt/format.h>

#include "asm/disasm.h"
#include "asm/isa.h"
#include "helpers.h"

namespace alp85::asm85::test {
namespace {

// The source text for opcode `op`: template placeholders become fixed operands.
std::string text_for(const isa::OpInfo& o) {
    std::string ops(o.operands);
    std::string out;
    std::size_t start = 0;
    while (start <= ops.size() && !ops.empty()) {
        auto comma = ops.find(',', start);
        std::string slot = ops.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (!out.empty()) out += ",";
        if (slot == "d8" || slot == "p8") out += "5AH";
        else if (slot == "d16" || slot == "a16") out += "1234H";
        else out += slot;
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return std::string(o.mnemonic) + (out.empty() ? "" : " " + out);
}

// Hand-known operand bytes: 5AH for a byte operand, 34H 12H (low first) for a word.
std::vector<int> expected_bytes(int op, const isa::OpInfo& o) {
    std::vector<int> b{op};
    std::string ops(o.operands);
    if (ops.find("d8") != std::string::npos || ops.find("p8") != std::string::npos) b.push_back(0x5A);
    if (ops.find("16") != std::string::npos) {
        b.push_back(0x34);
        b.push_back(0x12);
    }
    return b;
}

TEST(Opcodes, EveryOpcodeAssemblesAndDisassemblesToTheSameText) {
    for (int op = 0; op < 256; ++op) {
        const auto& o = isa::kOpcodes[static_cast<std::size_t>(op)];
        std::string text = text_for(o);
        auto r = assemble("\tORG 100H\n\t" + text + "\n", Cpu::i8085u);
        ASSERT_TRUE(r.ok()) << fmt::format("{:02X} {}: ", op, text) << diags(r);
        auto want = expected_bytes(op, o);
        ASSERT_EQ(all_bytes(r), want) << fmt::format("{:02X} {}", op, text);
        EXPECT_EQ(static_cast<int>(o.length), static_cast<int>(want.size())) << text;
        auto d = disassemble([&](std::uint16_t a) { return r.image.read(a).value_or(0); }, 0x100);
        EXPECT_EQ(d.text, text) << fmt::format("{:02X}", op);
        EXPECT_EQ(d.length, o.length);
    }
}

TEST(Opcodes, TheTableHas244DocumentedOpcodesTwoOf8085AndTenUndocumented) {
    int common = 0, only85 = 0, undoc = 0;
    for (auto& o : isa::kOpcodes) {
        common += o.set == isa::Set::Common;
        only85 += o.set == isa::Set::Only8085;
        undoc += o.set == isa::Set::Undoc8085;
    }
    // The 8080 leaves 12 bytes undefined; the 8085 puts RIM, SIM and ten undocumented ones there.
    EXPECT_EQ(common, 244);
    EXPECT_EQ(only85, 2);
    EXPECT_EQ(undoc, 10);
}

TEST(Opcodes, UndocumentedNeedTheOptionOrDirective) {
    const char* undoc[] = {"DSUB", "ARHL", "RDEL", "LDHI 5", "LDSI 5", "RSTV", "SHLX", "LHLX", "JNK 0", "JK 0", "JNX5 0", "JX5 0"};
    for (auto* u : undoc) {
        auto r = assemble(std::string("\t") + u + "\n");
        ASSERT_FALSE(r.ok()) << u;
        EXPECT_NE(first_error(r).message.find("undocumented 8085 instruction"), std::string::npos) << first_error(r).message;
        EXPECT_EQ(first_error(r).line, 1);
        EXPECT_EQ(first_error(r).col, 2);
        EXPECT_TRUE(assemble(std::string("\t") + u + "\n", Cpu::i8085u).ok()) << u;
        EXPECT_TRUE(assemble(std::string("\tCPU 8085U\n\t") + u + "\n").ok()) << u;
    }
}

TEST(Opcodes, AlternativeMnemonicsJnx5AndJx5) {
    EXPECT_EQ(ok_bytes("\tJNX5 1234H\n\tJX5 5678H\n", Cpu::i8085u), (std::vector<int>{0xDD, 0x34, 0x12, 0xFD, 0x78, 0x56}));
}

TEST(Opcodes, The8080RejectsRimAndSim) {
    for (const char* s : {"RIM", "SIM"}) {
        auto r = assemble(std::string("\t") + s + "\n", Cpu::i8080);
        ASSERT_FALSE(r.ok());
        EXPECT_NE(first_error(r).message.find("8085 instruction"), std::string::npos);
        EXPECT_TRUE(assemble(std::string("\t") + s + "\n").ok());
    }
    EXPECT_EQ(ok_bytes("\tRIM\n\tSIM\n"), (std::vector<int>{0x20, 0x30}));
    auto r = assemble("\tCPU 8080\n\tRIM\n");
    EXPECT_FALSE(r.ok());
    r = assemble("\tDSUB\n", Cpu::i8080);
    EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace alp85::asm85::test
