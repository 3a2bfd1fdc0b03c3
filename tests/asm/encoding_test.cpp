// Encodings from the bit patterns of the Intel 8085AH data sheet's instruction summary,
// computed here independently of the opcode table.
#include "helpers.h"

namespace alp85::asm85::test {
namespace {

const char* kReg[8] = {"B", "C", "D", "E", "H", "L", "M", "A"};
const char* kPair[4] = {"B", "D", "H", "SP"};
const char* kCond[8] = {"NZ", "Z", "NC", "C", "PO", "PE", "P", "M"};

TEST(Encoding, MovIs01DDDSSS) {
    for (int d = 0; d < 8; ++d)
        for (int s = 0; s < 8; ++s) {
            if (d == 6 && s == 6) continue;  // that byte is HLT
            std::string src = std::string("\tMOV ") + kReg[d] + "," + kReg[s] + "\n";
            EXPECT_EQ(ok_bytes(src), (std::vector<int>{0x40 | d << 3 | s})) << src;
        }
}

TEST(Encoding, RegisterOperandsMayBeExpressions) {
    // Intel: registers are the values 0-7, so MOV 7,0 is MOV A,B and an EQU may name a register.
    EXPECT_EQ(ok_bytes("\tMOV 7,0\nR EQU 3\n\tINR R\n\tMVI R+1,2\n"), (std::vector<int>{0x78, 0x1C, 0x26, 0x02}));
}

TEST(Encoding, SingleRegisterGroups) {
    for (int r = 0; r < 8; ++r) {
        std::string reg = kReg[r];
        EXPECT_EQ(ok_bytes("\tMVI " + reg + ",0A5H\n"), (std::vector<int>{0x06 | r << 3, 0xA5}));
        EXPECT_EQ(ok_bytes("\tINR " + reg + "\n"), (std::vector<int>{0x04 | r << 3}));
        EXPECT_EQ(ok_bytes("\tDCR " + reg + "\n"), (std::vector<int>{0x05 | r << 3}));
        const char* alu[8] = {"ADD", "ADC", "SUB", "SBB", "ANA", "XRA", "ORA", "CMP"};
        for (int o = 0; o < 8; ++o)
            EXPECT_EQ(ok_bytes(std::string("\t") + alu[o] + " " + reg + "\n"), (std::vector<int>{0x80 | o << 3 | r}));
    }
}

TEST(Encoding, ImmediateArithmeticIs11OOO110) {
    const char* imm[8] = {"ADI", "ACI", "SUI", "SBI", "ANI", "XRI", "ORI", "CPI"};
    for (int o = 0; o < 8; ++o)
        EXPECT_EQ(ok_bytes(std::string("\t") + imm[o] + " 12H\n"), (std::vector<int>{0xC6 | o << 3, 0x12}));
}

TEST(Encoding, RegisterPairGroups) {
    for (int p = 0; p < 4; ++p) {
        std::string rp = kPair[p];
        EXPECT_EQ(ok_bytes("\tLXI " + rp + ",0BEEFH\n"), (std::vector<int>{0x01 | p << 4, 0xEF, 0xBE}));
        EXPECT_EQ(ok_bytes("\tDAD " + rp + "\n"), (std::vector<int>{0x09 | p << 4}));
        EXPECT_EQ(ok_bytes("\tINX " + rp + "\n"), (std::vector<int>{0x03 | p << 4}));
        EXPECT_EQ(ok_bytes("\tDCX " + rp + "\n"), (std::vector<int>{0x0B | p << 4}));
        std::string sp = p == 3 ? "PSW" : rp;
        EXPECT_EQ(ok_bytes("\tPUSH " + sp + "\n"), (std::vector<int>{0xC5 | p << 4}));
        EXPECT_EQ(ok_bytes("\tPOP " + sp + "\n"), (std::vector<int>{0xC1 | p << 4}));
    }
    EXPECT_EQ(ok_bytes("\tSTAX B\n\tSTAX D\n\tLDAX B\n\tLDAX D\n"), (std::vector<int>{0x02, 0x12, 0x0A, 0x1A}));
}

TEST(Encoding, ConditionalJumpsCallsReturns) {
    for (int c = 0; c < 8; ++c) {
        std::string cc = kCond[c];
        EXPECT_EQ(ok_bytes("\tJ" + cc + " 1234H\n"), (std::vector<int>{0xC2 | c << 3, 0x34, 0x12}));
        EXPECT_EQ(ok_bytes("\tC" + cc + " 1234H\n"), (std::vector<int>{0xC4 | c << 3, 0x34, 0x12}));
        EXPECT_EQ(ok_bytes("\tR" + cc + "\n"), (std::vector<int>{0xC0 | c << 3}));
    }
}

TEST(Encoding, RestartsAre11NNN111) {
    for (int n = 0; n < 8; ++n) EXPECT_EQ(ok_bytes("\tRST " + std::to_string(n) + "\n"), (std::vector<int>{0xC7 | n << 3}));
    EXPECT_EQ(ok_bytes("\tRST 3+4\n"), (std::vector<int>{0xFF}));
}

TEST(Encoding, TheRest) {
    struct {
        const char* text;
        std::vector<int> bytes;
    } cases[] = {
        {"NOP", {0x00}},       {"RLC", {0x07}},       {"RRC", {0x0F}},       {"RAL", {0x17}},
        {"RAR", {0x1F}},       {"RIM", {0x20}},       {"SHLD 1234H", {0x22, 0x34, 0x12}},
        {"DAA", {0x27}},       {"LHLD 1234H", {0x2A, 0x34, 0x12}},           {"CMA", {0x2F}},
        {"SIM", {0x30}},       {"STA 1234H", {0x32, 0x34, 0x12}},            {"STC", {0x37}},
        {"LDA 1234H", {0x3A, 0x34, 0x12}},            {"CMC", {0x3F}},       {"HLT", {0x76}},
        {"JMP 1234H", {0xC3, 0x34, 0x12}},            {"CALL 1234H", {0xCD, 0x34, 0x12}},
        {"RET", {0xC9}},       {"OUT 0FEH", {0xD3, 0xFE}},                   {"IN 21H", {0xDB, 0x21}},
        {"XTHL", {0xE3}},      {"PCHL", {0xE9}},      {"XCHG", {0xEB}},      {"DI", {0xF3}},
        {"SPHL", {0xF9}},      {"EI", {0xFB}},
    };
    for (auto& c : cases) EXPECT_EQ(ok_bytes(std::string("\t") + c.text + "\n"), c.bytes) << c.text;
}

TEST(Encoding, UndocumentedOpcodes) {
    // Opcodes of the undocumented 8085 instructions (Dehnhardt and Sorensen, 1979).
    struct {
        const char* text;
        std::vector<int> bytes;
    } cases[] = {
        {"DSUB", {0x08}}, {"ARHL", {0x10}}, {"RDEL", {0x18}}, {"LDHI 12H", {0x28, 0x12}},
        {"LDSI 12H", {0x38, 0x12}}, {"RSTV", {0xCB}}, {"SHLX", {0xD9}}, {"JNK 1234H", {0xDD, 0x34, 0x12}},
        {"LHLX", {0xED}}, {"JK 1234H", {0xFD, 0x34, 0x12}},
    };
    for (auto& c : cases) EXPECT_EQ(ok_bytes(std::string("\t") + c.text + "\n", Cpu::i8085u), c.bytes) << c.text;
}

TEST(Encoding, NamesAreCaseInsensitive) {
    EXPECT_EQ(ok_bytes("\tmov a,b\n\tMov A,b\nloop: jmp LOOP\n"), (std::vector<int>{0x78, 0x78, 0xC3, 0x02, 0x00}));
}

}  // namespace
}  // namespace alp85::asm85::test
