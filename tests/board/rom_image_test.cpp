// The ROM loader for a board whose ROM is the user's (read_rom_image, emu/program/rom_image.h):
// a 2 KB dump, Intel HEX or source, placed in 0000H-07FFH; every bad file refused with a
// sentence naming it (and line:col where there is one). The expected bytes are written here by
// hand (opcodes from the 8085's instruction table: 3EH MVI A, 76H HLT, C3H JMP, 00H NOP).
#include "emu/program/rom_image.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace alp85::test {
namespace {

namespace fs = std::filesystem;

class RomImageTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("alp85_rom_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path write(const std::string& name, const std::string& data) {
        const fs::path p = dir / name;
        std::ofstream(p, std::ios::binary) << data;
        return p;
    }
    // A type 00 record: :LLAAAA00DD..CC, CC the two's complement of the sum of the other bytes.
    static std::string record(std::uint16_t address, const std::string& data) {
        unsigned sum = static_cast<unsigned>(data.size()) + (address >> 8) + (address & 0xFF);
        std::string r = ":" + hex2(static_cast<unsigned>(data.size())) + hex2(address >> 8) + hex2(address & 0xFF) + "00";
        for (char c : data) {
            r += hex2(static_cast<unsigned char>(c));
            sum += static_cast<unsigned char>(c);
        }
        return r + hex2((0x100 - (sum & 0xFF)) & 0xFF) + "\n";
    }
    static std::string hex2(unsigned v) {
        static const char* d = "0123456789ABCDEF";
        return {d[(v >> 4) & 15], d[v & 15]};
    }
    // The error message read_rom_image gives for `p`, or "" if it loads.
    static std::string refusal(const fs::path& p, const RomSpec& rom = {}) {
        try {
            (void)read_rom_image(p, rom);
        } catch (const LoadError& e) {
            return e.what();
        }
        return "";
    }
    static constexpr const char* kEof = ":00000001FF\n";
    fs::path dir;
};

// A dump as a kit's owner has one: 2048 bytes, byte 0 at 0000H.
std::string dump() {
    std::string d(2048, '\xFF');
    d[0] = '\xC3', d[1] = '\x00', d[2] = '\x01';  // JMP 0100H
    d[0x7FF] = '\x00';
    return d;
}

TEST_F(RomImageTest, A2048ByteDumpIsTheWholeRom) {
    const RomImage img = read_rom_image(write("monitor.bin", dump()));
    ASSERT_EQ(img.bytes.size(), 2048u);
    EXPECT_EQ(img.bytes[0], 0xC3);
    EXPECT_EQ(img.bytes[2], 0x01);
    EXPECT_EQ(img.bytes[3], 0xFF);
    EXPECT_EQ(img.bytes[0x7FF], 0x00);
    EXPECT_EQ(img.programmed, 2048u);
}

TEST_F(RomImageTest, MissingFileIsRefusedByName) {
    const std::string why = refusal(dir / "nothere.bin");
    EXPECT_NE(why.find("nothere.bin"), std::string::npos) << why;
    EXPECT_NE(why.find("no such file"), std::string::npos) << why;
}

TEST_F(RomImageTest, EmptyDumpIsRefused) {
    const std::string why = refusal(write("empty.bin", ""));
    EXPECT_NE(why.find("empty.bin: empty file"), std::string::npos) << why;
}

TEST_F(RomImageTest, ShortDumpIsRefusedNotPadded) {
    // 100 bytes: a truncated dump; a raw binary has no addresses, so its size is its only check.
    std::string d = dump().substr(0, 100);
    const std::string why = refusal(write("short.bin", d));
    EXPECT_NE(why.find("short.bin: short: 100 bytes"), std::string::npos) << why;
    EXPECT_NE(why.find("2048-byte ROM (0000H-07FFH)"), std::string::npos) << why;
}

TEST_F(RomImageTest, DumpLargerThanTheRomIsRefused) {
    const std::string why = refusal(write("big.bin", dump() + '\x00'));
    EXPECT_NE(why.find("big.bin: 2049 bytes, larger than the 2048-byte ROM (0000H-07FFH)"), std::string::npos) << why;
}

