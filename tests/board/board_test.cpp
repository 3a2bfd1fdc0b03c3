// Board tests: the ALP 85's maps, 8279 display and keys, 8155 timer → TRAP, with programs
// assembled by asm85 (tests/board/programs). Expected values come from the data sheets and the
// board map (docs/board.md), worked out in the comments.
#include <gtest/gtest.h>

#include <bitset>
#include <optional>

#include <cstdlib>

#include "board_programs.h"
#include "emu/board/snapshot_file.h"

namespace alp85::test {
namespace {

using periph::Key;

TEST(BoardMaps, RamEpromProtection8155RamAndUnmappedSpace) {
    Machine m;
    boot(m, "maps.asm");
    m.run_for(ms(5), [&] { return m.cpu().halted(); });
    ASSERT_TRUE(m.cpu().halted());
    EXPECT_EQ(m.peek(0x1100), 0xA5);  // RAM 1000H
    EXPECT_EQ(m.peek(0x1101), 0x5A);  // RAM 1FFFH
    EXPECT_EQ(m.peek(0x1102), 0x3C);  // 8155 RAM 2000H
    EXPECT_EQ(m.peek(0x1103), 0xC3);  // 8155 RAM 20FFH
    EXPECT_EQ(m.peek(0x1104), 0x96);  // monitor EPROM kept its byte
    EXPECT_EQ(m.peek(0x1105), 0xEE);  // user EPROM kept its byte
    EXPECT_EQ(m.peek(0x1106), 0xFF);  // unmapped 3000H
    EXPECT_EQ(m.peek(0x1107), 0xFF);  // unmapped FFFFH
    EXPECT_EQ(m.peek(0x1108), 0xFF);  // unmapped port 00H
    EXPECT_EQ(m.peek(0x1109), 0xFF);  // unmapped port E8H
    EXPECT_EQ(m.peek(0x110A), 0x12);  // PUSH B at SP = 20B0H: B at 20AFH
    EXPECT_EQ(m.peek(0x110B), 0x34);  //                      C at 20AEH
    // The two EPROM writes were ignored and counted by the bus.
    EXPECT_EQ(m.bus().rom_writes_ignored(), 2u);
    // The 8155's RAM is the chip's own (IO/M low), not a copy.
    EXPECT_EQ(m.rio().state().ram[0x00], 0x3C);
    EXPECT_EQ(m.rio().state().ram[0xFF], 0xC3);
}

TEST(BoardMaps, LoadingOffTheBoardIsRefusedAndChangesNothing) {
    Machine m;
    const std::uint8_t bytes[] = {1, 2, 3, 4};
    // 20FEH-2101H: the last two bytes fall past the 8155 RAM.
    EXPECT_THROW(m.load(0x20FE, bytes), std::out_of_range);
    EXPECT_EQ(m.peek(0x20FE), 0x00);
    EXPECT_EQ(m.peek(0x20FF), 0x00);
    m.load(0x1000, bytes);
    EXPECT_EQ(m.peek(0x1003), 4);
}

TEST(Board8279, HelloOnTheDisplay) {
    Machine m;
    boot(m, "hello.asm");
    m.run_for(ms(2));
    // 76H 79H 38H 38H 3FH then three blank digits. 3FH is also the glyph of zero, and the text
    // read-out gives digits priority.
    EXPECT_EQ(m.display_text(), "HELL0   ");
    const auto d = m.display();
    EXPECT_EQ(d[0], 0x76);
    EXPECT_EQ(d[4], 0x3F);
    EXPECT_EQ(d[7], 0x00);
}

TEST(Board8279, KeyByPollingThenByRst55) {
    Machine m;
    boot(m, "hello.asm");
    // Key 5 sits on scan row 0, return line 5; SHIFT and CNTL are grounded: FIFO entry 05H.
    m.key_at(Key::K5, true, ms(5));
    m.key_at(Key::K5, false, ms(35));
    m.run_until(ms(40));
    EXPECT_EQ(m.peek(0x1000), 0x05);
    EXPECT_EQ(m.peek(0x1002), 0x00);
    // Key A: row 1, return line 2: entry 0AH, read by the RST 5.5 routine.
    m.key_at(Key::KA, true, ms(50));
    m.key_at(Key::KA, false, ms(80));
    m.run_until(ms(90));
    EXPECT_EQ(m.peek(0x1001), 0x0A);
    EXPECT_EQ(m.peek(0x1002), 0x55);
    EXPECT_FALSE(m.kdc().irq());
}

TEST(Board8279, DebounceWindowAtPrescaler31) {
    // Prescaler 31: one digit time = 64 internal clocks = 64 x 31 = 1984 T-states; a scan of the
    // 8 rows = 15872 T-states. A key is entered when still closed two full scans after it is first
    // seen: at press + 31744 at the earliest, and one scan later at the latest.
    Machine m;
    boot(m, "hello.asm");
    const std::uint64_t press = ms(5);
    m.key_at(Key::K5, true, press);
    m.key_at(Key::K5, false, press + ms(30));
    m.run_until(press, {});
    m.run_until(press + ms(30), [&] { return m.kdc().state().fifo_count > 0 || m.peek(0x1000) != 0; });
    const std::uint64_t entered = m.now();
    EXPECT_GE(entered, press + 31744);
    EXPECT_LE(entered, press + 31744 + 15872 + 20);  // + the instruction that saw it
}

TEST(Board8279, KeyShorterThanDebounceIsNotRegistered) {
    Machine m;
    boot(m, "hello.asm");
    // Held 5 ms (15360 T-states), less than the 31744 T-states of debounce.
    m.key_at(Key::K7, true, ms(5));
    m.key_at(Key::K7, false, ms(10));
    m.run_until(ms(60));
    EXPECT_EQ(m.peek(0x1000), 0x00);
    EXPECT_EQ(m.kdc().state().fifo_count, 0);
}

TEST(Board8155, TimerTerminalCountTrapsEveryPeriod) {
    Machine m;
    boot(m, "timer.asm");
    ASSERT_EQ(m.run_to(0x0024, m.now() + ms(5)), Machine::RunEnd::Target);
    const std::uint64_t first = m.now();
    // Continuous pulse mode, count 1000: a TIMER OUT pulse, hence a TRAP edge, every 1000
    // T-states. The CPU takes the TRAP at the first instruction boundary after the edge; the
    // JMP loop's instructions are 10 T-states long, so each entry lies 0-9 T-states after its edge,
    // and the k-th entry within 10 T-states of first + 1000 k.
    for (std::uint64_t k = 1; k <= 10; ++k) {
        ASSERT_EQ(m.run_to(0x0024, m.now() + ms(5)), Machine::RunEnd::Target);
        const auto expected = static_cast<std::int64_t>(first + 1000 * k);
        EXPECT_LT(std::llabs(static_cast<std::int64_t>(m.now()) - expected), 10) << "trap " << k;
    }
    // 100 more periods: 100 more traps.
    const std::uint16_t before = static_cast<std::uint16_t>(m.peek(0x1000) | m.peek(0x1001) << 8);
    m.run_for(100'000);
    const std::uint16_t after = static_cast<std::uint16_t>(m.peek(0x1000) | m.peek(0x1001) << 8);
    EXPECT_EQ(after - before, 100);
}

// An observer that stops the run before the instruction at `pc` (a debugger's breakpoint), on
// the CPU's debug path, or on its plain path behind a fetch fence.
struct StopAt final : RunObserver {
    std::uint16_t pc = 0;
    std::optional<std::bitset<0x10000>> fence;
    bool before_instruction(const I8085& cpu) override { return cpu.regs().pc == pc; }
    const std::bitset<0x10000>* fetch_fence() const override { return fence ? &*fence : nullptr; }
};

TEST(BoardDebug, RunToStopsOnlyAtItsTargetAndKeepsTheObserver) {
    Machine m;
    const LoadedImage img = boot(m, "hello.asm");
    const std::uint16_t show = img.assembly->find_symbol("SHOW")->value;
    StopAt start;
    start.pc = 0x0040;  // START: passed on the way to SHOW, but not consulted by run_to
    m.set_observer(&start);
    ASSERT_EQ(m.run_to(show, m.now() + ms(5)), Machine::RunEnd::Target);
    EXPECT_EQ(m.cpu().regs().pc, show);
    EXPECT_EQ(m.observer(), &start);
    // A target that is never reached: the deadline ends the run.
    EXPECT_EQ(m.run_to(0x0700, m.now() + 10'000), Machine::RunEnd::Deadline);
    // The observer is consulted again for ordinary runs.
    m.reset();
    EXPECT_EQ(m.run_for(ms(5)), Machine::RunEnd::Observer);
    EXPECT_EQ(m.cpu().regs().pc, 0x0040);
    m.set_observer(nullptr);
}

// The same observer behind a fetch fence: the CPU stays on its plain path (no debug hooks) and
// the run stops at the same instruction and T-state as on the debug path.
TEST(BoardDebug, AFencedObserverStopsWhereTheDebugPathStops) {
    std::uint64_t at[2] = {};
    for (const bool fenced : {false, true}) {
        Machine m;
        const LoadedImage img = boot(m, "hello.asm");
        StopAt stop;
        stop.pc = img.assembly->find_symbol("SHOW")->value;
        if (fenced) {
            stop.fence.emplace();
            (*stop.fence)[stop.pc] = true;
        }
        m.set_observer(&stop);
        EXPECT_EQ(m.cpu().debug_hooks() == nullptr, fenced);
        EXPECT_EQ(m.cpu().fetch_fence() != nullptr, fenced);
        ASSERT_EQ(m.run_for(ms(5)), Machine::RunEnd::Observer);
        EXPECT_EQ(m.cpu().regs().pc, stop.pc);
        at[fenced] = m.now();
        m.set_observer(nullptr);
    }
    EXPECT_EQ(at[0], at[1]);
}

TEST(BoardReset, ResetKeyRestartsAtZeroAndResetsTheChips) {
    Machine m;
    boot(m, "timer.asm");
    m.run_for(ms(1));
    EXPECT_TRUE(m.rio().state().running);
    const std::uint64_t at = m.now() + 100;
    m.reset_key_at(true, at);
    m.reset_key_at(false, at + 100);
    m.run_until(at);
    // RESET IN: PC = 0000H; RESET OUT stops the 8155's timer.
    EXPECT_EQ(m.cpu().regs().pc, 0x0000);
    EXPECT_FALSE(m.rio().state().running);
    EXPECT_FALSE(m.cpu().interrupts_enabled());
}

TEST(BoardDeterminism, SameInputsSameCycles) {
    auto run = [] {
        Machine m;
        boot(m, "hello.asm");
        m.key_at(Key::K3, true, ms(7));
        m.key_at(Key::K3, false, ms(37));
        m.key_at(Key::KC, true, ms(55));
        m.key_at(Key::KC, false, ms(85));
        m.run_until(ms(100));
        return std::make_pair(m.cpu().instructions(), m.now());
    };
    EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace alp85::test

#include "emu/board/key_press.h"

namespace alp85::test {
namespace {

// Issue #10 item 6 / #11 item 12: one T-state <-> ms conversion (board_map.h, beside kCpuHz) and
// one key press (emu/board/key_press.h) for the script session and the monitor tests.
TEST(BoardTime, OneConversionAndOneKeyPress) {
    static_assert(board::tstates_from_ms(30) == 92'160);  // 30 ms x 3072 T-states per ms
    static_assert(board::tstates_from_ms(1) == 3'072);
    EXPECT_DOUBLE_EQ(board::ms_from_tstates(1'536'000), 500.0);
    EXPECT_EQ(Machine::tstates_from_ms(0.5), 1'536u);
    EXPECT_EQ(kKeyHold, 92'160u);
    Machine m;
    m.load(0x0800, std::vector<std::uint8_t>{0xC3, 0x00, 0x08});  // JMP 0800H: 10 T-states a loop
    m.cpu().regs().pc = 0x0800;
    const std::uint64_t t0 = m.now();
    press_button(m, Button::Matrix, periph::Key::K5, board::tstates_from_ms(40), board::tstates_from_ms(20));
    // 60 ms = 184320 T-states, ended on a whole instruction (a JMP: at most 10 T-states later).
    EXPECT_GE(m.now() - t0, 184'320u);
    EXPECT_LT(m.now() - t0, 184'320u + 10);
}

}  // namespace
}  // namespace alp85::test

namespace alp85::test {
namespace {

// Thesis 5.3's EPROM expansion (board::kExpansionEprom): absent on the machine as built, a 4 KB
// ROM at 3000H-3FFFH when the option is on, and carried by snapshots only then.
TEST(BoardOptions, ExpansionEpromIsOffByDefaultAndA4KRomWhenFitted) {
    Machine built;
    EXPECT_FALSE(built.expansion_eprom());
    EXPECT_EQ(built.memory_map().size(), board::kMemoryMap.size());
    const std::uint8_t code[] = {0x3E, 0x42};
    EXPECT_THROW(built.load(0x3000, code), std::out_of_range);  // no memory there
    EXPECT_EQ(built.peek(0x3000), 0xFF);

    Machine m(Machine::Options{.expansion_eprom = true});
    ASSERT_TRUE(m.expansion_eprom());
    m.load(0x3000, code);
    m.load(0x3FFE, code);
    EXPECT_EQ(m.peek(0x3000), 0x3E);
    EXPECT_EQ(m.peek(0x3FFF), 0x42);
    EXPECT_EQ(m.peek(0x4000), 0xFF);  // 4 KB exactly
    const std::uint8_t one[] = {0};
    EXPECT_THROW(m.load(0x4000, one), std::out_of_range);
    // A ROM: a CPU write is ignored. MVI A,55H / STA 3001H / HLT from RAM.
    const std::uint8_t prog[] = {0x3E, 0x55, 0x32, 0x01, 0x30, 0x76};
    m.load(0x1000, prog);
    m.cpu().regs().pc = 0x1000;
    m.run_for(1000, [&] { return m.cpu().halted(); });
    EXPECT_EQ(m.peek(0x3001), 0x42);
    EXPECT_EQ(m.bus().rom_writes_ignored(), 1u);

    // Snapshots carry it; a machine without it refuses such a snapshot.
    const auto bytes = m.snapshot_bytes();
    Machine other(Machine::Options{.expansion_eprom = true});
    other.restore_bytes(bytes);
    EXPECT_EQ(other.peek(0x3FFE), 0x3E);
    EXPECT_THROW(built.restore_bytes(bytes), snapshot::SnapshotError);

    // Removing it unmaps it; fitting it again brings back what it held.
    m.set_expansion_eprom(false);
    EXPECT_EQ(m.peek(0x3000), 0xFF);
    m.set_expansion_eprom(true);
    EXPECT_EQ(m.peek(0x3000), 0x3E);
}

}  // namespace
}  // namespace alp85::test
