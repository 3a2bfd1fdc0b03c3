// The monitor's debugging commands: single step (8155 timer -> TRAP), breakpoints (RST 1),
// VECT INTR (RST 7.5) and RESET during a run. Programs: tests/monitor/programs/step.asm and
// count.asm, in RAM; their addresses and T-states are in their comments.
#include <algorithm>
#include <iterator>

#include "monitor_harness.h"

namespace alp85::test {
namespace {

class MonitorStep : public ::testing::Test {
protected:
    void SetUp() override {
        b_.load("step.asm");
        ASSERT_TRUE(b_.wait_display("-ALP 85-", 10));
        b_.press(Key::Step);
        EXPECT_EQ(b_.display(), "0800.  FF");  // the saved PC and its byte (erased user EPROM)
        b_.type_hex(0x1000);
        EXPECT_EQ(b_.display(), "1000.  3E");
    }
    Board b_;
};

TEST_F(MonitorStep, EachNextRunsExactlyOneInstruction) {
    struct Want {
        const char* display;
        std::uint16_t pc, sp;
        std::uint8_t a;
    };
    const Want want[] = {
        {"1002.  3C", 0x1002, 0x20B0, 0x01},  // MVI A,01H
        {"1003.  00", 0x1003, 0x20B0, 0x02},  // INR A (4 T-states)
        {"1004.  Cd", 0x1004, 0x20B0, 0x02},  // NOP (4)
        {"1008.  C5", 0x1008, 0x20AE, 0x02},  // CALL SUB (18)
        {"1009.  C1", 0x1009, 0x20AC, 0x02},  // PUSH B (12)
        {"100A.  C9", 0x100A, 0x20AE, 0x02},  // POP B (10)
        {"1007.  76", 0x1007, 0x20B0, 0x02},  // RET (10)
        {"1008.  C5", 0x1008, 0x20B0, 0x02},  // HLT: TRAP ends the halt, PC after the HLT
    };
    for (const Want& w : want) {
        b_.press(Key::Next);
        EXPECT_EQ(b_.display(), w.display);
        const auto r = b_.saved();
        EXPECT_EQ(r.pc, w.pc) << w.display;
        EXPECT_EQ(r.sp, w.sp) << w.display;
        EXPECT_EQ(r.a, w.a) << w.display;
        if (r.sp == 0x20AE) {
            EXPECT_EQ(b_.word(0x20AE), 0x1007);  // CALL's return address
        }
    }
    b_.press(Key::Exec);
    EXPECT_EQ(b_.display(), "-       ");
    // R 5 is STEP; it starts where the last step ended.
    b_.type({Key::R, Key::K5});
    EXPECT_EQ(b_.display(), "1008.  C5");
}

TEST_F(MonitorStep, TrapIsTakenAsTheSteppedInstructionEnds) {
    b_.type({Key::Next, Key::Next});  // to the NOP at 1003H
    ASSERT_EQ(b_.display(), "1003.  00");
    const std::uint64_t t = b_.m.now();
    b_.m.key_at(Key::Next, true, t);
    b_.m.key_at(Key::Next, false, t + ms(30));
    ASSERT_EQ(b_.m.run_to(0x1003, t + ms(60)), Machine::RunEnd::Target);
    ASSERT_EQ(b_.m.cpu().regs().pc, 0x1003);
    const std::uint64_t start = b_.m.now();
    ASSERT_EQ(b_.m.run_to(0x0024, t + ms(60)), Machine::RunEnd::Target);
    ASSERT_EQ(b_.m.cpu().regs().pc, 0x0024);
    // NOP: 4 T-states; the TRAP acknowledge: 12 (8085 data sheet). Nothing in between.
    EXPECT_EQ(b_.m.now() - start, 4u + 12u);
    b_.m.run_until(t + ms(60));
    EXPECT_EQ(b_.display(), "1004.  Cd");
}

TEST_F(MonitorStep, TimerCountMatchesTheRestoreSequence) {
    // docs/monitor.md: the OUT that starts the timer (MVI A,0C1H / OUT 0F8H) is followed by
    // LXI SP, POP B, POP D, POP PSW, LHLD, SPHL, LHLD, JMP, EI (or NOP), JMP: with OUT's own 10 T-states,
    // 10+10+10+10+10+16+6+16+10+4+10 = 112 T-states from OUT to the program's first instruction.
    const std::uint8_t pattern[] = {0x3E, 0xC1, 0xD3, 0xF8};
    const std::uint8_t* rom = firmware::kMonitorRom;
    const std::uint8_t* end = rom + firmware::kMonitorRom_size;
    const std::uint8_t* at = std::search(rom, end, std::begin(pattern), std::end(pattern));
    ASSERT_NE(at, end);
    const auto out_pc = static_cast<std::uint16_t>(at - rom + 2);
    const std::uint64_t t = b_.m.now();
    b_.m.key_at(Key::Next, true, t);
    b_.m.key_at(Key::Next, false, t + ms(30));
    ASSERT_EQ(b_.m.run_to(out_pc, t + ms(60)), Machine::RunEnd::Target);
    ASSERT_EQ(b_.m.cpu().regs().pc, out_pc);
    const std::uint64_t out_t = b_.m.now();
    ASSERT_EQ(b_.m.run_to(0x1000, t + ms(60)), Machine::RunEnd::Target);
    ASSERT_EQ(b_.m.cpu().regs().pc, 0x1000);
    EXPECT_EQ(b_.m.now() - out_t, 112u);
    // The count: 112 - 7 (OUT's I/O write cycle starts 7 T-states in), single pulse mode (10).
    EXPECT_EQ(b_.m.rio().state().count_length, 0x8000 | 105);
    b_.m.run_until(t + ms(60));
    EXPECT_EQ(b_.display(), "1002.  3C");
}

TEST_F(MonitorStep, ExecTakesTheTypedAddressWithoutRunning) {
    b_.press(Key::Exec);
    EXPECT_EQ(b_.display(), "-       ");
    EXPECT_EQ(b_.saved().pc, 0x1000);
    EXPECT_EQ(b_.saved().a, 0x00);
}

class MonitorBreakpoints : public ::testing::Test {
protected:
    void SetUp() override {
        b_.load("count.asm");
        ASSERT_TRUE(b_.wait_display("-ALP 85-", 10));
    }
    void set_breakpoint(std::uint16_t a) {
        b_.type({Key::R, Key::K8});
        b_.type_hex(a);
        EXPECT_EQ(b_.display(), hex(a, 4) + ".  --");
        b_.press(Key::Next);
        EXPECT_EQ(b_.display(), hex(a, 4) + ".  bP");
        b_.press(Key::Exec);
    }
    static constexpr std::uint16_t kCount = 0x1100;
    Board b_;
};

TEST_F(MonitorBreakpoints, StopAtTheAddressWithTheProgramsBytesBack) {
    set_breakpoint(0x1009);  // INX H
    EXPECT_EQ(b_.byte(0x1009), 0x23);  // nothing written until GO
    b_.go(0x1000);
    ASSERT_TRUE(b_.wait_display("1009  23", 100));
    auto r = b_.saved();
    EXPECT_EQ(r.pc, 0x1009);
    EXPECT_EQ(r.hl, 0x0000);  // LHLD COUNT, before INX
    EXPECT_EQ(b_.byte(0x1009), 0x23);
    EXPECT_EQ(r.sp, 0x20B0);
    // GO again from the breakpoint: its instruction runs first, then the loop comes round.
    b_.type({Key::Go, Key::Exec});
    ASSERT_TRUE(b_.wait_display("1009  23", 100));
    r = b_.saved();
    EXPECT_EQ(r.hl, 0x0001);
    EXPECT_EQ(b_.word(kCount), 0x0001);
    EXPECT_EQ(b_.byte(0x1009), 0x23);
}

TEST_F(MonitorBreakpoints, ClearedOneNoLongerStopsAndVectBreaksIn) {
    set_breakpoint(0x1009);
    b_.type({Key::R, Key::K8});
    EXPECT_EQ(b_.display(), "1009.  bP");  // R 8 remembers its address
    b_.press(Key::Next);
    EXPECT_EQ(b_.display(), "1009.  --");
    b_.press(Key::Exec);
    b_.go(0x1000);
    b_.run_ms(50);
    EXPECT_EQ(b_.display(), "        ");  // GO blanked it; the program never stops
    EXPECT_GT(b_.word(kCount), 100);
    b_.vect();
    const auto r = b_.saved();
    EXPECT_GE(r.pc, 0x1006);
    EXPECT_LE(r.pc, 0x100D);
    EXPECT_EQ(r.im, 0x0B);  // IE was on (RST 7.5 was taken), masks as GO set them
    EXPECT_EQ(b_.display(), hex(r.pc, 4) + "  " + hex(b_.byte(r.pc), 2));
    // And it continues from there.
    const std::uint16_t count = b_.word(kCount);
    b_.type({Key::Go, Key::Exec});
    b_.run_ms(20);
    EXPECT_GT(b_.word(kCount), count);
}

TEST_F(MonitorBreakpoints, OnlyInRamAtMostFourAndR9ClearsThemAll) {
    b_.type({Key::R, Key::K8});
    b_.type_hex(0x0800);  // user EPROM: RST 1 cannot be written there
    b_.press(Key::Next);
    EXPECT_EQ(b_.display(), "Err     ");
    for (std::uint16_t a : {0x1000, 0x1003, 0x1006, 0x1009}) set_breakpoint(a);
    b_.type({Key::R, Key::K8});
    b_.type_hex(0x100A);
    b_.press(Key::Next);
    EXPECT_EQ(b_.display(), "Err     ");  // a fifth
    b_.type({Key::R, Key::K9});
    EXPECT_EQ(b_.display(), "-       ");
    b_.type({Key::R, Key::K8});
    b_.type_hex(0x1006);
    EXPECT_EQ(b_.display(), "1006.  --");
}

TEST_F(MonitorBreakpoints, ResetDuringARunGivesTheProgramItsBytesBack) {
    set_breakpoint(0x1000);  // run once only: the program loops below it
    b_.go(0x1000);           // starts on the breakpoint: stepped over, then inserted
    b_.run_ms(20);
    EXPECT_EQ(b_.byte(0x1000), 0xCF);  // RST 1 in place while the program runs
    EXPECT_GT(b_.word(kCount), 0);
    b_.m.reset_key_at(true, b_.m.now());
    b_.m.reset_key_at(false, b_.m.now() + ms(10));
    ASSERT_TRUE(b_.wait_display("-ALP 85-", 100));
    EXPECT_EQ(b_.byte(0x1000), 0x21);  // LXI H again
    b_.type({Key::R, Key::K8});
    EXPECT_EQ(b_.display(), "0800.  --");  // RESET also forgot the breakpoints
}

TEST(MonitorTrap, AProgramsOwnTimerTrapsOnceIntoTheMonitorWhichStopsIt) {
    Board b;
    b.load("timer.asm");
    b.run_ms(5);
    b.go(0x1000);
    // Stopped in its loop (JMP LOOP); the monitor takes every TRAP for a single step.
    ASSERT_TRUE(b.wait_display("100C.  C3", 100));
    EXPECT_FALSE(b.m.rio().state().running);
    b.run_ms(50);
    EXPECT_EQ(b.display(), "100C.  C3");
    b.press(Key::Mem);  // and the monitor works on
    EXPECT_EQ(b.display(), "0800.  FF");  // erased user EPROM
}

TEST(MonitorRst55, TheRamVectorEntersTheMonitorUntilTheProgramReplacesIt) {
    Board b;
    b.load("rst55.asm");
    b.run_ms(5);
    b.go(0x1000);
    b.run_ms(10);
    // A key raises the 8279's IRQ: RST 5.5 -> 20DEH -> the monitor, which then reads that key
    // (MEM) from the FIFO as its next command.
    b.press(Key::Mem);
    EXPECT_EQ(b.display(), "0800.  FF");  // erased user EPROM
    const auto r = b.saved();
    EXPECT_EQ(r.pc, 0x1004);
    EXPECT_EQ(r.im, 0x0E);  // IE was on; masks 110
    // The program's own routine in the vector: the key goes to it and the program runs on.
    b.press(Key::Exec);
    b.go(0x1007);
    b.run_ms(10);
    b.press(Key::K7);
    EXPECT_EQ(b.byte(0x1100), 0x07);
    EXPECT_FALSE(b.m.cpu().halted());
    EXPECT_EQ(b.display(), "        ");  // still the program's (blank) display
}

TEST(MonitorRst, AnyRestartOrARunIntoEmptyMemoryReturnsToTheMonitor) {
    Board b;
    // 1000H: MVI A,77H / RST 3; 1010H: JMP 3000H (nothing there: FFH = RST 7).
    const std::uint8_t prog[] = {0x3E, 0x77, 0xDF};
    b.m.load(0x1000, prog);
    const std::uint8_t jmp[] = {0xC3, 0x00, 0x30};
    b.m.load(0x1010, jmp);
    b.run_ms(5);
    b.go(0x1000);
    ASSERT_TRUE(b.wait_display("1003  00", 100));
    EXPECT_EQ(b.saved().a, 0x77);
    b.go(0x1010);
    ASSERT_TRUE(b.wait_display("3001  FF", 100));
    EXPECT_EQ(b.saved().pc, 0x3001);
}

}  // namespace
}  // namespace alp85::test
