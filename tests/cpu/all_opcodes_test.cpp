// Every one of the 256 opcodes, in each variant, executed once from a known state: its T-states
// and length checked against timing rules written out here by instruction group, straight from
// the 8085A and 8080A data sheets (independently of asm/isa.h, which the core's tables come from).
#include <gtest/gtest.h>

#include "tests/cpu/rig.h"

namespace alp85::test {
namespace {

struct Expect {
    unsigned t;       // T-states with all flags clear (NZ, NC, PO, P true; Z, C, PE, M false)
    unsigned length;  // bytes, for opcodes that do not branch
    bool branches;    // PC goes elsewhere with all flags clear
};

Expect expect_8085(unsigned op) {
    const unsigned hi = op >> 6, mid = (op >> 3) & 7, lo = op & 7;
    if (op == 0x76) return {5, 1, false};  // HLT
    if (hi == 1) return {(mid == 6 || lo == 6) ? 7u : 4u, 1, false};  // MOV
    if (hi == 2) return {lo == 6 ? 7u : 4u, 1, false};                // ALU r/M
    if (hi == 0) {
        switch (lo) {
            case 0:  // NOP RIM SIM; DSUB ARHL RDEL LDHI LDSI
                switch (mid) {
                    case 0: case 4: case 6: return {4, 1, false};
                    case 1: return {10, 1, false};  // DSUB
                    case 2: return {7, 1, false};   // ARHL
                    case 3: return {10, 1, false};  // RDEL
                    default: return {10, 2, false}; // LDHI, LDSI
                }
            case 1: return mid & 1 ? Expect{10, 1, false} : Expect{10, 3, false};  // DAD / LXI
            case 2:
                if (mid < 4) return {7, 1, false};                                 // STAX/LDAX
                return {(mid == 4 || mid == 5) ? 16u : 13u, 3, false};             // SHLD LHLD STA LDA
            case 3: return {6, 1, false};                                          // INX/DCX
            case 4: case 5: return {mid == 6 ? 10u : 4u, 1, false};                // INR/DCR
            case 6: return {mid == 6 ? 10u : 7u, 2, false};                        // MVI
            default: return {4, 1, false};                                         // rotates DAA CMA STC CMC
        }
    }
    // hi == 3
    const bool cond_true = (mid & 1) == 0;  // NZ NC PO P are true with flags clear
    switch (lo) {
        case 0: return cond_true ? Expect{12, 1, true} : Expect{6, 1, false};  // Rcc
        case 1:
            if (mid == 1) return {10, 1, true};  // RET
            if (mid == 3) return {10, 1, false}; // SHLX
            if (mid == 5) return {6, 1, true};   // PCHL
            if (mid == 7) return {6, 1, false};  // SPHL
            return {10, 1, false};               // POP
        case 2: return cond_true ? Expect{10, 3, true} : Expect{7, 3, false};  // Jcc
        case 3:
            switch (mid) {
                case 0: return {10, 3, true};    // JMP
                case 1: return {6, 1, false};    // RSTV, V clear
                case 2: case 3: return {10, 2, false};  // OUT IN
                case 4: return {16, 1, false};   // XTHL
                case 5: return {4, 1, false};    // XCHG
                default: return {4, 1, false};   // DI EI
            }
        case 4: return cond_true ? Expect{18, 3, true} : Expect{9, 3, false};  // Ccc
        case 5:
            if (mid == 1) return {18, 3, true};  // CALL
            if (mid == 3) return {10, 3, true};  // JNK, K clear: taken
            if (mid == 5) return {10, 1, false}; // LHLX
            if (mid == 7) return {7, 3, false};  // JK, K clear: not taken
            return {12, 1, false};               // PUSH
        case 6: return {7, 2, false};            // ALU immediate
        default: return {12, 1, true};           // RST
    }
}

Expect expect_8080(unsigned op) {
    const unsigned hi = op >> 6, mid = (op >> 3) & 7, lo = op & 7;
    if (op == 0x76) return {7, 1, false};
    if (hi == 1) return {(mid == 6 || lo == 6) ? 7u : 5u, 1, false};
    if (hi == 2) return {lo == 6 ? 7u : 4u, 1, false};
    if (hi == 0) {
        switch (lo) {
            case 0: return {4, 1, false};  // NOP and its seven undocumented copies
            case 1: return mid & 1 ? Expect{10, 1, false} : Expect{10, 3, false};
            case 2:
                if (mid < 4) return {7, 1, false};
                return {(mid == 4 || mid == 5) ? 16u : 13u, 3, false};
            case 3: return {5, 1, false};
            case 4: case 5: return {mid == 6 ? 10u : 5u, 1, false};
            case 6: return {mid == 6 ? 10u : 7u, 2, false};
            default: return {4, 1, false};
        }
    }
    const bool cond_true = (mid & 1) == 0;
    switch (lo) {
        case 0: return cond_true ? Expect{11, 1, true} : Expect{5, 1, false};
        case 1:
            if (mid == 1 || mid == 3) return {10, 1, true};  // RET, and D9 is RET too
            if (mid == 5) return {5, 1, true};
            if (mid == 7) return {5, 1, false};
            return {10, 1, false};
        case 2: return cond_true ? Expect{10, 3, true} : Expect{10, 3, false};
        case 3:
            switch (mid) {
                case 0: case 1: return {10, 3, true};  // JMP, and CB is JMP too
                case 2: case 3: return {10, 2, false};
                case 4: return {18, 1, false};
                case 5: return {4, 1, false};
                default: return {4, 1, false};
            }
        case 4: return cond_true ? Expect{17, 3, true} : Expect{11, 3, false};
        case 5: return mid & 1 ? Expect{17, 3, true} : Expect{11, 1, false};  // CALL (CD DD ED FD) / PUSH
        case 6: return {7, 2, false};
        default: return {11, 1, true};
    }
}

void sweep(Variant v) {
    for (unsigned op = 0; op < 256; ++op) {
        Rig rig(v);
        Registers& r = rig.r();
        r.f = rig.flags(0);
        r.set_bc(0x2000), r.set_de(0x2100), r.set_hl(0x2200), r.sp = 0x3000;
        rig.ram[0x3000] = 0x00, rig.ram[0x3001] = 0x40;  // a return address on the stack: 4000H
        const Expect e = v == Variant::I8085 ? expect_8085(op) : expect_8080(op);
        const std::uint64_t t = rig.exec({static_cast<std::uint8_t>(op), 0x00, 0x50});
        EXPECT_EQ(t, e.t) << "opcode " << std::hex << op;
        EXPECT_EQ(rig.cpu.instructions(), 1u) << "opcode " << std::hex << op;
        if (!e.branches) {
            EXPECT_EQ(r.pc, 0x0100 + e.length) << "opcode " << std::hex << op;
        } else {
            EXPECT_NE(r.pc, 0x0100 + e.length) << "opcode " << std::hex << op;
        }
    }
}

TEST(AllOpcodes, Every8085OpcodeTimingAndLength) { sweep(Variant::I8085); }
TEST(AllOpcodes, Every8080OpcodeTimingAndLength) { sweep(Variant::I8080); }

}  // namespace
}  // namespace alp85::test
