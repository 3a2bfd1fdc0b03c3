// Disassembly of emulated memory with names from asm85's JSON map.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "emu/program/symbols.h"
#include "tests/cpu/rig.h"

namespace alp85::test {
namespace {

// delay.asm, assembled at build time with its map (see CMakeLists.txt): START 0100H, DL 0108H,
// IDI 010AH.
void load_delay(Rig& rig) {
    std::ifstream in(ALP85_DELAY_COM, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (std::size_t i = 0; i < bytes.size(); ++i) rig.ram[0x100 + i] = static_cast<std::uint8_t>(bytes[i]);
}

TEST(Symbols, LoadsTheAsm85Map) {
    SymbolTable syms;
    ASSERT_EQ(syms.load_map_file(ALP85_DELAY_MAP), "");
    EXPECT_EQ(syms.value_of("dl"), 0x0108);
    EXPECT_EQ(syms.value_of("IDI"), 0x010A);
    EXPECT_EQ(syms.label_at(0x0100), "START");
    EXPECT_FALSE(syms.value_of("NOPE").has_value());
}

TEST(Symbols, DisassemblyUsesNames) {
    Rig rig;
    load_delay(rig);
    SymbolTable syms;
    ASSERT_EQ(syms.load_map_file(ALP85_DELAY_MAP), "");
    auto d = disassemble(rig.bus, 0x0102, Variant::I8085, &syms);
    EXPECT_EQ(d.text, "CALL DL");
    EXPECT_EQ(d.length, 3);
    d = disassemble(rig.bus, 0x010B, Variant::I8085, &syms);
    EXPECT_EQ(d.text, "JNZ IDI");
    d = disassemble(rig.bus, 0x0100, Variant::I8085, &syms);
    EXPECT_EQ(d.text, "MVI A,0AH");
    d = disassemble(rig.bus, 0x0102, Variant::I8085, nullptr);
    EXPECT_EQ(d.text, "CALL 0108H");
}

TEST(Symbols, VariantDecidesUndocumentedBytes) {
    Rig rig;
    rig.ram[0] = 0x08;
    EXPECT_EQ(disassemble(rig.bus, 0, Variant::I8085).text, "DSUB");
    EXPECT_NE(disassemble(rig.bus, 0, Variant::I8080).text, "DSUB");
}

TEST(Symbols, RejectsWhatIsNotAMap) {
    SymbolTable syms;
    EXPECT_NE(syms.load_map_text("{"), "");
    EXPECT_NE(syms.load_map_text(R"({"format":"other","version":1,"symbols":[]})"), "");
    EXPECT_NE(syms.load_map_text(R"({"format":"alp85-asm-map","version":1,"symbols":[{"name":"X","value":70000}]})"), "");
    // Members of the wrong type are refused, not thrown (found by tests/fuzz/input_fuzz).
    EXPECT_EQ(syms.load_map_text(R"({"format":0,"symbols":[]})"), "not an asm85 map (format alp85-asm-map)");
    EXPECT_NE(syms.load_map_text(R"({"format":"alp85-asm-map","version":"1","symbols":[]})"), "");
    EXPECT_NE(syms.load_map_text(R"({"format":"alp85-asm-map","version":1,"symbols":[{"name":"X","value":1,"kind":7}]})"), "");
    EXPECT_EQ(syms.size(), 0u);
    EXPECT_NE(syms.load_map_file("/nonexistent/map.json"), "");
}

}  // namespace
}  // namespace alp85::test
