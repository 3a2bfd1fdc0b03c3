// The disassembler: text format, symbol callback, 8080 mode, wrap-around.
#include "asm/disasm.h"
#include "helpers.h"

namespace alp85::asm85::test {
namespace {

Disassembly dis(std::vector<std::uint8_t> mem, std::uint16_t at = 0, const DisasmOptions& o = {}) {
    return disassemble([&](std::uint16_t a) { return a < mem.size() ? mem[a] : std::uint8_t{0}; }, at, o);
}

TEST(Disasm, Formats) {
    EXPECT_EQ(dis({0x3E, 0xFF}).text, "MVI A,0FFH");
    EXPECT_EQ(dis({0x3E, 0x05}).text, "MVI A,05H");
    EXPECT_EQ(dis({0xC3, 0x00, 0xC0}).text, "JMP 0C000H");
    EXPECT_EQ(dis({0x78}).text, "MOV A,B");
    EXPECT_EQ(dis({0xF5}).text, "PUSH PSW");
    EXPECT_EQ(dis({0xEF}).text, "RST 5");
    EXPECT_EQ(dis({0xDB, 0x21}).text, "IN 21H");
    auto d = dis({0x21, 0x34, 0x12});
    EXPECT_EQ(d.length, 3);
    EXPECT_EQ(d.bytes[1], 0x34);
    EXPECT_EQ(d.bytes[2], 0x12);
}

TEST(Disasm, SymbolCallback) {
    DisasmOptions o;
    o.symbol = [](std::uint16_t a) -> std::optional<std::string> {
        if (a == 0x0005) return "BDOS";
        return std::nullopt;
    };
    EXPECT_EQ(dis({0xCD, 0x05, 0x00}, 0, o).text, "CALL BDOS");
    EXPECT_EQ(dis({0xCD, 0x06, 0x00}, 0, o).text, "CALL 0006H");
    EXPECT_EQ(dis({0x21, 0x05, 0x00}, 0, o).text, "LXI H,BDOS");  // no data_symbol: symbol names d16 too
    o.data_symbol = [](std::uint16_t) -> std::optional<std::string> { return std::nullopt; };
    EXPECT_EQ(dis({0x21, 0x05, 0x00}, 0, o).text, "LXI H,0005H");
    EXPECT_EQ(dis({0xCD, 0x05, 0x00}, 0, o).text, "CALL BDOS");
}

TEST(Disasm, Cpu8080ShowsNon8080BytesAsData) {
    DisasmOptions o;
    o.cpu8080 = true;
    EXPECT_EQ(dis({0x20}, 0, o).text, "DB 20H");
    EXPECT_EQ(dis({0xDD, 1, 2}, 0, o).length, 1);
    EXPECT_EQ(dis({0x20}).text, "RIM");
}

TEST(Disasm, OperandsWrapAtTheTopOfMemory) {
    auto d = disassemble([](std::uint16_t a) -> std::uint8_t { return a == 0xFFFF ? 0xC3 : a == 0 ? 0x34 : a == 1 ? 0x12 : 0; }, 0xFFFF);
    EXPECT_EQ(d.text, "JMP 1234H");
}

}  // namespace
}  // namespace alp85::asm85::test
