// The debugger's command line on the thesis firmware (thesis-fixed, the worked line of
// docs/thesis.md): reverse execution back to exactly the earlier state (the whole machine's
// snapshot compared byte for byte: registers, memory, chips, machine tool, cycle count), looking
// without changing any device, and errors with their columns.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <string>
#include <thread>

#include "emu/program/firmware.h"
#include "emu/script/debug_shell.h"

namespace alp85::test {
namespace {

class Thesis : public ::testing::Test {
protected:
    static constexpr std::uint64_t kInterval = 30'720;
    script::DebugShell shell{[] {
        script::SessionOptions o;
        o.monitor_rom = firmware::monitor;
        return o;
    }()};

    Machine& m() { return shell.session().machine(); }
    std::vector<std::uint8_t> snap() { return m().snapshot_bytes(); }

    // Runs a line that must not fail; returns its text.
    std::string run(const std::string& line) {
        const int before = shell.console().errors();
        std::string out = shell.execute(line);
        EXPECT_EQ(shell.console().errors(), before) << line << "\n" << out;
        return out;
    }

    void SetUp() override {
        if (!firmware::have_monitor() || !firmware::find("thesis-fixed")) GTEST_SKIP() << "built without the firmware";
        for (const char* line : {"monitor", "firmware thesis-fixed", "reset"}) run(line);
        // Snapshots every 10 ms of machine time: a few steps of the line apart, so that going back
        // crosses several of them.
        shell.debugger().set_history(true, kInterval);
        // (0100, 0050) -> (0300, 0200), Z = 0, 750 mm/min
        for (const char* line : {"type R 7 0 8 0 0 EXEC", "wait display \"?.=----\" timeout 200ms", "type 0 0 0 0",
                                 "wait display \"H1=----\" timeout 1s", "type 0 1 0 0 EXEC", "wait display \"y1=----\" timeout 200ms",
                                 "type 0 0 5 0 EXEC", "wait display \"H2=----\" timeout 200ms", "type 0 3 0 0 EXEC",
                                 "wait display \"y2=----\" timeout 200ms", "type 0 2 0 0 EXEC", "wait display \"H=----\" timeout 200ms",
                                 "type 0 7 5 0"})
            run(line);
    }
    std::uint16_t symbol(const char* name) { return *shell.debugger().program().value_of(name); }
};

TEST_F(Thesis, ReverseStepReturnsToExactlyTheEarlierState) {
    run("break OUT");
    run("press EXEC");
    ASSERT_EQ(m().cpu().regs().pc, symbol("OUT"));
    const auto a = snap();
    run("stepi");
    const auto b = snap();
    run("stepi");
    const auto c = snap();
    EXPECT_NE(a, b);
    EXPECT_NE(b, c);
    run("reverse-step");
    EXPECT_EQ(snap(), b);
    run("rs");
    EXPECT_EQ(snap(), a);
    EXPECT_EQ(m().cpu().regs().pc, symbol("OUT"));
    // forward again: the same run
    run("si");
    run("si");
    EXPECT_EQ(snap(), c);
}

TEST_F(Thesis, ReverseContinueReturnsToThePreviousHitExactly) {
    run("break OUT");
    run("press EXEC");
    const auto first = snap();
    const std::uint64_t t1 = m().now();
    run("continue");
    const auto second = snap();
    const std::uint64_t t2 = m().now();
    for (int i = 0; i < 5; ++i) run("continue");
    const std::uint64_t t7 = m().now();
    // a step of the line is 6140*D + about 12 500 T-states (docs/thesis.md): several snapshots apart
    EXPECT_GT(t2 - t1, 20'000u);
    EXPECT_GT(t7 - t2, 3 * kInterval);
    run("reverse-continue");
    for (int i = 0; i < 4; ++i) run("rc");
    EXPECT_EQ(m().now(), t2);
    EXPECT_EQ(snap(), second);
    run("rc");
    EXPECT_EQ(snap(), first);
    // nothing before the first hit since the history began: back to its start, said so
    const std::string out = shell.execute("rc");
    EXPECT_NE(out.find("no more reverse-execution history"), std::string::npos) << out;
    EXPECT_EQ(m().now(), shell.debugger().history_start());
}

// Going back and pressing a key makes a new future: a later reverse-step lands in that future, not
// in the first one (whose snapshots no longer hold).
TEST_F(Thesis, AKeyPressedInThePastMakesANewFuture) {
    run("break OUT");
    run("press EXEC");
    run("delete");
    run("run 50ms");
    run("reverse-continue");  // no breakpoints: back to the start of history
    run("break OUT");
    run("continue");
    const std::uint64_t t_out = m().now();
    run("delete");
    run("press 5");  // during the motion: the key waits in the FIFO
    run("run 50ms");
    ASSERT_EQ(m().kdc().state().fifo_count, 1);
    run("stepi");
    const auto after = snap();
    run("reverse-stepi");
    run("stepi");
    EXPECT_EQ(snap(), after);
    EXPECT_EQ(m().kdc().state().fifo_count, 1);  // the key is in this future's past
    EXPECT_GT(m().now(), t_out);
}

TEST_F(Thesis, ReverseFinishAndReverseNextGoBackOverWholeCalls) {
    run("break DELAY");
    run("press EXEC");
    ASSERT_EQ(m().cpu().regs().pc, symbol("DELAY"));
    run("stepi 3");  // LDA 1B38H; ANA A; MOV C,A: at CALL DL
    ASSERT_EQ(m().cpu().regs().pc, symbol("DELAY") + 5);
    const auto at_call = snap();
    run("stepi 4");  // CALL DL; MVI B,0DAH; DCR B; JNZ IDI: inside DL
    ASSERT_EQ(m().cpu().regs().pc, symbol("IDI"));
    run("reverse-finish");
    EXPECT_EQ(snap(), at_call);
    run("next");  // DL run whole: 3070*2 - 3 T-states, and the CALL's 18
    EXPECT_EQ(m().cpu().regs().pc, symbol("DELAY") + 8);
    run("reverse-next");
    EXPECT_EQ(snap(), at_call);
}

// LOOP+6 (JZ SOBE) is the main loop's own code: the firmware set SP (LXI SP) and calls from
// here, so no return address is on the stack. reverse-finish there has no caller to go back to,
// as finish has none to run to: it says so at once and changes nothing, however long the history
// behind it (20 s of machine time waiting at the prompt: 2000 snapshots at 10 ms).
TEST_F(Thesis, ReverseFinishInTheOutermostRoutineAnswersAtOnce) {
    run("run 20s");
    run("break LOOP+6");
    run("press EXEC");
    ASSERT_EQ(m().cpu().regs().pc, symbol("LOOP") + 6);
    const auto before = snap();
    const auto started = std::chrono::steady_clock::now();
    const std::string out = shell.execute("reverse-finish");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_LT(seconds, 1.0);
    EXPECT_NE(out.find("not meaningful in the outermost routine"), std::string::npos) << out;
    EXPECT_EQ(snap(), before);
    const std::string fin = shell.execute("finish");
    EXPECT_NE(fin.find("not meaningful in the outermost routine"), std::string::npos) << fin;
    EXPECT_EQ(snap(), before);
}

// A reverse command that goes far back re-executes the history once, a span at a time: an
// interrupt (Ctrl-C, the window's Pause, DAP's pause) ends it between two spans of at most
// 65 536 T-states (21 ms of machine time, well under a millisecond of host time).
TEST_F(Thesis, AnInterruptEndsALongReverseRunPromptly) {
    // The history: re-executing it must outlast the 50 ms before the interrupt (tests/CMakeLists.txt:
    // ALP85_LONG_HISTORY_S; this test takes three fifths of it, as before).
    run("run " + std::to_string(ALP85_LONG_HISTORY_S * 3 / 5) + "s");
    run("break SOBE");  // never reached while the firmware waits for EXEC: back to the start
    std::atomic<bool> started{false};
    std::chrono::steady_clock::time_point asked;
    std::thread ctrl_c([&] {
        while (!started.load()) std::this_thread::yield();
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        asked = std::chrono::steady_clock::now();
        shell.debugger().interrupt();
    });
    started.store(true);
    const debug::Stop s = shell.debugger().reverse_continue();
    const auto ended = std::chrono::steady_clock::now();
    ctrl_c.join();
    ASSERT_EQ(s.reason, debug::StopReason::Interrupted) << s.message;
    const double ms = std::chrono::duration<double, std::milli>(ended - asked).count();
    EXPECT_LT(ms, 100.0);
    std::cout << "reverse-continue ended " << ms << " ms after the interrupt\n";
    // The machine is at a position of this timeline: forward from it runs as before.
    EXPECT_GE(m().now(), shell.debugger().history_start());
    EXPECT_EQ(shell.execute("reverse-stepi").find("error"), std::string::npos);
}

TEST_F(Thesis, HistoryListsTheLastInstructionsWithTheRegistersTheyChanged) {
    run("break OUT");
    run("press EXEC");
    run("stepi 3");  // LXI H,1B39H; MOV A,M; RLC
    const std::string out = run("history 3");
    EXPECT_NE(out.find("LXI H,"), std::string::npos) << out;
    EXPECT_NE(out.find("L=39H"), std::string::npos) << out;  // H was 1BH already (HL = XAC's address)
    EXPECT_NE(out.find("MOV A,M"), std::string::npos) << out;
    EXPECT_NE(out.find("RLC"), std::string::npos) << out;
}

TEST_F(Thesis, LookingChangesNoDevice) {
    run("break OUT");
    run("press EXEC");
    run("delete");
    // a key pressed during the motion waits in the 8279's FIFO (RST 5.5 is masked, nobody reads it)
    run("press 5");
    ASSERT_EQ(m().kdc().state().fifo_count, 1);
    const auto before = snap();
    for (const char* line : {"info 8279", "info 8155", "info axis", "info registers", "info display", "bt", "list",
                             "disassemble", "x/16xb 1B00H", "x/4xw YAC", "x/3i OUT", "p [HL]", "p word[1B30H] + 1",
                             "p M", "info breakpoints", "display word[YAC]", "info line"})
        run(line);
    EXPECT_EQ(snap(), before);
    EXPECT_NE(run("info 8279").find("FIFO 1 entry"), std::string::npos);
}

TEST_F(Thesis, ErrorsSayWhatAndWhereAndTheSessionGoesOn) {
    auto err = [&](const std::string& line) {
        const int before = shell.console().errors();
        std::string out = shell.execute(line);
        EXPECT_EQ(shell.console().errors(), before + 1) << line << "\n" << out;
        return out;
    };
    EXPECT_NE(err("frobnicate 3").find("column 1: error: unknown command 'frobnicate'"), std::string::npos);
    EXPECT_NE(err("p 1 + * 2").find("column 7: error: unexpected '*'"), std::string::npos);
    EXPECT_NE(err("break NOSUCH").find("column 7: error: unknown symbol 'NOSUCH'"), std::string::npos);
    EXPECT_NE(err("p word[YAC").find("column 11: error: expected ']'"), std::string::npos);
    EXPECT_NE(err("p 1/0").find("column 4: error: division by zero"), std::string::npos);
    // an address that cannot be evaluated (found by debug_fuzz: it ended the process)
    EXPECT_NE(err("watch byte[10/0H]").find("column 14: error: division by zero"), std::string::npos);
    EXPECT_NE(err("x/2x 1/0").find("column 7: error: division by zero"), std::string::npos);
    EXPECT_NE(err("p 0800").find("column 3: error: '0800' is ambiguous"), std::string::npos);
    EXPECT_NE(err("watch port 300").find("column 12: error: bad port '300'"), std::string::npos);
    EXPECT_NE(err("x/8q YAC").find("unknown format letter 'q'"), std::string::npos);
    EXPECT_NE(err("break OUT if A ==").find("column 18: error: expected a value"), std::string::npos);
    EXPECT_NE(err("break thesis.asm:99999").find("no code at or after"), std::string::npos);
    EXPECT_NE(err("info nothing").find("no 'info nothing'"), std::string::npos);
    // and the session still works
    EXPECT_EQ(run("p 2 + 3 * 4"), "$1 = 0EH (14)\n");
    EXPECT_EQ(run("p/x word[1B00H]"), "$2 = 0064H\n");  // X1 = 100 as typed
}

TEST_F(Thesis, ExpressionsReadRegistersFlagsMemoryAndSymbols) {
    run("break OUT");
    run("press EXEC");
    EXPECT_EQ(run("p PC == OUT"), "$1 = 01H (1)\n");
    EXPECT_EQ(run("p word[YAC] + word[XAC]"), "$2 = 0096H (150)\n");  // 50 + 100
    EXPECT_EQ(run("p &Z == Z"), "$3 = 00H (0)\n");  // the routine Z (0A5CH...) is not the zero flag
    run("set A = 0x5A");
    run("set CY = 1");
    run("set word[1B50H] = 1234H");
    EXPECT_EQ(m().cpu().regs().a, 0x5A);
    EXPECT_EQ(m().cpu().regs().f & 1, 1);
    EXPECT_EQ(m().peek(0x1B50), 0x34);
    EXPECT_EQ(m().peek(0x1B51), 0x12);
    EXPECT_EQ(run("p/t A"), "$4 = 01011010B\n");
}

TEST_F(Thesis, CommandsAtABreakpointMakeALogPoint) {
    run("break OUT");
    run("commands");
    run("p word[XAC]");
    run("continue");
    run("end");
    run("watch word YAC");  // stops the chain of continues when Y first moves
    const std::string out = run("press EXEC");
    // YAC = Y1 is set before the first OUT: the watch stops there first
    EXPECT_NE(out.find("Watchpoint 2: word YAC"), std::string::npos) << out;
    const std::string more = run("continue");
    // OUT at X = 100 and 101 printed X and went on; at X = 102 the first Y step's count stops it
    EXPECT_NE(more.find("= 0064H (100)"), std::string::npos) << more;
    EXPECT_NE(more.find("= 0065H (101)"), std::string::npos) << more;
    EXPECT_NE(more.find("New value = 0033H (51)"), std::string::npos) << more;
}

// OUT is called at X = 100 (an X step), 101 (X), 102 (the first Y step: YID(102) = 51), 102 (X), ...
TEST_F(Thesis, IgnoreCountsTemporaryBreakpointsEnableAndDisable) {
    run("break OUT");
    run("ignore 1 2");
    run("press EXEC");
    EXPECT_EQ(m().cpu().regs().pc, symbol("OUT"));
    EXPECT_EQ(m().peek(symbol("XAC")), 102);  // the third call
    EXPECT_EQ(m().peek(symbol("YAC")), 50);
    EXPECT_NE(run("info breakpoints").find("already hit 3 times"), std::string::npos);
    run("disable 1");
    run("tbreak DELAY");
    run("continue");
    EXPECT_EQ(m().cpu().regs().pc, symbol("DELAY"));
    EXPECT_EQ(shell.debugger().breakpoints().size(), 1u);  // the temporary one is gone
    run("enable 1");
    run("continue");
    EXPECT_EQ(m().cpu().regs().pc, symbol("OUT"));
    EXPECT_EQ(m().peek(symbol("XAC")), 102);  // the Y step did not move X: OUT again at 102
    EXPECT_EQ(m().peek(symbol("YAC")), 51);
    run("advance DELAY");
    EXPECT_EQ(m().cpu().regs().pc, symbol("DELAY"));
}

TEST_F(Thesis, WatchpointsOnReadsChipsAndTheKeyboard) {
    // DELAY's LDA 1B38H reads D: stop after it, A = D = 2
    run("rwatch DLYK");
    run("press EXEC");
    EXPECT_EQ(m().cpu().regs().pc, symbol("DELAY") + 3);
    EXPECT_EQ(m().cpu().regs().a, 2);
    run("delete");
    // port A's latch: the next change is DELAY's pulse low, 03H -> 02H (O42's MVI A,03H ... OUT)
    run("watch 8155 porta");
    const std::string out = run("continue");
    EXPECT_NE(out.find("Old value = 03H (3)\nNew value = 02H (2)"), std::string::npos) << out;
    EXPECT_EQ(m().cpu().regs().pc, symbol("DELAY") + 13);
    run("delete");
    // a key pressed during the motion: the 8279's FIFO count goes 0 -> 1 when its debounce ends
    run("watch 8279 fifo");
    run("keydown 5");
    const std::string key = run("continue");
    EXPECT_NE(key.find("Watchpoint 3: 8279 fifo\nOld value = 00H (0)\nNew value = 01H (1)"), std::string::npos) << key;
    EXPECT_EQ(m().kdc().state().fifo_count, 1);
    run("delete");
    run("keyup 5");
    // awatch: any access; OKEY reads XAC (LXI H,1B34H; XRA M)
    run("awatch XAC");
    run("continue");
    EXPECT_NE(run("info breakpoints").find("acc watchpoint"), std::string::npos);
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

// `info board` is the board's description as fitted: the ALP 85's ports as the thesis listing
// fixes them (OUT 0E1H to the 8279, 8155 at F8H-FDH), and on the SDK-85 its memory-mapped 8279.
TEST(InfoBoard, ShowsTheBoardsMapsAndWiring) {
    script::DebugShell alp{script::SessionOptions{}};
    const std::string a = alp.execute("info board");
    EXPECT_NE(a.find("I/O    E0H-E1H  8279"), std::string::npos) << a;
    EXPECT_NE(a.find("I/O    F8H-FDH  8155"), std::string::npos) << a;
    EXPECT_NE(a.find("8155 TIMER OUT -> TRAP"), std::string::npos) << a;
    EXPECT_EQ(a.find("3000H-3FFFH  ROM"), std::string::npos) << a;  // the expansion EPROM is an option, out
    EXPECT_NE(a.find("option expansion (off)"), std::string::npos) << a;
    script::SessionOptions o;
    o.board = &board::kSdk85;
    script::DebugShell sdk{o};
    const std::string s = sdk.execute("info board");
    EXPECT_NE(s.find("memory 1800H-1FFFH  8279"), std::string::npos) << s;
    EXPECT_NE(s.find("2000H-20FFH  RAM"), std::string::npos) << s;
}

}  // namespace
}  // namespace alp85::test
