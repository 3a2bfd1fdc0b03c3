// asm/isa_cycles.h: every opcode's machine cycles against asm/isa.h's T-states and against the
// core, which counts them (taken and not taken); and the data sheet's sequences for a few.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "asm/isa.h"
#include "asm/isa_cycles.h"
#include "tests/cpu/rig.h"

namespace alp85 {
namespace {

using isa::MachineCycle;

std::string letters(const isa::CycleList& l) {
    std::string s;
    for (int i = 0; i < l.count; ++i) {
        static constexpr char kLetter[] = "FSRWIOBHNA";
        s += (s.empty() ? "" : " ") + std::string(1, kLetter[static_cast<int>(l.cycles[static_cast<std::size_t>(i)])]);
    }
    return s;
}

TEST(IsaCycles, EveryOpcodeAddsUpToItsTStates) {
    for (int op = 0; op < 256; ++op) {
        const isa::OpInfo& info = isa::kOpcodes[static_cast<std::size_t>(op)];
        const isa::CycleList nt = isa::cycles_of(static_cast<std::uint8_t>(op), false);
        const isa::CycleList tk = isa::cycles_of(static_cast<std::uint8_t>(op), true);
        SCOPED_TRACE(fmt::format("{:02X}H {} {}", op, info.mnemonic, info.operands));
        EXPECT_EQ(nt.tstates, info.t8085);
        EXPECT_EQ(tk.tstates, info.t8085_taken);
        // Every instruction starts with its opcode fetch, and only there.
        for (const isa::CycleList* l : {&nt, &tk}) {
            ASSERT_GE(l->count, 1);
            EXPECT_TRUE(l->cycles[0] == MachineCycle::Fetch4 || l->cycles[0] == MachineCycle::Fetch6);
            for (int i = 1; i < l->count; ++i) {
                EXPECT_NE(l->cycles[static_cast<std::size_t>(i)], MachineCycle::Fetch4);
                EXPECT_NE(l->cycles[static_cast<std::size_t>(i)], MachineCycle::Fetch6);
            }
        }
        // An instruction reads at least as many bytes after its opcode as it is long.
        const auto reads = std::count(tk.cycles.begin(), tk.cycles.begin() + tk.count, MachineCycle::MemRead);
        EXPECT_GE(reads, info.length - 1);
    }
}

// The core counts each opcode's T-states: run once with every flag clear and once with every flag
// set; a conditional instruction is taken in one of the two runs and not in the other.
TEST(IsaCycles, TheCoreTakesEachOpcodesTStates) {
    for (int op = 0; op < 256; ++op) {
        const isa::OpInfo& info = isa::kOpcodes[static_cast<std::size_t>(op)];
        SCOPED_TRACE(fmt::format("{:02X}H {} {}", op, info.mnemonic, info.operands));
        std::uint64_t t[2];
        for (int set = 0; set < 2; ++set) {
            test::Rig rig;
            rig.r().f = set ? 0xFF : 0x00;
            rig.r().set_hl(0x2000);
            t[set] = rig.exec({static_cast<std::uint8_t>(op), 0x00, 0x30});
        }
        const int nt = isa::cycles_of(static_cast<std::uint8_t>(op), false).tstates;
        const int tk = isa::cycles_of(static_cast<std::uint8_t>(op), true).tstates;
        EXPECT_EQ(std::min(t[0], t[1]), static_cast<std::uint64_t>(std::min(nt, tk)));
        EXPECT_EQ(std::max(t[0], t[1]), static_cast<std::uint64_t>(std::max(nt, tk)));
    }
}

// Intel 8085AH data sheet, instruction set table: machine cycles and T-states.
TEST(IsaCycles, DataSheetSequences) {
    auto seq = [](std::uint8_t op, bool taken = true) { return letters(isa::cycles_of(op, taken)); };
    EXPECT_EQ(seq(0x3E), "F R");            // MVI A,d8: 7 T
    EXPECT_EQ(seq(0x36), "F R W");          // MVI M,d8: 10 T
    EXPECT_EQ(seq(0x32), "F R R W");        // STA a16: 13 T
    EXPECT_EQ(seq(0x3A), "F R R R");        // LDA a16: 13 T
    EXPECT_EQ(seq(0xCD), "S R R W W");      // CALL a16: 18 T
    EXPECT_EQ(seq(0xC4, false), "S R");     // CNZ not taken: 9 T
    EXPECT_EQ(seq(0xC2, false), "F R");     // JNZ not taken: 7 T
    EXPECT_EQ(seq(0xC0, true), "S R R");    // RNZ taken: 12 T
    EXPECT_EQ(seq(0xDB), "F R I");          // IN p8: 10 T
    EXPECT_EQ(seq(0xD3), "F R O");          // OUT p8: 10 T
    EXPECT_EQ(seq(0x09), "F B B");          // DAD B: 10 T
    EXPECT_EQ(seq(0xE3), "F R R W W");      // XTHL: 16 T
    EXPECT_EQ(seq(0xF5), "S W W");          // PUSH PSW: 12 T
    EXPECT_EQ(seq(0x76), "F H");            // HLT: 5 T
    EXPECT_EQ(letters(isa::parse_cycles(isa::kAckRst)), "A W W");  // RST 7.5 acknowledge: 12 T
    EXPECT_EQ(isa::parse_cycles(isa::kAckRst).tstates, 12);
}

}  // namespace
}  // namespace alp85
