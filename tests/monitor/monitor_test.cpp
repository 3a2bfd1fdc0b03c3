// The monitor through its keypad: sign-on, commands, memory, registers, GO, single step,
// breakpoints, VECT INTR. Expected displays follow docs/monitor.md ("Display"); registers and
// addresses come from the test programs (tests/monitor/programs) worked out by hand.
#include "monitor_harness.h"

namespace alp85::test {
namespace {

TEST(MonitorReset, SignOnAndBoardSetUp) {
    Board b;
    ASSERT_TRUE(b.wait_display("-ALP 85-", 10));
    const std::array<std::uint8_t, 8> want{0x40, 0x77, 0x38, 0x73, 0x00, 0x7F, 0x6D, 0x40};
    EXPECT_EQ(b.m.display(), want);
    // 8279: mode 00H (8 digits left entry, encoded scan, 2-key lockout), prescaler 31.
    EXPECT_EQ(b.m.kdc().state().mode, 0x00);
    EXPECT_EQ(b.m.kdc().state().prescaler, 31);
    EXPECT_EQ(b.m.kdc().display_digits(), 8u);
    // 8155: port A drives the motors (output), port B reads the transducers (input).
    EXPECT_EQ(b.m.rio().port_output_mask(periph::I8155::Port::A), 0xFF);
    EXPECT_EQ(b.m.rio().port_output_mask(periph::I8155::Port::B), 0x00);
    // RST 5.5 and 6.5 masked, RST 7.5 open; the monitor runs with interrupts off.
    EXPECT_EQ(b.m.cpu().masks(), 0x03);
    EXPECT_FALSE(b.m.cpu().interrupts_enabled());
}

TEST(MonitorReset, UserRegistersStartAtTheDocumentedValues) {
    Board b;
    b.run_ms(5);
    const auto r = b.saved();
    EXPECT_EQ(r.sp, 0x20B0);  // the thesis's stack top
    EXPECT_EQ(r.pc, 0x0800);  // the user EPROM
    EXPECT_EQ(r.im, 0x0B);    // IE on, RST 7.5 open: VECT INTR can break in
    EXPECT_EQ(r.a, 0);
    EXPECT_EQ(r.hl, 0);
}

TEST(MonitorCommands, InvalidCommandsShowErrAndTheNextKeyIsACommandAgain) {
    Board b;
    ASSERT_TRUE(b.wait_display("-ALP 85-", 10));
    b.press(Key::Exec);
    EXPECT_EQ(b.display(), "Err     ");
    b.press(Key::R);
    EXPECT_EQ(b.display(), "r       ");
    b.press(Key::K3);  // no command 3
    EXPECT_EQ(b.display(), "Err     ");
    for (Key k : {Key::K0, Key::K4, Key::K6, Key::KA, Key::KF, Key::Next}) {
        b.type({Key::R, k});
        EXPECT_EQ(b.display(), "Err     ") << "R " << periph::Keypad::info(k).name;
    }
    // At the prompt only R, MEM, REG, GO and STEP are commands; after Err the next key is one.
    for (Key k : {Key::Next, Key::Prev, Key::Exec, Key::K0, Key::K7, Key::KF}) {
        b.press(k);
        EXPECT_EQ(b.display(), "Err     ") << periph::Keypad::info(k).name;
    }
    b.m.poke(0x0800, 0x3E);
    b.press(Key::Mem);  // still a working monitor
    EXPECT_EQ(b.display(), "0800.  3E");
}

TEST(MonitorMemory, ExamineModifyNextPrev) {
    Board b;
    b.m.poke(0x1000, 0x5A);
    b.m.poke(0x1001, 0xC3);
    b.m.poke(0x0800, 0x31);
    b.run_ms(5);
    b.press(Key::Mem);
    EXPECT_EQ(b.display(), "0800.  31");  // MEM starts at the user EPROM
    b.type({Key::K1, Key::K0, Key::K0, Key::K0});
    EXPECT_EQ(b.display(), "1000.  5A");
    b.press(Key::Next);
    EXPECT_EQ(b.display(), "1000  5A.");
    b.type({Key::K3, Key::KC});
    EXPECT_EQ(b.display(), "1000  3C.");
    EXPECT_EQ(b.byte(0x1000), 0x5A);  // stored only when the field is left
    b.press(Key::Next);
    EXPECT_EQ(b.byte(0x1000), 0x3C);
    EXPECT_EQ(b.display(), "1001  C3.");
    b.type({Key::K1, Key::K2, Key::K3});  // the last two digits count
    EXPECT_EQ(b.display(), "1001  23.");
    b.press(Key::Prev);
    EXPECT_EQ(b.byte(0x1001), 0x23);
    EXPECT_EQ(b.display(), "1000  3C.");
    b.press(Key::Exec);
    EXPECT_EQ(b.display(), "-       ");
    // MEM remembers its address; R 1 is the same command.
    b.type({Key::R, Key::K1});
    EXPECT_EQ(b.display(), "1000.  3C");
}

TEST(MonitorMemory, AByteThatDoesNotStickIsAnError) {
    Board b;
    b.m.poke(0x0800, 0x31);  // programmed into the user EPROM
    b.run_ms(5);
    b.type({Key::Mem, Key::Next});
    EXPECT_EQ(b.display(), "0800  31.");
    b.type({Key::K1, Key::K2, Key::Next});
    EXPECT_EQ(b.display(), "Err     ");
    EXPECT_EQ(b.byte(0x0800), 0x31);
    // Nothing at 3000H: reads FFH, keeps nothing.
    b.type({Key::Mem, Key::K3, Key::K0, Key::K0, Key::K0, Key::Next});
    EXPECT_EQ(b.display(), "3000  FF.");
    b.type({Key::K0, Key::Exec});
    EXPECT_EQ(b.display(), "Err     ");
}

// hello.asm: GO, the program writes HELL0, a key makes it return with RST 1.
class MonitorGo : public ::testing::Test {
protected:
    void SetUp() override {
        b_.load("hello.asm");
        ASSERT_TRUE(b_.wait_display("-ALP 85-", 10));
        // Appendix C: R, command 7, the start address, the terminal key.
        b_.type({Key::R, Key::K7});
        EXPECT_EQ(b_.display(), "0800.  Go");  // the saved PC
        b_.type({Key::K0, Key::K8, Key::K0, Key::K0, Key::Exec});
        ASSERT_TRUE(b_.wait_display("HELL0   ", 100));
        b_.press(Key::K5);
        ASSERT_TRUE(b_.wait_display(hex(kAgain, 4) + "  32", 100));  // where it stopped: STA
    }
    // hello.asm: HELLO 0800H, 3+2+2+3+2+3+2+3+3+2+3 = 28 bytes to WAIT (081CH), 3+3 to
    // LXI H (0822H), LXI H, PUSH, POP, LXI B, LXI D, LXI H = 0822H+3+1+1+3+3+3 = 0830H: RST 1,
    // AGAIN 0831H (STA 1000H, 3 bytes), RST 1 at 0834H.
    static constexpr std::uint16_t kAgain = 0x0831;
    Board b_;
};

TEST_F(MonitorGo, ProgramReturnsWithRst1AndItsRegistersSaved) {
    const auto r = b_.saved();
    EXPECT_EQ(r.a, 0xEF);
    EXPECT_EQ(r.f, 0xD5);
    EXPECT_EQ(r.b, 0x12);
    EXPECT_EQ(r.c, 0x34);
    EXPECT_EQ(r.d, 0x56);
    EXPECT_EQ(r.e, 0x78);
    EXPECT_EQ(r.hl, 0x9ABC);
    EXPECT_EQ(r.sp, 0x20B0);  // GO's stack; the RST's push was taken back
    EXPECT_EQ(r.pc, kAgain);
    EXPECT_EQ(r.im, 0x0B);
    EXPECT_FALSE(b_.m.cpu().interrupts_enabled());
}

TEST_F(MonitorGo, GoExecContinuesFromTheSavedPc) {
    b_.press(Key::Go);
    EXPECT_EQ(b_.display(), hex(kAgain, 4) + ".  Go");
    b_.press(Key::Exec);
    ASSERT_TRUE(b_.wait_display(hex(kAgain + 4, 4) + "  76", 100));  // after STA and RST 1: HLT
    EXPECT_EQ(b_.byte(0x1000), 0xEF);
    EXPECT_EQ(b_.saved().pc, kAgain + 4);
}

TEST_F(MonitorGo, RegistersExaminedInOrderAndWrapping) {
    b_.press(Key::Reg);
    EXPECT_EQ(b_.display(), "A     EF.");
    const char* want[] = {"b     12.", "C     34.", "d     56.", "E     78.", "F     d5.", "I     0b.",
                          "H     9A.", "L     bC.", "5P  20b0."};
    for (const char* w : want) {
        b_.press(Key::Next);
        EXPECT_EQ(b_.display(), w);
    }
    b_.press(Key::Next);
    EXPECT_EQ(b_.display(), "PC  " + hex(kAgain, 4) + ".");
    b_.press(Key::Next);
    EXPECT_EQ(b_.display(), "A     EF.");
    b_.press(Key::Prev);
    EXPECT_EQ(b_.display(), "PC  " + hex(kAgain, 4) + ".");
    b_.press(Key::Exec);
    EXPECT_EQ(b_.display(), "-       ");
    b_.type({Key::R, Key::K2});
    EXPECT_EQ(b_.display(), "A     EF.");
}

TEST_F(MonitorGo, ModifiedRegistersAreWhatTheProgramGets) {
    b_.press(Key::Reg);
    b_.type({Key::K5, Key::K5});
    EXPECT_EQ(b_.display(), "A     55.");
    b_.press(Key::Exec);
    EXPECT_EQ(b_.saved().a, 0x55);
    // SP: the ninth register; four digits.
    b_.press(Key::Reg);
    b_.press(Key::Prev);
    b_.press(Key::Prev);
    EXPECT_EQ(b_.display(), "5P  20b0.");
    b_.type({Key::K1, Key::K8, Key::K0, Key::K0, Key::Exec});
    EXPECT_EQ(b_.word(kSaveSP), 0x1800);
    b_.type({Key::Go, Key::Exec});
    ASSERT_TRUE(b_.wait_display(hex(kAgain + 4, 4) + "  76", 100));
    EXPECT_EQ(b_.byte(0x1000), 0x55);
    EXPECT_EQ(b_.saved().sp, 0x1800);
    // The two bytes below the user's SP are the only ones the monitor's entry uses on the user's
    // stack: RST 1 put its return address there, the entry's PUSH PSW then A and the flags.
    EXPECT_EQ(b_.word(0x17FE), 0x55D5);
}

}  // namespace
}  // namespace alp85::test
