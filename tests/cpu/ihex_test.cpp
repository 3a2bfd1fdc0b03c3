// Intel HEX loading (emu/ihex.h) and the CP/M machine's program loading.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "emu/cpm/cpm.h"
#include "emu/program/ihex.h"

namespace alp85::test {
namespace {

std::map<std::uint16_t, std::uint8_t> load(const std::string& text, std::string& err) {
    std::map<std::uint16_t, std::uint8_t> bytes;
    err = load_intel_hex(text, [&](std::uint16_t a, std::uint8_t v) { bytes[a] = v; });
    return bytes;
}

TEST(IntelHex, LoadsDataRecords) {
    // 3 bytes 3E 05 76 at 0100H: checksum = -(03+01+00+00+3E+05+76) = -0BDH = 43H.
    std::string err;
    auto bytes = load(":030100003E057643\r\n:00000001FF\r\n", err);
    EXPECT_EQ(err, "");
    EXPECT_EQ(bytes, (std::map<std::uint16_t, std::uint8_t>{{0x100, 0x3E}, {0x101, 0x05}, {0x102, 0x76}}));
}

TEST(IntelHex, RejectsBadChecksumAndStoresNothing) {
    std::string err;
    auto bytes = load(":0100000000FF\n:030100003E057644\n:00000001FF\n", err);
    EXPECT_NE(err.find("line 2"), std::string::npos) << err;
    EXPECT_NE(err.find("checksum"), std::string::npos) << err;
    EXPECT_TRUE(bytes.empty());
}

TEST(IntelHex, RejectsMalformedRecords) {
    std::string err;
    load("030100003E057643\n", err);
    EXPECT_NE(err, "");
    load(":0301", err);
    EXPECT_NE(err, "");
    load(":0G0100003E057643\n:00000001FF\n", err);
    EXPECT_NE(err, "");
    load(":030100003E057643\n", err);  // no end-of-file record
    EXPECT_NE(err.find("end-of-file"), std::string::npos) << err;
    load(":02FFFF00000000\n:00000001FF\n", err);  // runs past FFFFH (checksum 02+FF+FF = 00)
    EXPECT_NE(err.find("FFFFH"), std::string::npos) << err;
}

TEST(CpmMachine, RejectsEmptyAndOversizedPrograms) {
    CpmMachine m(Variant::I8085);
    EXPECT_NE(m.load_program({}), "");
    std::vector<std::uint8_t> big(0x10000 - 0x100, 0);
    EXPECT_NE(m.load_program(big), "");
    std::vector<std::uint8_t> ok{0xC3, 0x00, 0x00};  // JMP 0: warm boot
    EXPECT_EQ(m.load_program(ok), "");
    const auto r = m.run(0, nullptr);
    EXPECT_EQ(r.end, CpmMachine::End::WarmBoot);
    EXPECT_EQ(r.exit_status, 0);
    EXPECT_EQ(r.tstates, 10u + 5u);  // JMP 10, HLT 5 at 0000H
}

TEST(CpmMachine, ADebugHookCanStopTheRun) {
    struct StopAt : DebugHooks {
        bool before_instruction(I8085& cpu) override { return cpu.regs().pc != 0x0103; }
    } hook;
    CpmMachine m(Variant::I8085);
    const std::vector<std::uint8_t> prog{0x3E, 0x01, 0x00, 0x00, 0xC3, 0x00, 0x00};  // MVI A,1 / NOP / NOP / JMP 0
    ASSERT_EQ(m.load_program(prog), "");
    m.cpu().set_debug_hooks(&hook);
    const auto r = m.run(0, nullptr);
    EXPECT_EQ(r.end, CpmMachine::End::Stopped);
    EXPECT_NE(r.exit_status, 0);
    EXPECT_EQ(r.message, "stopped by a debug hook before 0103H");
    EXPECT_EQ(r.tstates, 7u + 4u);  // MVI 7, NOP 4; the second NOP did not run
}

TEST(CpmMachine, BdosEntryIsTheTopOfTheTpa) {
    CpmMachine m(Variant::I8080);
    EXPECT_EQ(m.bdos_entry(), 0xFF00);
    EXPECT_EQ(m.cpu().regs().pc, 0x0100);
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

// Issue #11, 8: line and column of what is wrong, and an empty file called empty (not "line 0").
TEST(IntelHex, ErrorsHaveALineAndAColumn) {
    const auto nothing = [](std::uint16_t, std::uint8_t) {};
    auto e = read_intel_hex("", nothing);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->line, 1);
    EXPECT_EQ(e->col, 1);
    EXPECT_EQ(e->message, "empty file: no Intel HEX records");
    e = read_intel_hex("\n\r\n", nothing);  // blank lines only
    ASSERT_TRUE(e);
    EXPECT_EQ(e->message, "empty file: no Intel HEX records");
    // Line 2's checksum (the last two of its 17 characters) is off by one: column 16.
    e = read_intel_hex(":0100000000FF\n:030100003E057644\n:00000001FF\n", nothing);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->line, 2);
    EXPECT_EQ(e->col, 16);
    EXPECT_EQ(e->message, "checksum mismatch");
    // 'G' is the 3rd character of the record.
    e = read_intel_hex(":0G0100003E057643\n:00000001FF\n", nothing);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->line, 1);
    EXPECT_EQ(e->col, 3);
    // Record type 06 (columns 8-9) is unknown; checksum 00+00+00+06 -> FAH.
    e = read_intel_hex(":00000006FA\n:00000001FF\n", nothing);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->col, 8);
    EXPECT_EQ(e->message, "unknown record type");
    // No end-of-file record after line 1: reported where it was due, line 2.
    e = read_intel_hex(":030100003E057643\n", nothing);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->line, 2);
    EXPECT_FALSE(read_intel_hex(":030100003E057643\r\n:00000001FF\r\n", nothing));
}

}  // namespace
}  // namespace alp85::test
