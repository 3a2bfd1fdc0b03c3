// The five entry points the thesis firmware calls (AUS 05A8H, UMW 05C9H, ANWEIN 0701H,
// ANWAZL 07BCH, ANWAUS 07C7H), each checked against its contract in docs/monitor.md by
// tests/monitor/programs/entries.asm: a section loads known registers, calls, and halts; VECT INTR
// then brings the monitor in, which saves the registers where docs/monitor.md says.
// Segment codes: bit0 = a ... bit6 = g (docs/board.md): 0 = 3FH (a-f), 1 = 06H (b c), ...
#include <algorithm>
#include <stdexcept>

#include "monitor_harness.h"

namespace alp85::test {
namespace {

constexpr std::uint8_t kS = 0x80, kZ = 0x40, kAC = 0x10, kP = 0x04, kCY = 0x01;

std::uint16_t symbol(const LoadedImage& img, const std::string& name) {
    auto it = std::find_if(img.symbols.begin(), img.symbols.end(), [&](const auto& s) { return s.name == name; });
    if (it == img.symbols.end()) throw std::runtime_error("no symbol " + name);
    return it->value;
}

// A board at the sign-on with entries.asm in the user EPROM.
class EntryPoints : public ::testing::Test {
protected:
    void SetUp() override {
        img_ = b_.load("entries.asm");
        ASSERT_TRUE(b_.wait_display("-ALP 85-", 100));
    }
    // GO to a section; it halts after its call.
    void run_section(const std::string& label) {
        b_.go(symbol(img_, label));
        ASSERT_TRUE(b_.wait_halt());
    }
    // VECT INTR: the monitor saves the registers (the halted program's state).
    Board::Saved enter_monitor() {
        b_.vect();
        return b_.saved();
    }
    void continue_program() {
        b_.type({Key::Go, Key::Exec});
        ASSERT_TRUE(b_.wait_halt());
    }
    void expect_kept_bc_de_hl(const Board::Saved& r, std::uint8_t b, std::uint8_t c) {
        EXPECT_EQ(r.b, b);
        EXPECT_EQ(r.c, c);
        EXPECT_EQ(r.d, 0x56);
        EXPECT_EQ(r.e, 0x78);
        EXPECT_EQ(r.hl, 0x9ABC);
        EXPECT_EQ(r.sp, 0x20B0);  // every call returned
    }