TEST_F(RomImageTest, TextNamedBinIsNotARom) {
    const std::string why = refusal(write("listing.bin", "; SDK-85 monitor\n\tORG 0\n"));
    EXPECT_NE(why.find("listing.bin: text, not a ROM image (it begins '; SDK-85 monitor')"), std::string::npos) << why;
}

TEST_F(RomImageTest, HexFillsTheRestWithFF) {
    const RomImage img = read_rom_image(write("p.hex", record(0x0000, "\x3E\x01\x76") + kEof));
    ASSERT_EQ(img.bytes.size(), 2048u);
    EXPECT_EQ(img.bytes[0], 0x3E);
    EXPECT_EQ(img.bytes[1], 0x01);
    EXPECT_EQ(img.bytes[2], 0x76);
    EXPECT_EQ(img.bytes[3], 0xFF);
    EXPECT_EQ(img.programmed, 3u);
}

TEST_F(RomImageTest, HexRecordOutsideTheRomIsRefusedAtItsLine) {
    // Line 2 puts a byte at 0800H, the first address past the 8355.
    const std::string nop(1, '\0');
    const std::string why = refusal(write("p.hex", record(0x0000, nop) + record(0x0800, nop) + kEof));
    EXPECT_NE(why.find("p.hex:2:4: error: data at 0800H is outside the ROM (0000H-07FFH)"), std::string::npos) << why;
}

TEST_F(RomImageTest, HexThatIsNotHexIsRefusedAtItsLineAndColumn) {
    const std::string why = refusal(write("notes.hex", "this is not Intel HEX\n"));
    EXPECT_NE(why.find("notes.hex:1:1: error:"), std::string::npos) << why;
}

TEST_F(RomImageTest, HexWithNoDataIsRefused) {
    const std::string why = refusal(write("eof.hex", kEof));
    EXPECT_NE(why.find("eof.hex: no data"), std::string::npos) << why;
}

TEST_F(RomImageTest, SourceIsAssembledIntoTheRom) {
    const RomImage img = read_rom_image(write("p.asm", "\tORG\t0\n\tMVI\tA,1\n\tHLT\n\tEND\n"));
    EXPECT_EQ(img.bytes[0], 0x3E);
    EXPECT_EQ(img.bytes[1], 0x01);
    EXPECT_EQ(img.bytes[2], 0x76);
    EXPECT_EQ(img.bytes[3], 0xFF);
    EXPECT_TRUE(img.assembly.has_value());
}

TEST_F(RomImageTest, SourceCodeOutsideTheRomIsRefusedAtItsLine) {
    const fs::path p = write("p.asm", "\tORG\t0\n\tNOP\n\tORG\t0800H\n\tNOP\n\tEND\n");
    const std::string why = refusal(p);
    EXPECT_NE(why.find(p.string() + ":4:1: error: code at 0800H is outside the ROM (0000H-07FFH)"), std::string::npos)
        << why;
}

TEST_F(RomImageTest, SourceWithErrorsIsRefusedAtLineAndColumn) {
    const fs::path p = write("p.asm", "\tORG\t0\n\tMVI\tQ,1\n\tEND\n");
    const std::string why = refusal(p);
    EXPECT_NE(why.find("1 error(s) in assembly"), std::string::npos) << why;
    EXPECT_NE(why.find(p.string() + ":2:"), std::string::npos) << why;
}

TEST_F(RomImageTest, UnknownTypeIsRefused) {
    const std::string why = refusal(write("monitor.txt", dump()));
    EXPECT_NE(why.find("monitor.txt: unknown ROM image type '.txt'"), std::string::npos) << why;
}

TEST_F(RomImageTest, AnotherRomPlaceAndSize) {
    // A 1 KB ROM at 0800H: a 1024-byte dump fits, a record at 07FFH does not.
    const RomSpec rom{0x0800, 0x0400};
    EXPECT_EQ(refusal(write("k.bin", dump().substr(0, 1024)), rom), "");
    const std::string why = refusal(write("k.hex", record(0x07FF, std::string(1, '\0')) + kEof), rom);
    EXPECT_NE(why.find("k.hex:1:4: error: data at 07FFH is outside the ROM (0800H-0BFFH)"), std::string::npos) << why;
}

}  // namespace
}  // namespace alp85::test
