// Session::boot as DAP's launch uses it (issue 35): a program without the monitor, assembled with
// its defines, the PC at its END address, the bytes it placed reported for the runaway guard, and
// the launch's keys typed after the reset. Addresses from the source below (one byte for DB and
// HLT, two for MVI), RAM from board_map.h (1000H-1FFFH, the 8155's 2000H-20FFH), the press's hold
// and gap from key_press.h (30 ms each, the script's defaults).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "emu/script/session.h"

namespace alp85::test {
namespace {

TEST(SessionBoot, AProgramWithoutTheMonitorStartsAtItsEndAddressAndReportsItsBytes) {
    const auto dir = std::filesystem::temp_directory_path() / "alp85_session_boot_test";
    std::filesystem::create_directories(dir);
    const auto src = dir / "defined.asm";
    std::ofstream(src) << "        ORG 0800H\nDATA:   DB VALUE\nGO:     MVI A,VALUE\n        HLT\n        END GO\n";
    script::Session session{script::SessionOptions{}};
    script::Session::Boot boot;
    boot.monitor = false;
    boot.images.push_back({src, std::nullopt});
    boot.defines = {{"VALUE", "42"}};
    boot.pc_at_program = true;
    script::Session::BootReport report;
    ASSERT_EQ(session.boot(boot, &report).status, script::Session::Status::Ok);
    EXPECT_EQ(session.machine().peek(0x0800), 42);                // DB VALUE, VALUE defined as 42
    EXPECT_EQ(session.machine().cpu().regs().pc, 0x0801);         // END GO: GO follows the one DB byte
    for (unsigned a = 0x0800; a <= 0x0803; ++a) EXPECT_TRUE(report.code[a]) << a;  // DB, MVI A (2), HLT
    EXPECT_FALSE(report.code[0x0804]);
    EXPECT_FALSE(report.code[0x0000]);                            // no monitor
    EXPECT_TRUE(report.code[0x1000]);
    EXPECT_TRUE(report.code[0x1FFF]);
    EXPECT_TRUE(report.code[0x20FF]);
    EXPECT_FALSE(report.code[0x2100]);
    std::filesystem::remove_all(dir);
}

TEST(SessionBoot, TheKeysAreTypedAfterTheBootTime) {
    script::Session session{script::SessionOptions{}};
    script::Session::Boot boot;
    boot.monitor = false;
    std::string why;
    std::size_t at = 0;
    boot.keys = *script::parse_key_list("7 EXEC", why, at);
    boot.boot_time = board::tstates_from_ms(10);
    ASSERT_EQ(session.boot(boot).status, script::Session::Status::Ok);
    const std::uint64_t t0 = session.now();
    Machine& m = session.machine();
    const auto at_ms = [&](int ms) { m.run_until(t0 + board::tstates_from_ms(ms)); };
    at_ms(5);
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::K7));   // still the boot time
    at_ms(25);
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::K7));    // 7 held over 10-40 ms
    at_ms(55);
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::K7));   // the gap, 40-70 ms
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::Exec));
    at_ms(85);
    EXPECT_TRUE(m.keypad().is_pressed(periph::Key::Exec));  // EXEC held over 70-100 ms
    at_ms(105);
    EXPECT_FALSE(m.keypad().is_pressed(periph::Key::Exec));
}

}  // namespace
}  // namespace alp85::test
