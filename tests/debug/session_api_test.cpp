// One session API and a resumable debugger (issue 22): instruction flow from the opcode table
// (RSTV is a restart), runs cut into slices that end where the whole run ends, pause, hit
// conditions and log points decided by the Debugger, HLT and runaway stops, convenience variables
// read by conditions, and the typed Session calls. Programs are poked in by hand; addresses and
// T-states are counted from the Intel 8085AH data sheet's instruction table.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "asm/isa.h"
#include "emu/debug/debugger.h"
#include "emu/program/firmware.h"
#include "emu/script/debug_shell.h"

namespace alp85::test {
namespace {

using debug::Debugger;
using debug::StopReason;

constexpr std::uint16_t kOrg = 0x0800;     // the user EPROM
constexpr std::uint16_t kStack = 0x2000;   // top of the 4 KB RAM (1000H-1FFFH)

struct Rig {
    Machine m{[] {
        Machine::Options o;
        o.machine_tool = false;
        return o;
    }()};
    Debugger d{m};
    void program(std::vector<std::uint8_t> bytes, std::uint16_t at = kOrg) {
        m.load(at, bytes);
        m.reset();
        m.cpu().regs().pc = kOrg;
    }
};

// 0800 LXI SP,2000H (10 T) / 0803 MVI A,7FH (7) / 0805 ADI 01H (7): 7FH + 1 = 80H overflows, V = 1
// 0807 RSTV: taken (12 T) to 0040H, where RET (10 T) comes back to 0808H.
std::vector<std::uint8_t> rstv_program() { return {0x31, 0x00, 0x20, 0x3E, 0x7F, 0xC6, 0x01, 0xCB, 0x00}; }

TEST(Flow, TheOpcodeTableKnowsEveryCallRestartReturnAndJump) {
    EXPECT_EQ(isa::flow_of(0xCB, false), isa::Flow::RestartIf);  // RSTV
    EXPECT_EQ(isa::flow_of(0xCB, true), isa::Flow::Jump);        // the 8080's JMP
    EXPECT_EQ(isa::flow_of(0xDD, false), isa::Flow::JumpIf);     // JNK
    EXPECT_EQ(isa::flow_of(0xDD, true), isa::Flow::Call);        // the 8080's CALL
    EXPECT_EQ(isa::flow_of(0xC7, false), isa::Flow::Restart);
    EXPECT_EQ(isa::flow_of(0xC4, false), isa::Flow::CallIf);
    EXPECT_EQ(isa::flow_of(0xC0, false), isa::Flow::ReturnIf);
    EXPECT_EQ(isa::flow_of(0xE9, false), isa::Flow::JumpIndirect);
    EXPECT_EQ(isa::flow_of(0x76, false), isa::Flow::Halt);
    EXPECT_EQ(isa::flow_of(0x3E, false), isa::Flow::Next);
    int calls = 0, returns = 0, jumps = 0;
    for (int op = 0; op < 256; ++op) {
        const isa::Flow f = isa::flow_of(static_cast<std::uint8_t>(op), false);
        calls += isa::may_call(f), returns += isa::may_return(f), jumps += isa::may_jump(f);
    }
    EXPECT_EQ(calls, 1 + 8 + 8 + 1);    // CALL, 8 Ccc, 8 RST, RSTV
    EXPECT_EQ(returns, 1 + 8);          // RET, 8 Rcc
    EXPECT_EQ(jumps, 1 + 8 + 2 + 1);    // JMP, 8 Jcc, JNK and JK, PCHL
}

TEST(Flow, NextOverATakenRstvStopsAtTheNextInstruction) {
    Rig r;
    r.program(rstv_program());
    r.m.load(0x0040, std::vector<std::uint8_t>{0xC9});  // RET
    for (int i = 0; i < 3; ++i) r.d.stepi();
    ASSERT_EQ(r.m.cpu().regs().pc, 0x0807);
    ASSERT_TRUE(r.m.cpu().regs().f & isa::F_V);
    const std::uint64_t t0 = r.m.now();
    const debug::Stop s = r.d.next();
    EXPECT_EQ(s.reason, StopReason::Step);
    EXPECT_EQ(s.pc, 0x0808);
    EXPECT_EQ(r.m.cpu().regs().sp, kStack);
    EXPECT_EQ(r.m.now() - t0, 12u + 10u);  // RSTV taken, then RET
}

TEST(Flow, StepIntoATakenRstvGoesTo0040H) {
    Rig r;
    r.program(rstv_program());
    r.m.load(0x0040, std::vector<std::uint8_t>{0xC9});
    for (int i = 0; i < 4; ++i) r.d.stepi();
    EXPECT_EQ(r.m.cpu().regs().pc, 0x0040);
    EXPECT_EQ(r.m.cpu().regs().sp, kStack - 2);
    EXPECT_EQ(r.m.peek(kStack - 2) | r.m.peek(kStack - 1) << 8, 0x0808);  // the return address pushed
}

// 0800 LXI SP,2000H / 0803 MVI B,10 / 0805 LOOP: DCR B / 0806 JNZ 0805H / 0809 HLT (DI'd by reset)
std::vector<std::uint8_t> loop_program() { return {0x31, 0x00, 0x20, 0x06, 0x0A, 0x05, 0xC2, 0x05, 0x08, 0x76}; }

TEST(Resumable, SlicesEndWhereTheWholeRunEnds) {
    // A breakpoint on the loop's DCR with a hit condition: its 7th pass.
    std::uint64_t whole_at = 0;
    std::uint8_t whole_b = 0;
    {
        Rig r;
        r.program(loop_program());
        const int n = r.d.add_breakpoint("0805H").number;
        ASSERT_EQ(r.d.set_hit_condition(n, "==7"), "");
        const debug::Stop s = r.d.cont();
        ASSERT_EQ(s.reason, StopReason::Breakpoint);
        whole_at = s.at;
        whole_b = r.m.cpu().regs().b;
        // LXI 10 + MVI 7, six passes of DCR (4) and JNZ taken (10): 17 + 6 x 14 T-states.
        EXPECT_EQ(whole_at, 17u + 6u * 14u);
        EXPECT_EQ(whole_b, 10 - 6);
    }
    Rig r;
    r.program(loop_program());
    const int n = r.d.add_breakpoint("0805H").number;
    r.d.set_hit_condition(n, "==7");
    ASSERT_FALSE(r.d.begin_continue());
    EXPECT_TRUE(r.d.running());
    int slices = 0;
    std::optional<debug::Stop> s;
    while (!(s = r.d.resume({.tstates = 5, .seconds = 0}))) ++slices;
    EXPECT_GT(slices, 5);  // each slice ends after the instruction that crosses its budget
    EXPECT_FALSE(r.d.running());
    EXPECT_EQ(s->reason, StopReason::Breakpoint);
    EXPECT_EQ(s->at, whole_at);
    EXPECT_EQ(r.m.cpu().regs().b, whole_b);
}

TEST(Resumable, PauseEndsARunBetweenSlices) {
    Rig r;
    r.program({0xC3, 0x00, 0x08});  // JMP 0800H: forever
    ASSERT_FALSE(r.d.begin_continue());
    EXPECT_FALSE(r.d.resume({.tstates = 1000, .seconds = 0}));
    const debug::Stop s = r.d.pause();
    EXPECT_EQ(s.reason, StopReason::Paused);
    EXPECT_FALSE(r.d.running());
    EXPECT_GE(r.m.now(), 1000u);
}

TEST(Resumable, ALogPointPrintsAndGoesOn) {
    Rig r;
    r.program(loop_program());
    const int n = r.d.add_breakpoint("0805H").number;
    r.d.set_log_message(n, "B={B}");
    std::vector<std::string> out;
    r.d.listen([&](const debug::Event& e) {
        if (e.kind == debug::Event::Kind::Output) out.push_back(e.text);
    });
    const debug::Stop s = r.d.cont();
    EXPECT_EQ(s.reason, StopReason::Halted);  // past every pass of the log point, to the HLT
    ASSERT_EQ(out.size(), 10u);
    EXPECT_EQ(out.front(), "B=0AH (10)");
    EXPECT_EQ(out.back(), "B=01H (1)");
}

TEST(Resumable, AHaltedCpuIsReportedLikeAnExitedProgram) {
    Rig r;
    r.program(loop_program());
    debug::Stop s = r.d.cont();
    EXPECT_EQ(s.reason, StopReason::Halted);
    EXPECT_NE(s.message.find("HLT at 0809H"), std::string::npos) << s.message;
    EXPECT_EQ(s.at, 17u + 9u * 14u + 4u + 7u + 5u);  // nine taken passes, the last DCR, JNZ not taken, HLT
    // Again: nothing can wake it (interrupts off, no timer, no input): it says so at once.
    const std::uint64_t t = r.m.now();
    s = r.d.cont();
    EXPECT_EQ(s.reason, StopReason::Halted);
    EXPECT_NE(s.message.find("only RESET"), std::string::npos) << s.message;
    EXPECT_EQ(r.m.now(), t);
}

TEST(Resumable, ARunawayStopsBeforeTheFetchNamingTheJumpThatLeft) {
    Rig r;
    r.program({0x31, 0x00, 0x20, 0xC3, 0x00, 0x90});  // LXI SP,2000H / JMP 9000H (nothing there)
    std::bitset<0x10000> code;
    for (int a = kOrg; a < kOrg + 6; ++a) code[static_cast<std::size_t>(a)] = true;
    r.d.set_runaway_guard(&code);
    const debug::Stop s = r.d.cont();
    EXPECT_EQ(s.reason, StopReason::Runaway);
    EXPECT_EQ(s.pc, 0x9000);
    ASSERT_TRUE(s.after);
    EXPECT_EQ(*s.after, 0x0803);
    EXPECT_EQ(s.at, 10u + 10u);  // LXI, JMP: the RST 7 that unmapped memory reads (FFH) has not run
    EXPECT_NE(s.message.find("9000H"), std::string::npos);
    EXPECT_NE(s.message.find("0803H"), std::string::npos);
}

// Breakpoints (hit conditions included) and the runaway guard need only the CPU's fetch fence:
// no debug hooks, so the plain path runs (delay loops too, where no breakpoint is inside them).
// A memory watch needs every access: the debug path. Both stop where the data sheet says.
TEST(Resumable, BreakpointsAndTheRunawayGuardKeepTheCpuOnItsPlainPath) {
    Rig r;
    r.program(loop_program());
    std::bitset<0x10000> code;
    for (int a = kOrg; a < kOrg + 10; ++a) code[static_cast<std::size_t>(a)] = true;
    r.d.set_runaway_guard(&code);
    const int n = r.d.add_breakpoint("0805H").number;
    r.d.set_hit_condition(n, "==7");
    EXPECT_EQ(r.m.cpu().debug_hooks(), nullptr);
    ASSERT_NE(r.m.cpu().fetch_fence(), nullptr);
    EXPECT_TRUE((*r.m.cpu().fetch_fence())[0x0805]);   // the breakpoint
    EXPECT_TRUE((*r.m.cpu().fetch_fence())[0x9000]);   // outside the code
    EXPECT_FALSE((*r.m.cpu().fetch_fence())[0x0806]);  // code without a breakpoint
    const debug::Stop s = r.d.cont();
    ASSERT_EQ(s.reason, StopReason::Breakpoint);
    EXPECT_EQ(s.at, 17u + 6u * 14u);  // as in SlicesEndWhereTheWholeRunEnds, on the debug path
    // A watch on the stack's top word: every write is looked at, on the debug path.
    debug::WatchSpec w;
    w.kind = debug::WatchKind::Write;
    w.what = "stack";
    w.first = kStack - 2;
    w.last = kStack - 1;
    r.d.add_watchpoint(w);
    EXPECT_NE(r.m.cpu().debug_hooks(), nullptr);
    EXPECT_EQ(r.m.cpu().fetch_fence(), nullptr);
}

// ---- the console: one expression language, convenience variables in conditions -----------------

struct Shell {
    script::DebugShell shell{script::SessionOptions{}};
    std::string run(const std::string& line, bool ok = true) {
        const int before = shell.console().errors();
        std::string out = shell.execute(line);
        EXPECT_EQ(shell.console().errors() == before, ok) << line << "\n" << out;
        return out;
    }
};

TEST(Variables, BreakIfAndConditionReadConvenienceVariablesWhenTheyAreChecked) {
    Shell s;
    Machine& m = s.shell.session().machine();
    m.load(kOrg, loop_program());
    m.reset();
    m.cpu().regs().pc = kOrg;
    s.run("set $N = 7");
    s.run("break 0805H if $N < 5");
    // $N = 7: the condition is false, the run goes to the HLT.
    std::string out = s.run("continue");
    EXPECT_EQ(out.find("Breakpoint 1"), std::string::npos) << out;
    m.reset();
    m.cpu().regs().pc = kOrg;
    s.run("set $N = 3");
    out = s.run("continue");
    EXPECT_NE(out.find("Breakpoint 1"), std::string::npos) << out;
    s.run("condition 1 $N > 5");
    out = s.run("continue");  // $N = 3: no more stops
    EXPECT_EQ(out.find("Breakpoint 1"), std::string::npos) << out;
    s.run("break 0806H if $NOSUCH < 5", false);
}

// ---- the typed Session calls ---------------------------------------------------------------------

TEST(SessionApi, LoadsAPathWithASpaceAndAQuoteAndPlotsWhatItRecorded) {
    if (!firmware::have_monitor()) GTEST_SKIP() << "built without the monitor";
    const auto dir = std::filesystem::temp_directory_path() / "alp85 session's test";
    std::filesystem::create_directories(dir);
    const auto src = dir / "it's a program.asm";
    std::ofstream(src) << "        ORG 0800H\nSTART:  MVI B,10\nLOOP:   DCR B\n        JNZ LOOP\n        HLT\n        END START\n";
    script::SessionOptions o;
    o.monitor_rom = firmware::monitor;
    script::Session session(o);
    script::Session::Boot boot;
    boot.images.push_back({src, std::nullopt});
    ASSERT_EQ(session.boot(boot).status, script::Session::Status::Ok);
    EXPECT_EQ(session.symbols().value_of("LOOP"), 0x0802);
    EXPECT_EQ(session.machine().peek(0x0800), 0x06);  // MVI B
    // Record, run, plot: the plot needs what was recorded, not a recording in the same batch.
    ASSERT_EQ(session.record(dir / "r.csv", board::tstates_from_ms(1)).status, script::Session::Status::Ok);
    session.debugger().run_for(board::tstates_from_ms(10));
    const auto plot = dir / "p.svg";
    std::filesystem::remove(plot);
    EXPECT_EQ(session.plot_toolpath(plot).status, script::Session::Status::Ok);
    EXPECT_TRUE(std::filesystem::exists(plot));
    // A refused snapshot is an error, and the machine stays as it was.
    std::ofstream(dir / "bad.snap") << "not a snapshot";
    const auto before = session.machine().snapshot_bytes();
    EXPECT_EQ(session.restore(dir / "bad.snap").status, script::Session::Status::Failed);
    EXPECT_EQ(session.machine().snapshot_bytes(), before);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace alp85::test
