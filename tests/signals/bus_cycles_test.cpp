// The bus cycles `alp85 timing` and the debugger's `timing` draw (emu/debug/bus_cycles.h), against
// the Intel 8085AH data sheet: the machine cycle types and T-states of its instruction set table,
// the status lines of its machine cycle chart (IO/M, S1, S0), and the addresses and data a hand
// trace of each instruction puts on the bus.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "emu/debug/bus_cycles.h"

namespace alp85::debug {
namespace {

using isa::MachineCycle;

struct Memory {
    std::array<std::uint8_t, 0x10000> bytes{};
    Memory() { bytes.fill(0xFF); }
    void put(std::uint16_t at, std::initializer_list<std::uint8_t> code) {
        for (std::uint8_t b : code) bytes[at++] = b;
    }
    Peek peek() const {
        return [this](std::uint16_t a) { return bytes[a]; };
    }
};

struct Expected {
    MachineCycle type;
    int tstates;
    std::uint16_t address;
    std::uint8_t data;
};

void expect_cycles(const std::vector<BusCycle>& got, const std::vector<Expected>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        SCOPED_TRACE("M" + std::to_string(i + 1));
        EXPECT_EQ(got[i].type, want[i].type);
        EXPECT_EQ(got[i].tstates, want[i].tstates);
        if (want[i].type == MachineCycle::BusIdle || want[i].type == MachineCycle::AckIdle) {
            EXPECT_FALSE(got[i].has_address);
            continue;
        }
        EXPECT_TRUE(got[i].has_address);
        EXPECT_EQ(got[i].address, want[i].address);
        EXPECT_EQ(got[i].data, want[i].data);
    }
}

Registers at(std::uint16_t pc) {
    Registers r;
    r.pc = pc;
    r.sp = 0x20C0;
    r.a = 0x5A;
    r.set_hl(0x1234);
    return r;
}

// MVI A,32H: F R, 7 T (4 + 3): the opcode from 0800H, the operand from 0801H.
TEST(BusCycles, MviIsAFetchAndARead) {
    Memory m;
    m.put(0x0800, {0x3E, 0x32});
    expect_cycles(instruction_cycles(at(0x0800), m.peek()),
                  {{MachineCycle::Fetch4, 4, 0x0800, 0x3E}, {MachineCycle::MemRead, 3, 0x0801, 0x32}});
}

// STA 2050H: F R R W, 13 T: A (5AH) written to 2050H.
TEST(BusCycles, StaWritesAToItsAddress) {
    Memory m;
    m.put(0x0800, {0x32, 0x50, 0x20});
    expect_cycles(instruction_cycles(at(0x0800), m.peek()),
                  {{MachineCycle::Fetch4, 4, 0x0800, 0x32},
                   {MachineCycle::MemRead, 3, 0x0801, 0x50},
                   {MachineCycle::MemRead, 3, 0x0802, 0x20},
                   {MachineCycle::MemWrite, 3, 0x2050, 0x5A}});
}

// CALL 0900H: S R R W W, 18 T (6 + 4 x 3): the return address 0803H pushed high byte first at
// SP-1 = 20BFH, then the low byte at 20BEH.
TEST(BusCycles, CallPushesTheReturnAddress) {
    Memory m;
    m.put(0x0800, {0xCD, 0x00, 0x09});
    expect_cycles(instruction_cycles(at(0x0800), m.peek()),
                  {{MachineCycle::Fetch6, 6, 0x0800, 0xCD},
                   {MachineCycle::MemRead, 3, 0x0801, 0x00},
                   {MachineCycle::MemRead, 3, 0x0802, 0x09},
                   {MachineCycle::MemWrite, 3, 0x20BF, 0x08},
                   {MachineCycle::MemWrite, 3, 0x20BE, 0x03}});
}

// IN 0FAH and OUT 0F9H: F R I and F R O, 10 T; the port on A15-A8 and on AD7-AD0 alike; OUT puts A
// on the bus, IN's byte is the device's (not known here).
TEST(BusCycles, InAndOutAddressThePortTwice) {
    Memory m;
    m.put(0x0800, {0xDB, 0xFA});
    const auto in = instruction_cycles(at(0x0800), m.peek());
    expect_cycles({in[0], in[1]}, {{MachineCycle::Fetch4, 4, 0x0800, 0xDB}, {MachineCycle::MemRead, 3, 0x0801, 0xFA}});
    ASSERT_EQ(in.size(), 3u);
    EXPECT_EQ(in[2].type, MachineCycle::IoRead);
    EXPECT_EQ(in[2].tstates, 3);
    EXPECT_EQ(in[2].address, 0xFAFA);
    EXPECT_FALSE(in[2].has_data);

    m.put(0x0900, {0xD3, 0xF9});
    expect_cycles(instruction_cycles(at(0x0900), m.peek()),
                  {{MachineCycle::Fetch4, 4, 0x0900, 0xD3},
                   {MachineCycle::MemRead, 3, 0x0901, 0xF9},
                   {MachineCycle::IoWrite, 3, 0xF9F9, 0x5A}});
}

// DAD B: F B B, 10 T: two bus idle cycles, no address, no strobe.
TEST(BusCycles, DadIdlesTheBusTwice) {
    Memory m;
    m.put(0x0800, {0x09});
    const auto c = instruction_cycles(at(0x0800), m.peek());
    expect_cycles(c, {{MachineCycle::Fetch4, 4, 0x0800, 0x09}, {MachineCycle::BusIdle, 3, 0, 0}, {MachineCycle::BusIdle, 3, 0, 0}});
    const BusStatus s = bus_status(MachineCycle::BusIdle);
    EXPECT_FALSE(s.rd || s.wr || s.inta || s.ale);
}

// RST 7.5 acknowledged before the instruction at 0850H: a 6 T bus idle with IO/M = 1, S1 S0 = 1 1
// and no INTA (the data sheet's "ACK. OF RST, TRAP"), then the PC pushed: 12 T (isa.h's RST).
TEST(BusCycles, Rst75AcknowledgeHasNoInta) {
    const auto c = restart_ack_cycles(at(0x0850));
    expect_cycles(c, {{MachineCycle::AckIdle, 6, 0, 0},
                      {MachineCycle::MemWrite, 3, 0x20BF, 0x08},
                      {MachineCycle::MemWrite, 3, 0x20BE, 0x50}});
    const BusStatus s = bus_status(MachineCycle::AckIdle);
    EXPECT_EQ(s.io_m, '1');
    EXPECT_EQ(s.s1, '1');
    EXPECT_EQ(s.s0, '1');
    EXPECT_FALSE(s.inta || s.rd || s.wr);
}

// Jcc and Ccc as their flags say: JNZ not taken (Z set) is F R, 7 T; CNZ taken (Z clear) S R R W W.
TEST(BusCycles, ConditionalsFollowTheFlags) {
    Memory m;
    m.put(0x0800, {0xC2, 0x00, 0x09});
    Registers r = at(0x0800);
    r.f = 0x40;  // Z
    EXPECT_EQ(instruction_cycles(r, m.peek()).size(), 2u);
    m.put(0x0800, {0xC4, 0x00, 0x09});
    r.f = 0x00;
    EXPECT_EQ(instruction_cycles(r, m.peek()).size(), 5u);
}

// The data sheet's machine cycle chart: status per cycle type.
TEST(BusCycles, StatusLines) {
    auto status = [](MachineCycle c) {
        const BusStatus s = bus_status(c);
        return std::string{s.io_m, s.s1, s.s0};
    };
    EXPECT_EQ(status(MachineCycle::Fetch4), "011");
    EXPECT_EQ(status(MachineCycle::MemRead), "010");
    EXPECT_EQ(status(MachineCycle::MemWrite), "001");
    EXPECT_EQ(status(MachineCycle::IoRead), "110");
    EXPECT_EQ(status(MachineCycle::IoWrite), "101");
    EXPECT_EQ(status(MachineCycle::IntAck), "111");
    EXPECT_EQ(status(MachineCycle::Halt), "z00");
}

// The waveforms of STA: ALE high in the first half of each T1 only, RD low in T2-T3 of the three
// reads, WR low in T2-T3 of the write, the address low byte on AD7-AD0 in T1 and A on it while WR is low.
TEST(BusCycles, StaWaveforms) {
    Memory m;
    m.put(0x0800, {0x32, 0x50, 0x20});
    const Waveforms w = waveforms(instruction_cycles(at(0x0800), m.peek()));
    ASSERT_EQ(w.half_tstates, 26);
    auto row = [&](const std::string& name) {
        for (std::size_t i = 0; i < w.names.size(); ++i)
            if (w.names[i] == name) return w.levels[i];
        return std::string();
    };
    //                        T1T2T3T4|T1T2T3|T1T2T3|T1T2T3
    EXPECT_EQ(row("ALE"),  "10000000" "100000" "100000" "100000");
    EXPECT_EQ(row("RD"),   "11000011" "110000" "110000" "111111");
    EXPECT_EQ(row("WR"),   "11111111" "111111" "111111" "110000");
    EXPECT_EQ(row("CLK"),  "10101010" "101010" "101010" "101010");
    EXPECT_EQ(w.bus_low[20], 0x50);  // M4 T1: the address 2050H's low byte
    EXPECT_EQ(w.bus_high[20], 0x20);
    EXPECT_EQ(w.bus_low[22], 0x5A);  // M4 T2: A
    EXPECT_EQ(w.bus_low[25], 0x5A);
}

}  // namespace
}  // namespace alp85::debug