    Board b_;
    LoadedImage img_;
};

TEST_F(EntryPoints, AnwazlBlanksEveryDigitAndKeepsAllRegistersAndFlags) {
    run_section("S1");
    EXPECT_EQ(b_.display(), "        ");
    for (auto d : b_.m.display()) EXPECT_EQ(d, 0x00);
    const auto r = enter_monitor();
    EXPECT_EQ(r.a, 0xA5);
    EXPECT_EQ(r.f, 0xD5);
    expect_kept_bc_de_hl(r, 0x12, 0x34);
}

TEST_F(EntryPoints, AusWritesTheDigitOfMaskBThenMovesRightEvenJustAfterA0D1HClear) {
    run_section("S2");
    // 0D1H cleared the display to 00H; AUS waited for the clear to end and wrote digit 0.
    const auto d = b_.m.display();
    EXPECT_EQ(d[0], 0x76);
    for (int i = 1; i < 8; ++i) EXPECT_EQ(d[i], 0x00);
    EXPECT_EQ(b_.display(), "H       ");
    const auto r = enter_monitor();
    EXPECT_EQ(r.a, 0x76);  // kept
    EXPECT_EQ(r.f, 0x95);  // kept
    expect_kept_bc_de_hl(r, 0x40, 0x34);  // B: 80H rotated right = digit 1
}

TEST_F(EntryPoints, AusAsTheThesisBittiUsesIt) {
    run_section("S3");
    // B = 20H is digit 2; five calls fill digits 2-6 with B (shown as 8), i, t, t, i.
    const std::array<std::uint8_t, 8> want{0x00, 0x00, 0x7F, 0x04, 0x78, 0x78, 0x04, 0x00};
    EXPECT_EQ(b_.m.display(), want);
    EXPECT_EQ(b_.display(), "  8itti ");
    EXPECT_EQ(enter_monitor().b, 0x01);  // 20H rotated right five times
}

TEST_F(EntryPoints, AusWrapsFromTheLastDigitToTheFirstAndIgnoresAnEmptyMask) {
    run_section("S4");
    // GO blanked the display; 01H = digit 7 gets 2, then 80H = digit 0 gets 4; B = 0 wrote nothing.
    EXPECT_EQ(b_.display(), "4      2");
    EXPECT_EQ(enter_monitor().b, 0x00);
}

TEST_F(EntryPoints, UmwGivesTheSegmentCodeOfTheLowNibble) {
    run_section("S5");
    // a-f for 0; b c for 1; a b d e g for 2; ... (bit0 = a ... bit6 = g).
    const std::uint8_t want[16] = {0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07,
                                   0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(b_.byte(static_cast<std::uint16_t>(0x1100 + i)), want[i]) << "digit " << i;
    const auto r = enter_monitor();
    EXPECT_EQ(r.a, 0x6D);  // A5H: the 5, bits 7-4 ignored
    expect_kept_bc_de_hl(r, 0x12, 0x34);
}

TEST_F(EntryPoints, AnwausShowsAHexDigitAtMaskBAndKeepsAAndFlags) {
    run_section("S6");
    EXPECT_EQ(b_.display(), "      C ");
    auto r = enter_monitor();
    EXPECT_EQ(r.a, 0x0C);
    EXPECT_EQ(r.f, 0xD5);
    expect_kept_bc_de_hl(r, 0x01, 0x34);  // digit 6 -> 7
    continue_program();  // S7: A = 3FH, B still 01H (GO blanked the display again)
    EXPECT_EQ(b_.display(), "       F");
    r = enter_monitor();
    EXPECT_EQ(r.a, 0x3F);
    EXPECT_EQ(r.f, 0x95);
    EXPECT_EQ(r.b, 0x80);  // wrapped to digit 0
}

TEST_F(EntryPoints, AnweinReturnsAtOnceWithZWhenNoKeyIsWaiting) {
    run_section("S8");
    const auto r = enter_monitor();
    EXPECT_EQ(r.a, 0x00);
    EXPECT_EQ(r.f & kZ, kZ);
    expect_kept_bc_de_hl(r, 0x12, 0x34);
}

TEST_F(EntryPoints, AnweinReturnsTheKeyCodeWithZClearEvenForKey0) {
    b_.go(symbol(img_, "S9"));
    b_.run_ms(100);
    EXPECT_FALSE(b_.m.cpu().halted());  // BASLA-style loop: no key yet
    b_.press(Key::K0);
    ASSERT_TRUE(b_.wait_halt());
    auto r = enter_monitor();
    EXPECT_EQ(r.a, 0x00);
    EXPECT_EQ(r.f & (kZ | kCY), kCY);  // NZ although A = 0; CY set
    expect_kept_bc_de_hl(r, 0x12, 0x34);

    b_.type({Key::Go, Key::Exec});  // S10: the terminal key
    b_.run_ms(100);
    EXPECT_FALSE(b_.m.cpu().halted());
    b_.press(Key::Exec);
    ASSERT_TRUE(b_.wait_halt());
    r = enter_monitor();
    EXPECT_EQ(r.a, 0x10);
    EXPECT_EQ(r.f & kZ, 0);
    EXPECT_NE(r.a & 0x0F, 0x0F);  // after the thesis's ANI 0FH it is not F ("re-enter")
}

TEST(EntryPointAddresses, EachHoldsCodeAtItsFixedAddress) {
    Board b;
    // The first byte of each routine as docs/monitor.md lists it (PUSH H, PUSH H, IN, JMP, PUSH PSW).
    EXPECT_EQ(b.byte(kAus), 0xE5);
    EXPECT_EQ(b.byte(kUmw), 0xE5);
    EXPECT_EQ(b.byte(kAnwein), 0xDB);
    EXPECT_EQ(b.byte(static_cast<std::uint16_t>(kAnwein + 1)), 0xE1);  // IN E1H: the 8279 status
    EXPECT_EQ(b.byte(kAnwazl), 0xC3);
    EXPECT_EQ(b.byte(kAnwaus), 0xF5);
}

}  // namespace
}  // namespace alp85::test
