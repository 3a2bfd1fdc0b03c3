// The console as a gdb user meets it (issue 23, items 7, 8 and 10): names of addresses, the
// backtrace against finish, display/i, info watchpoints, tbreak, help, frame selection, jump,
// info symbol, list FIRST,LAST and file-name completion. Expected text comes from the sources:
// firmware/monitor/monitor.asm (ANWEIN at 0701H: IN KDCMD, 2 bytes; ANI KSTCNT at 0703H) and
// firmware/thesis/thesis.asm (OUT, O42, DELAY, the CALL DELAY at O42+9 whose return address is
// O42+12), and gdb's manual for the wording.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <fmt/format.h>

#include "emu/program/firmware.h"
#include "emu/script/debug_shell.h"

namespace alp85::test {
namespace {

class Gdb : public ::testing::Test {
protected:
    script::DebugShell shell{[] {
        script::SessionOptions o;
        o.monitor_rom = firmware::monitor;
        return o;
    }()};

    Machine& m() { return shell.session().machine(); }
    std::string run(const std::string& line) {
        const int before = shell.console().errors();
        std::string out = shell.execute(line);
        EXPECT_EQ(shell.console().errors(), before) << line << "\n" << out;
        return out;
    }
    std::uint16_t symbol(const char* name) { return *shell.debugger().program().value_of(name); }

