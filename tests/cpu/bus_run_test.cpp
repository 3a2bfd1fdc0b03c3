// The bus (page table, ROM, unmapped, device pages, ports) and the run API (deadlines, stop
// requests from handlers, counters, debug hooks, determinism).
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "tests/cpu/rig.h"

namespace alp85::test {
namespace {

TEST(Bus, UnmappedReadsFloatHighAndWritesAreCounted) {
    Bus bus;
    EXPECT_EQ(bus.read(0x1234, 0), 0xFF);
    EXPECT_EQ(bus.page_kind(0x1234), Bus::PageKind::Unmapped);
    bus.write(0x1234, 0x00, 0);
    EXPECT_EQ(bus.read(0x1234, 0), 0xFF);
    EXPECT_EQ(bus.unmapped_writes_ignored(), 1u);
}

TEST(Bus, RomIgnoresAndCountsWrites) {
    std::vector<std::uint8_t> rom(0x800, 0xA5);
    Bus bus;
    bus.map_rom(0x0000, 0x800, rom.data());
    EXPECT_EQ(bus.read(0x07FF, 0), 0xA5);
    bus.write(0x0010, 0x00, 0);
    EXPECT_EQ(rom[0x10], 0xA5);
    EXPECT_EQ(bus.rom_writes_ignored(), 1u);
    EXPECT_FALSE(bus.poke(0x0010, 0));
    EXPECT_EQ(bus.read(0x0800, 0), 0xFF);  // beyond the ROM: unmapped
}

TEST(Bus, CpuStoreToRomIsIgnored) {
    std::vector<std::uint8_t> rom(0x100, 0x00), ram(0x100, 0x00);
    Bus bus;
    bus.map_rom(0x0000, 0x100, rom.data());
    bus.map_ram(0x1000, 0x100, ram.data());
    rom[0] = 0x32, rom[1] = 0x10, rom[2] = 0x00;  // STA 0010H (into the ROM)
    rom[3] = 0x32, rom[4] = 0x10, rom[5] = 0x10;  // STA 1010H
    I8085 cpu(bus);
    cpu.regs().a = 0x42;
    cpu.step();
    cpu.step();
    EXPECT_EQ(rom[0x10], 0x00);
    EXPECT_EQ(ram[0x10], 0x42);
    EXPECT_EQ(bus.rom_writes_ignored(), 1u);
}

TEST(Bus, RejectsPartialPages) {
    Bus bus;
    std::vector<std::uint8_t> mem(0x100);
    EXPECT_THROW(bus.map_ram(0x0080, 0x100, mem.data()), std::invalid_argument);
    EXPECT_THROW(bus.map_ram(0xFF00, 0x200, mem.data()), std::invalid_argument);
}

// A memory-mapped device page that records accesses with their T-states.
struct Recorder : MemoryDevice {
    std::vector<std::uint64_t> read_t, write_t;
    std::vector<std::uint16_t> write_addr;
    std::uint8_t value = 0x5C;
    std::uint8_t read(std::uint16_t, std::uint64_t t) override {
        read_t.push_back(t);
        return value;
    }
    void write(std::uint16_t addr, std::uint8_t v, std::uint64_t t) override {
        write_t.push_back(t);
        write_addr.push_back(addr);
        value = v;
    }
    std::uint8_t peek(std::uint16_t) const override { return value; }
};

TEST(Bus, DevicePageSeesAccessesWithTheirTstate) {
    Rig rig;
    Recorder dev;
    rig.bus.map_device(0x2000, 0x100, dev);
    rig.load(0x0100, {0x3A, 0x05, 0x20,    // LDA 2005H   (13: read at T-state 10)
                      0x32, 0x06, 0x20});  // STA 2006H   (13: write at T-state 23)
    rig.r().pc = 0x0100;
    rig.cpu.run(26);
    EXPECT_EQ(rig.r().a, 0x5C);
    EXPECT_EQ(dev.read_t, (std::vector<std::uint64_t>{10}));
    EXPECT_EQ(dev.write_t, (std::vector<std::uint64_t>{23}));
    EXPECT_EQ(dev.write_addr, (std::vector<std::uint16_t>{0x2006}));
    EXPECT_EQ(rig.bus.peek(0x2000), 0x5C);
}

TEST(Run, WholeInstructionsUpToTheDeadline) {
    Rig rig;
    rig.load(0x0000, {0x00, 0x00, 0x00});  // NOP NOP NOP
    EXPECT_EQ(rig.cpu.run(5), 8u);          // the second NOP starts before 5 and finishes
    EXPECT_EQ(rig.cpu.instructions(), 2u);
    EXPECT_EQ(rig.cpu.run(8), 0u);          // already there
    EXPECT_EQ(rig.cpu.tstates(), 8u);
}

TEST(Run, HandlerCanShortenTheBatch) {
    Rig rig;
    IoFunctions io;
    io.on_out = [&](std::uint8_t, std::uint8_t, std::uint64_t t) { rig.cpu.stop_at(t); };
    rig.bus.map_io(0x20, 0x20, io);
    rig.load(0x0000, {0x00, 0xD3, 0x20, 0x00, 0x00});  // NOP; OUT 20H; NOP; NOP
    EXPECT_EQ(rig.cpu.run(1000000), 14u);                // stops after the OUT
    EXPECT_EQ(rig.r().pc, 0x0003);
}

TEST(Run, StepExecutesOneInstruction) {
    Rig rig;
    rig.load(0x0000, {0x3E, 0x12, 0x47});  // MVI A,12H; MOV B,A
    EXPECT_EQ(rig.cpu.step(), 7u);
    EXPECT_EQ(rig.r().a, 0x12);
    EXPECT_EQ(rig.r().b, 0x00);
    EXPECT_EQ(rig.cpu.step(), 4u);
    EXPECT_EQ(rig.r().b, 0x12);
    EXPECT_EQ(rig.cpu.instructions(), 2u);
}

// The 1 ms delay loop of the thesis firmware's kind: MVI B,n / loop: DCR B; JNZ loop.
// 8085: MVI 7, then n-1 times DCR 4 + JNZ taken 10, and DCR 4 + JNZ untaken 7.
TEST(Run, DelayLoopTiming) {
    Rig rig;
    rig.load(0x0000, {0x06, 0xC8,         // MVI B,200
                      0x05,               // DCR B
                      0xC2, 0x02, 0x00,   // JNZ 0002H
                      0x76});             // HLT
    rig.cpu.on_halt = [&] { rig.cpu.request_stop(); };
    rig.cpu.run(1000000);
    EXPECT_EQ(rig.cpu.tstates(), 7u + 199 * 14 + 11 + 5);
    EXPECT_EQ(rig.cpu.instructions(), 1u + 400 + 1);
}

TEST(Run, DelayLoopTiming8080) {
    Rig rig(Variant::I8080);
    rig.load(0x0000, {0x06, 0xC8, 0x05, 0xC2, 0x02, 0x00, 0x76});
    rig.cpu.on_halt = [&] { rig.cpu.request_stop(); };
    rig.cpu.run(1000000);
    EXPECT_EQ(rig.cpu.tstates(), 7u + 200 * 15 + 7);  // DCR 5 + JNZ 10 either way; HLT 7
}

// Debugger hooks: stop before an address, watch a write, and the same results as the plain path.
struct Hooks : DebugHooks {
    std::uint16_t break_at = 0xFFFF;
    std::vector<std::uint16_t> writes;
    unsigned count = 0;
    bool before_instruction(I8085& cpu) override {
        ++count;
        return cpu.regs().pc != break_at;
    }
    void on_write(I8085&, std::uint16_t addr, std::uint8_t) override { writes.push_back(addr); }
};

TEST(Debug, BreakpointStopsBeforeTheInstruction) {
    Rig rig;
    rig.load(0x0000, {0x00, 0x00, 0x32, 0x00, 0x30, 0x00});  // NOP NOP STA 3000H NOP
    Hooks hooks;
    hooks.break_at = 0x0002;
    rig.cpu.set_debug_hooks(&hooks);
    rig.cpu.run(1000);
    EXPECT_EQ(rig.r().pc, 0x0002);
    EXPECT_EQ(rig.cpu.tstates(), 8u);
    hooks.break_at = 0xFFFF;
    rig.cpu.step();
    EXPECT_EQ(hooks.writes, (std::vector<std::uint16_t>{0x3000}));
}

TEST(Debug, DebugPathMatchesPlainPath) {
    // A loop with memory traffic; both paths must end in the same state at the same T-state.
    auto program = [](Rig& rig) {
        rig.load(0x0000, {0x21, 0x00, 0x30,   // LXI H,3000H
                          0x0E, 0x40,         // MVI C,64
                          0x71,               // MOV M,C
                          0x23,               // INX H
                          0xE5, 0xE1,         // PUSH H; POP H
                          0x0D,               // DCR C
                          0xC2, 0x05, 0x00,   // JNZ 0005H
                          0x76});
        rig.cpu.on_halt = [&rig] { rig.cpu.request_stop(); };
    };
    Rig plain, debug;
    program(plain);
    program(debug);
    Hooks hooks;
    debug.cpu.set_debug_hooks(&hooks);
    plain.cpu.run(100000);
    debug.cpu.run(100000);
    EXPECT_EQ(plain.cpu.tstates(), debug.cpu.tstates());
    EXPECT_EQ(plain.cpu.instructions(), debug.cpu.instructions());
    EXPECT_EQ(plain.r().hl(), debug.r().hl());
    EXPECT_EQ(plain.ram, debug.ram);
    EXPECT_EQ(hooks.count, debug.cpu.instructions());
    EXPECT_EQ(hooks.writes.size(), 64u * 3);
}

TEST(Determinism, TwoRunsGiveIdenticalCounters) {
    auto run = [] {
        Rig rig;
        // CRC-8-like loop over 256 bytes of RAM, then HLT.
        rig.load(0x0000, {0x21, 0x00, 0x10, 0x06, 0x00, 0xAF,  // LXI H; MVI B,0; XRA A
                          0xAE, 0x07, 0xD2, 0x0D, 0x00, 0xEE, 0x07,  // XRA M; RLC; JNC +; XRI 07H
                          0x23, 0x05, 0xC2, 0x06, 0x00, 0x76});      // INX H; DCR B; JNZ; HLT
        for (unsigned i = 0; i < 256; ++i) rig.ram[0x1000 + i] = static_cast<std::uint8_t>(i * 7);
        rig.cpu.on_halt = [&rig] { rig.cpu.request_stop(); };
        rig.cpu.run(10'000'000);
        return std::tuple{rig.cpu.instructions(), rig.cpu.tstates(), rig.r().a};
    };
    EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace alp85::test
