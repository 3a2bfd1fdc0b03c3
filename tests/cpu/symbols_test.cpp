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

// Names of locations, built by hand as the monitor lays them out: a routine (label, instructions
// of 1-3 bytes), a data table (one 16-byte DB line), an FFH fill (one DS line), and an entry point
// named only by EQU; constants named by small EQUs.
TEST(Symbols, ARoutineNamesItsInstructionsOnlyAndAnEquNamesAnEntryPoint) {
    SymbolTable t;
    t.add("DIGIT", 0x05C0, "label");                   // MVI (2), CALL (3), RET (1)
    t.add_line(0x05C0, 2, "m.asm", 10);
    t.add_line(0x05C2, 3, "m.asm", 11);
    t.add_line(0x05C5, 1, "m.asm", 12);
    t.add("TABLE", 0x05C6, "label");                   // DB 16 bytes
    t.add_line(0x05C6, 16, "m.asm", 13);
    t.add_line(0x05D6, 0x0701 - 0x05D6, "m.asm", 14);  // DS up to the entry point, FFH
    t.add("POLL", 0x0701, "equ");                      // the entry point: IN (2), ANI (2), RZ (1)
    t.add_line(0x0701, 2, "m.asm", 20);
    t.add_line(0x0703, 2, "m.asm", 21);
    t.add_line(0x0705, 1, "m.asm", 22);
    t.add("KMODE", 0x0000, "equ");                     // a constant
    t.add("RAMVAR", 0x2000, "equ");                    // an address no line of code starts at
    t.add_line(0x0000, 3, "m.asm", 1);

    EXPECT_EQ(t.routine_at(0x05C0), "DIGIT");
    EXPECT_EQ(t.routine_at(0x05C2), "DIGIT+2");
    EXPECT_EQ(t.routine_at(0x05C5), "DIGIT+5");
    EXPECT_EQ(t.routine_at(0x05C6), "TABLE");
    EXPECT_EQ(t.routine_at(0x05D0), std::nullopt);    // inside the table
    EXPECT_EQ(t.routine_at(0x0650), std::nullopt);    // in the fill: not TABLE+138
    EXPECT_EQ(t.routine_at(0x0701), "POLL");          // 315 bytes after TABLE: the EQU's name
    EXPECT_EQ(t.routine_at(0x0703), "POLL+2");
    EXPECT_EQ(t.routine_at(0x0704), std::nullopt);    // mid-instruction
    EXPECT_EQ(t.routine_at(0x0000), std::nullopt);    // KMODE is a constant
    EXPECT_EQ(t.code_name_at(0x0701), "POLL");
    EXPECT_EQ(t.code_name_at(0x0000), std::nullopt);
    EXPECT_EQ(t.code_name_at(0x2000), std::nullopt);  // RAMVAR names data, not code
    EXPECT_EQ(t.data_name_at(0x2000), "RAMVAR");
    EXPECT_EQ(t.data_name_at(0x0000), std::nullopt);
}

}  // namespace
}  // namespace alp85::test
