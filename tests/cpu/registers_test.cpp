// The 8085's description (emu/core/cpu_registers.h) against the data sheet: every register's
// width and what reading and writing it does in the register file; the flags' bits as PUSH PSW
// stores them (S Z K AC 0 P V CY from bit 7 down; docs/cpu.md).
#include <gtest/gtest.h>

#include "emu/core/cpu_registers.h"

namespace alp85::test {
namespace {

TEST(CpuDescription, RegistersReadAndWriteTheRegisterFile) {
    const cpu::Description d = cpu::i8085_description();
    Registers r;
    r.a = 0x12, r.f = 0xD7, r.b = 0x34, r.c = 0x56, r.d = 0x78, r.e = 0x9A, r.h = 0x1B, r.l = 0x30;
    r.sp = 0x20AE, r.pc = 0x0800;
    struct Want {
        const char* name;
        int width;
        std::uint16_t value;
    };
    // The pairs: the first register the high byte (PSW = A, then the flags: PUSH PSW's order).
    for (const Want& w : {Want{"A", 8, 0x12}, {"F", 8, 0xD7}, {"B", 8, 0x34}, {"C", 8, 0x56}, {"D", 8, 0x78}, {"E", 8, 0x9A},
                          {"H", 8, 0x1B}, {"L", 8, 0x30}, {"PSW", 16, 0x12D7}, {"BC", 16, 0x3456}, {"DE", 16, 0x789A},
                          {"HL", 16, 0x1B30}, {"SP", 16, 0x20AE}, {"PC", 16, 0x0800}}) {
        const cpu::Register* x = d.find(w.name);
        ASSERT_NE(x, nullptr) << w.name;
        EXPECT_EQ(x->width, w.width) << w.name;
        EXPECT_EQ(x->read(r), w.value) << w.name;
    }
    d.find("psw")->write(r, 0xA5C3);  // any case
    EXPECT_EQ(r.a, 0xA5);
    EXPECT_EQ(r.f, 0xC3);
    d.find("DE")->write(r, 0x0102);
    EXPECT_EQ(r.d, 0x01);
    EXPECT_EQ(r.e, 0x02);
    d.find("B")->write(r, 0x1FF);  // a byte keeps the low 8 bits
    EXPECT_EQ(r.b, 0xFF);
    EXPECT_EQ(d.find("C")->hex(0x0A), "0AH");
    EXPECT_EQ(d.find("SP")->hex(0x0A), "000AH");
    // M is memory, at the address HL holds: no read or write of its own.
    const cpu::Register* m = d.find("M");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->kind, cpu::Register::Kind::Memory);
    EXPECT_EQ(m->high, "HL");
    EXPECT_EQ(m->read, nullptr);
    EXPECT_EQ(d.find("Q"), nullptr);
    // BC, DE, HL, SP and PC hold addresses; PSW does not.
    for (const char* n : {"BC", "DE", "HL", "SP", "PC"}) EXPECT_TRUE(d.find(n)->address) << n;
    EXPECT_FALSE(d.find("PSW")->address);
    EXPECT_EQ(d.flag_register(), d.find("F"));
}

TEST(CpuDescription, FlagsAreTheBitsPushPswStores) {
    const cpu::Description d = cpu::i8085_description();
    struct Want {
        const char* name;
        std::uint8_t bit;
        bool documented;
    };
    // S bit 7, Z 6, K 5, AC 4, P 2, V 1, CY 0 (bit 3 is always 0); V and K are undocumented.
    for (const Want& w : {Want{"S", 0x80, true}, {"Z", 0x40, true}, {"K", 0x20, false}, {"AC", 0x10, true},
                          {"P", 0x04, true}, {"V", 0x02, false}, {"CY", 0x01, true}}) {
        const cpu::Flag* f = d.find_flag(w.name);
        ASSERT_NE(f, nullptr) << w.name;
        EXPECT_EQ(f->bit, w.bit) << w.name;
        EXPECT_EQ(f->documented, w.documented) << w.name;
    }
    EXPECT_EQ(d.find_flag("c"), d.find_flag("CY"));  // JC, JNC
    EXPECT_EQ(d.find_flag("X5"), d.find_flag("K"));  // its other name
    EXPECT_EQ(d.find_flag("B"), nullptr);
    EXPECT_EQ(d.flags.size(), 7u);
}

}  // namespace
}  // namespace alp85::test