    void SetUp() override {
        if (!firmware::have_monitor() || !firmware::find("thesis-fixed")) GTEST_SKIP() << "built without the firmware";
        for (const char* line : {"monitor", "firmware thesis-fixed", "reset"}) run(line);
    }
    // The worked line of docs/thesis.md up to the key that starts the motion.
    void enter_line() {
        for (const char* line : {"type R 7 0 8 0 0 EXEC", "wait display \"?.=----\" timeout 200ms", "type 0 0 0 0",
                                 "wait display \"H1=----\" timeout 1s", "type 0 1 0 0 EXEC", "wait display \"y1=----\" timeout 200ms",
                                 "type 0 0 5 0 EXEC", "wait display \"H2=----\" timeout 200ms", "type 0 3 0 0 EXEC",
                                 "wait display \"y2=----\" timeout 200ms", "type 0 2 0 0 EXEC", "wait display \"H=----\" timeout 200ms",
                                 "type 0 7 5 0"})
            run(line);
    }
};

// Item 7: the key poll is ANWEIN (an EQU entry point), not the data table 301 bytes before it.
TEST_F(Gdb, AnAddressIsNamedByItsRoutineNotAFarTable) {
    run("set PC = 0703H");
    const std::string frame = run("info frame");
    EXPECT_NE(frame.find("ANWEIN+2 (0703H)"), std::string::npos) << frame;
    EXPECT_EQ(frame.find("SEGTAB"), std::string::npos) << frame;
    EXPECT_NE(run("bt").find("in ANWEIN+2"), std::string::npos);
    EXPECT_NE(run("info symbol 0703H").find("ANWEIN + 2"), std::string::npos);
    // 0000H holds JMP COLD with no label: no name; KMODE EQU 0 is a constant.
    const std::string x = run("x/s 0");
    EXPECT_EQ(x.find("KMODE"), std::string::npos) << x;
    EXPECT_EQ(x.rfind("0000H:", 0), 0u) << x;
    EXPECT_EQ(run("info symbol 0").find("KMODE"), std::string::npos);
    // In the FFH fill between SEGTAB's table and ANWEIN: no name, not SEGTAB+N.
    run("set PC = 06F0H");
    const std::string fill = run("info frame");
    EXPECT_EQ(fill.find("SEGTAB"), std::string::npos) << fill;
    EXPECT_NE(fill.find("?? (06F0H)"), std::string::npos) << fill;
}

// Item 8: a caller's frame is named at its return address, as finish names it.
TEST_F(Gdb, BacktraceNamesTheCallerAsFinishDoes) {
    enter_line();
    run("break DELAY");
    run("press EXEC");
    ASSERT_EQ(m().cpu().regs().pc, symbol("DELAY"));
    const std::string bt = run("bt");
    std::smatch b;
    ASSERT_TRUE(std::regex_search(bt, b, std::regex(R"(#1\s+([0-9A-F]{4}H) in (\S+))"))) << bt;
    const std::string fin = run("finish");
    std::smatch f;
    ASSERT_TRUE(std::regex_search(fin, f, std::regex(R"(returned to (\S+) \(([0-9A-F]{4}H)\))"))) << fin;
    EXPECT_EQ(b[1].str(), f[2].str());
    EXPECT_EQ(b[2].str(), f[1].str()) << bt << fin;
    // The CALL DELAY of O42 is at O42+9 (three bytes): it returns to O42+12.
    EXPECT_EQ(f[1].str(), "O42+12");
}

TEST_F(Gdb, DisplayIShowsTheInstruction) {
    run("set PC = OUT");
    const std::string d = run("display/i $pc");
    EXPECT_NE(d.find("1: x/i $pc"), std::string::npos) << d;
    EXPECT_NE(d.find("=> 0C73H <OUT>:\tLXI H,1B39H"), std::string::npos) << d;
    const std::string s = run("stepi");
    EXPECT_NE(s.find("=> 0C76H <OUT+3>:\tMOV A,M"), std::string::npos) << s;
}

TEST_F(Gdb, InfoWatchpointsListsOnlyWatchpoints) {
    run("break OUT");
    EXPECT_EQ(run("info watchpoints"), "No watchpoints.\n");
    run("watch word YAC");
    const std::string w = run("info watchpoints");
    EXPECT_NE(w.find("word YAC (1B32H)"), std::string::npos) << w;
    EXPECT_EQ(w.find("breakpoint"), std::string::npos) << w;
    const std::string b = run("info breakpoints");
    EXPECT_NE(b.find("in OUT"), std::string::npos) << b;
}

TEST_F(Gdb, TbreakSaysWhereAndItsHitIsTemporary) {
    enter_line();
    const std::string t = run("tbreak OUT");
    EXPECT_TRUE(std::regex_search(t, std::regex(R"(^Temporary breakpoint 1 at 0C73H: file thesis\.asm, line \d+\.\n$)"))) << t;
    const std::string hit = run("press EXEC");
    EXPECT_NE(hit.find("Temporary breakpoint 1, OUT (0C73H)"), std::string::npos) << hit;
    EXPECT_EQ(run("info breakpoints"), "No breakpoints or watchpoints.\n");
}

// gdb's note for a line without code, for tbreak as for break: the point goes to the next line that has.
TEST_F(Gdb, TbreakOnALineWithoutCodeSaysWhereItBinds) {
    const auto& program = shell.debugger().program();
    int blank = 0;  // the first line of thesis.asm without code followed by one with code
    for (int line = 1; line < 2000 && !blank; ++line)
        if (program.addresses_of("thesis.asm", line).empty() && !program.addresses_of("thesis.asm", line + 1).empty())
            blank = line;
    ASSERT_NE(blank, 0);
    const std::uint16_t at = program.addresses_of("thesis.asm", blank + 1).front();
    EXPECT_EQ(run(fmt::format("tbreak thesis.asm:{}", blank)),
              fmt::format("thesis.asm:{} has no code: the breakpoint binds to line {}\n"
                          "Temporary breakpoint 1 at {:04X}H: file thesis.asm, line {}.\n",
                          blank, blank + 1, at, blank + 1));
}

// The script's print forms at the debugger's prompt: print board is the board's description, not
// a symbol BOARD.
TEST_F(Gdb, PrintBoardIsTheScriptsPrint) {
    const std::string b = run("print board");
    EXPECT_NE(b.find("board alp85:"), std::string::npos) << b;
    EXPECT_NE(b.find("0000H-07FFH"), std::string::npos) << b;  // the monitor EPROM (thesis Chapter II)
}

TEST_F(Gdb, HelpShowsEveryCommandsWholeText) {
    const std::string h = run("help");
    // Unwrapped, the text holds each command's full help (the break line's description too).
    std::string flat;
    for (std::size_t i = 0; i < h.size(); ++i) {
        if (std::isspace(static_cast<unsigned char>(h[i]))) {
            if (!flat.empty() && flat.back() != ' ') flat += ' ';
        } else {
            flat += h[i];
        }
    }
    for (const char* cmd : {"break", "watch", "x", "info", "run", "display", "list"}) {
        std::string one = run(std::string("help ") + cmd);
        while (!one.empty() && one.back() == '\n') one.pop_back();
        EXPECT_NE(flat.find(one), std::string::npos) << cmd << ": " << one;
    }
    std::istringstream lines(h);
    for (std::string l; std::getline(lines, l);) EXPECT_LE(l.size(), 100u) << l;
}

TEST_F(Gdb, UpDownFrameSelectTheCallers) {
    enter_line();
    run("break DELAY");
    run("press EXEC");
    const std::string up = run("up");
    // gdb and DAP show a caller at the line of its call: O42's CALL DELAY (thesis.asm:758, L669),
    // not the CALL INPUT after it, where it returns to.
    EXPECT_EQ(up.rfind("#1  0CC7H in O42+12 at thesis.asm:758\n", 0), 0u) << up;
    EXPECT_NE(up.find("CALL    DELAY"), std::string::npos) << up;
    EXPECT_EQ(run("up").rfind("#2 ", 0), 0u);
    EXPECT_NE(shell.execute("up").find("Initial frame selected; you cannot go up."), std::string::npos);
    EXPECT_EQ(run("down").rfind("#1 ", 0), 0u);
    EXPECT_EQ(run("frame 0").rfind("#0  0D34H in DELAY", 0), 0u);
    EXPECT_NE(shell.execute("down").find("Bottom (innermost) frame selected; you cannot go down."), std::string::npos);
    EXPECT_EQ(run("frame 2").rfind("#2 ", 0), 0u);
    EXPECT_EQ(run("f").rfind("#2 ", 0), 0u);
    // list shows the selected frame's source: LOOP's CALL OUT (L31) among the lines
    EXPECT_NE(run("list").find("; L31"), std::string::npos);
}

// Item 4: the backtrace's callers are at their CALLs' lines; LOOP calls OUT at thesis.asm:83 (L31).
TEST_F(Gdb, BacktraceShowsCallersAtTheirCalls) {
    enter_line();
    run("break OUT");
    run("press EXEC");
    ASSERT_EQ(m().cpu().regs().pc, symbol("OUT"));
    const std::string bt = run("bt");
    EXPECT_TRUE(std::regex_search(bt, std::regex(R"(\n#1 .* at thesis\.asm:83\n)"))) << bt;
    const std::string f = run("frame 1");
    EXPECT_NE(f.find(" at thesis.asm:83\n83\t"), std::string::npos) << f;
    EXPECT_NE(f.find("CALL    OUT"), std::string::npos) << f;
}

// Item 5: after the main program's HLT (thesis.asm:87, after SOBE's CALL BITTI; three bytes) the PC
// is past it, at ADDSUB; the stop is shown at the HLT.
TEST_F(Gdb, AHaltedCpuIsShownAtItsHlt) {
    run("set PC = SOBE + 3");
    const std::string s = run("continue");
    EXPECT_NE(s.find("the CPU halted"), std::string::npos) << s;
    EXPECT_NE(s.find(" at thesis.asm:87\n87\t"), std::string::npos) << s;
    EXPECT_EQ(s.find("ADDSUB"), std::string::npos) << s;
    EXPECT_EQ(run("bt").rfind(fmt::format("#0  {:04X}H in SOBE+3 at thesis.asm:87", symbol("SOBE") + 3), 0), 0u);
}

// Items 1 and 2: breakpoint commands run at every stop, a script command's too; `silent` keeps
// the stop quiet; echo and output print without a new line of their own.
TEST_F(Gdb, CommandsRunAtAStopInsideAScriptCommand) {
    enter_line();
    run("set $N = 0");
    run("break OUT");
    for (const char* line : {"commands", "silent", "set $N = $N + 1", "echo N=", "output $N", "echo \\n", "end"}) run(line);
    const std::string hit = run("press EXEC");
    ASSERT_EQ(m().cpu().regs().pc, symbol("OUT"));
    EXPECT_EQ(hit.find("Breakpoint 1"), std::string::npos) << hit;
    EXPECT_TRUE(std::regex_search(hit, std::regex(R"((^|\n)N=[^\n]*\(1\)\n)"))) << hit;
    EXPECT_NE(run("print $N").find("(1)"), std::string::npos);
}

// Item 1: commands that resume the run end their list, and the stop they reach runs its commands
// in turn, not one list inside another (that overflowed the stack); the prompt comes back.
TEST_F(Gdb, ResumingCommandsDoNotNest) {
    for (const char* resume : {"jump ANWEIN", "advance ANWEIN", "run 1ms"}) {
        run("delete");
        run("break ANWEIN");
        run("commands");
        run(resume);
        run("end");
        // ANWEIN, the key poll, is called again some 60 T-states after it returns: the commands
        // would resume forever; after 10000 stops the prompt comes back and says why.
        const std::string c = run("continue");
        EXPECT_NE(c.find("Stopped: the commands of breakpoint"), std::string::npos) << resume << c.substr(c.size() - std::min<std::size_t>(c.size(), 400));
        EXPECT_EQ(m().cpu().regs().pc, symbol("ANWEIN")) << resume;
        EXPECT_NE(run("print 6*7").find("= 2AH (42)"), std::string::npos) << resume;  // 6*7 = 42 = 2AH
    }
}

// Item 3: finish inside DGIR, which waits for four digits, gives up after the guard of machine
// time and says why.
TEST_F(Gdb, FinishThatGivesUpSaysWhy) {
    run("type R 7 0 8 0 0 EXEC");
    run("wait display \"?.=----\" timeout 200ms");
    run("break DGIR1");
    run("continue");
    ASSERT_EQ(m().cpu().regs().pc, symbol("DGIR1"));
    run("delete");
    // The limit is 10 min of machine time; 2 s give the same answer sooner (DGIR1 waits for a key
    // that never comes; 600 s took 87 s of the sanitizer pass, 20 s took 4.9).
    EXPECT_EQ(debug::Debugger::kContinueLimit, 600ull * 3'072'000);
    EXPECT_EQ(shell.debugger().continue_limit(), debug::Debugger::kContinueLimit);
    EXPECT_EQ(run("set limit 2s"), "continue, finish, until and advance give up after 2.000 s of machine time.\n");
    const std::uint64_t t0 = m().now();
    const std::string f = run("finish");
    EXPECT_NE(f.find("the routine did not return within 2 s of simulated time"), std::string::npos) << f;
    EXPECT_GE(m().now() - t0, 2ull * 3'072'000);
    EXPECT_LT(m().now() - t0, 3ull * 3'072'000);
}

TEST_F(Gdb, SetLimitRefusesWhatIsNoTime) {
    for (const char* bad : {"set limit", "set limit 0s", "set limit 5 parsecs", "set limit -1s"}) {
        const int before = shell.console().errors();
        shell.execute(bad);
        EXPECT_EQ(shell.console().errors(), before + 1) << bad;
    }
    EXPECT_EQ(shell.debugger().continue_limit(), debug::Debugger::kContinueLimit);
}

// Item 6: smaller gdb habits.
TEST_F(Gdb, InfoSymbolNamesAByteOfAWord) {
    // YAC EQU 1B32H, a word: 1B33H is its high byte.
    EXPECT_EQ(run("info symbol 1B33H"), "YAC + 1\n");
}

TEST_F(Gdb, RunUntilSaysItPassesBreakpointsAndWhereItStopped) {
    run("set SP = 20AEH");
    run("set PC = SOBE");
    run("break SOBE");
    const std::string r = run("run until BITTI");
    EXPECT_NE(r.find("run until does not stop at breakpoints"), std::string::npos) << r;
    EXPECT_NE(r.find(fmt::format("BITTI ({:04X}H) at thesis.asm:659\n", symbol("BITTI"))), std::string::npos) << r;
}

TEST_F(Gdb, AnXCountBeyondAnyIntIsNamed) {
    const std::string x = shell.execute("x/" + std::string(40, '1') + "xb 0");
    EXPECT_NE(x.find("error: bad count '" + std::string(40, '1') + "'"), std::string::npos) << x;
    EXPECT_EQ(x.find("stoi"), std::string::npos) << x;
}

TEST_F(Gdb, TheTStateCounterIsReadOnly) {
    run("stepi");
    const std::string t = shell.execute("set $T = 0");
    EXPECT_NE(t.find("error: $T is read-only"), std::string::npos) << t;
    EXPECT_NE(run("print $T").find("= "), std::string::npos);
    EXPECT_EQ(run("print $T == 0").find("(1)"), std::string::npos);  // the machine's time, not 0
}

TEST_F(Gdb, JumpContinuesAtTheLocation) {
    // From the start of BITTI (CALL 3, MVI 2, MVI 2, CALL 3, MVI 2 bytes) to its second CALL AUS.
    run("set SP = 20AEH");
    run("break BITTI+12");
    const std::string j = run("jump BITTI");
    EXPECT_NE(j.find("Continuing at 0"), std::string::npos) << j;
    EXPECT_NE(j.find("Breakpoint 1, BITTI+12"), std::string::npos) << j;
    EXPECT_EQ(m().cpu().regs().pc, symbol("BITTI") + 12);
}

TEST_F(Gdb, ListFirstLast) {
    run("set PC = OUT");
    const std::string l = run("list 700,703");
    std::istringstream in(l);
    std::vector<std::string> rows;
    for (std::string s; std::getline(in, s);) rows.push_back(s);
    ASSERT_EQ(rows.size(), 4u) << l;
    EXPECT_NE(rows[0].find("  700\t"), std::string::npos) << l;
    EXPECT_NE(rows[3].find("  703\t"), std::string::npos) << l;
    // a plain list goes on after the last line shown
    EXPECT_NE(run("list").find("  704\t"), std::string::npos);
    const std::string byname = run("list OUT,OUT+3");
    EXPECT_NE(byname.find("OUT:    LXI"), std::string::npos) << byname;
    EXPECT_NE(byname.find("MOV     A,M"), std::string::npos) << byname;
}

TEST_F(Gdb, FileNamesCompleteAfterLoad) {
    const auto dir = std::filesystem::temp_directory_path() / "alp85_complete_test";
    std::filesystem::create_directories(dir / "sub");
    std::ofstream(dir / "prog.asm") << "  END\n";
    const std::string base = dir.string() + "/pr";
    const auto files = shell.console().complete(base, false, "load");
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0], dir.string() + "/prog.asm");
    const auto dirs = shell.console().complete(dir.string() + "/su", false, "save");
    ASSERT_EQ(dirs.size(), 1u);
    EXPECT_EQ(dirs[0], dir.string() + "/sub/");
    std::filesystem::remove_all(dir);
}

TEST_F(Gdb, BannerNamesTheDebuggerAndHelp) {
    const std::string b = shell.console().banner();
    EXPECT_NE(b.find("help"), std::string::npos);
    EXPECT_NE(b.find("symbols"), std::string::npos);
}

}  // namespace
}  // namespace alp85::test
