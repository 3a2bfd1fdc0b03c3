// The machine cycles of every 8085 opcode, as the Intel 8085AH data sheet's instruction set table
// (and the MCS-80/85 Family User's Manual, 1983, chapter 5) lists them: one entry per opcode,
// parallel to isa.h's kOpcodes, read by `alp85 timing` and the debugger's `timing`.
//
// Letters, each one machine cycle (the data sheet's names and T-states):
//   F  opcode fetch, 4 T (T1-T4)          S  opcode fetch, 6 T (T1-T6)
//   R  memory read, 3 T                   W  memory write, 3 T
//   I  I/O read, 3 T                      O  I/O write, 3 T
//   B  bus idle, 3 T (DAD's two, the undocumented DSUB, ARHL, RDEL, LDHI, LDSI)
//   H  HLT's halt state after its fetch: 1 T (the data sheet's 5 T for HLT), bus floating
// A conditional instruction has two sequences: condition false, then true (isa.h's t8085 and
// t8085_taken); an unconditional one repeats its sequence. The interrupt acknowledges are the
// CPU's, not an opcode's (kAckRst75 and the others below).
//
// The ten undocumented 8085 instructions are not in Intel's table: their T-states are isa.h's
// (docs/cpu.md), split into the cycles of the documented instruction of the same shape (DSUB and
// RDEL as DAD, ARHL a fetch and one idle cycle, LDHI/LDSI a fetch, an operand read and an idle
// cycle, SHLX as PUSH's writes after a 4 T fetch, LHLX as POP's reads, JNK/JK as Jcc, RSTV as RST
// when taken).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace alp85::isa {

enum class MachineCycle : std::uint8_t {
    Fetch4,    // F
    Fetch6,    // S
    MemRead,   // R
    MemWrite,  // W
    IoRead,    // I
    IoWrite,   // O
    BusIdle,   // B
    Halt,      // H
    IntAck,    // INTA cycle of an INTR acknowledge: RST n read from the bus, 6 T (status 1 1 1, INTA low)
    AckIdle,   // RST 5.5/6.5/7.5 and TRAP: a 6 T bus idle with status 1 1 1 and no INTA
};

constexpr int tstates_of(MachineCycle c) {
    switch (c) {
        case MachineCycle::Fetch4: return 4;
        case MachineCycle::Fetch6:
        case MachineCycle::IntAck:
        case MachineCycle::AckIdle: return 6;
        case MachineCycle::Halt: return 1;
        default: return 3;
    }
}

struct CycleEntry {
    std::string_view not_taken;  // condition false (or the only sequence)
    std::string_view taken;      // condition true
};

// clang-format off
inline constexpr std::array<CycleEntry, 256> kCycles{{
    {"F", "F"},  // 00 NOP
    {"F R R", "F R R"},  // 01 LXI B,d16
    {"F W", "F W"},  // 02 STAX B
    {"S", "S"},  // 03 INX B
    {"F", "F"},  // 04 INR B
    {"F", "F"},  // 05 DCR B
    {"F R", "F R"},  // 06 MVI B,d8
    {"F", "F"},  // 07 RLC
    {"F B B", "F B B"},  // 08 DSUB
    {"F B B", "F B B"},  // 09 DAD B
    {"F R", "F R"},  // 0A LDAX B
    {"S", "S"},  // 0B DCX B
    {"F", "F"},  // 0C INR C
    {"F", "F"},  // 0D DCR C
    {"F R", "F R"},  // 0E MVI C,d8
    {"F", "F"},  // 0F RRC
    {"F B", "F B"},  // 10 ARHL
    {"F R R", "F R R"},  // 11 LXI D,d16
    {"F W", "F W"},  // 12 STAX D
    {"S", "S"},  // 13 INX D
    {"F", "F"},  // 14 INR D
    {"F", "F"},  // 15 DCR D
    {"F R", "F R"},  // 16 MVI D,d8
    {"F", "F"},  // 17 RAL
    {"F B B", "F B B"},  // 18 RDEL
    {"F B B", "F B B"},  // 19 DAD D
    {"F R", "F R"},  // 1A LDAX D
    {"S", "S"},  // 1B DCX D
    {"F", "F"},  // 1C INR E
    {"F", "F"},  // 1D DCR E
    {"F R", "F R"},  // 1E MVI E,d8
    {"F", "F"},  // 1F RAR
    {"F", "F"},  // 20 RIM
    {"F R R", "F R R"},  // 21 LXI H,d16
    {"F R R W W", "F R R W W"},  // 22 SHLD a16
    {"S", "S"},  // 23 INX H
    {"F", "F"},  // 24 INR H
    {"F", "F"},  // 25 DCR H
    {"F R", "F R"},  // 26 MVI H,d8
    {"F", "F"},  // 27 DAA
    {"F R B", "F R B"},  // 28 LDHI d8
    {"F B B", "F B B"},  // 29 DAD H
    {"F R R R R", "F R R R R"},  // 2A LHLD a16
    {"S", "S"},  // 2B DCX H
    {"F", "F"},  // 2C INR L
    {"F", "F"},  // 2D DCR L
    {"F R", "F R"},  // 2E MVI L,d8
    {"F", "F"},  // 2F CMA
    {"F", "F"},  // 30 SIM
    {"F R R", "F R R"},  // 31 LXI SP,d16
    {"F R R W", "F R R W"},  // 32 STA a16
    {"S", "S"},  // 33 INX SP
    {"F R W", "F R W"},  // 34 INR M
    {"F R W", "F R W"},  // 35 DCR M
    {"F R W", "F R W"},  // 36 MVI M,d8
    {"F", "F"},  // 37 STC
    {"F R B", "F R B"},  // 38 LDSI d8
    {"F B B", "F B B"},  // 39 DAD SP
    {"F R R R", "F R R R"},  // 3A LDA a16
    {"S", "S"},  // 3B DCX SP
    {"F", "F"},  // 3C INR A
    {"F", "F"},  // 3D DCR A
    {"F R", "F R"},  // 3E MVI A,d8
    {"F", "F"},  // 3F CMC
    {"F", "F"},  // 40 MOV B,B
    {"F", "F"},  // 41 MOV B,C
    {"F", "F"},  // 42 MOV B,D
    {"F", "F"},  // 43 MOV B,E
    {"F", "F"},  // 44 MOV B,H
    {"F", "F"},  // 45 MOV B,L
    {"F R", "F R"},  // 46 MOV B,M
    {"F", "F"},  // 47 MOV B,A
    {"F", "F"},  // 48 MOV C,B
    {"F", "F"},  // 49 MOV C,C
    {"F", "F"},  // 4A MOV C,D
    {"F", "F"},  // 4B MOV C,E
    {"F", "F"},  // 4C MOV C,H
    {"F", "F"},  // 4D MOV C,L
    {"F R", "F R"},  // 4E MOV C,M
    {"F", "F"},  // 4F MOV C,A
    {"F", "F"},  // 50 MOV D,B
    {"F", "F"},  // 51 MOV D,C
    {"F", "F"},  // 52 MOV D,D
    {"F", "F"},  // 53 MOV D,E
    {"F", "F"},  // 54 MOV D,H
    {"F", "F"},  // 55 MOV D,L
    {"F R", "F R"},  // 56 MOV D,M
    {"F", "F"},  // 57 MOV D,A
    {"F", "F"},  // 58 MOV E,B
    {"F", "F"},  // 59 MOV E,C
    {"F", "F"},  // 5A MOV E,D
    {"F", "F"},  // 5B MOV E,E
    {"F", "F"},  // 5C MOV E,H
    {"F", "F"},  // 5D MOV E,L
    {"F R", "F R"},  // 5E MOV E,M
    {"F", "F"},  // 5F MOV E,A
    {"F", "F"},  // 60 MOV H,B
    {"F", "F"},  // 61 MOV H,C
    {"F", "F"},  // 62 MOV H,D
    {"F", "F"},  // 63 MOV H,E
    {"F", "F"},  // 64 MOV H,H
    {"F", "F"},  // 65 MOV H,L
    {"F R", "F R"},  // 66 MOV H,M
    {"F", "F"},  // 67 MOV H,A
    {"F", "F"},  // 68 MOV L,B
    {"F", "F"},  // 69 MOV L,C
    {"F", "F"},  // 6A MOV L,D
    {"F", "F"},  // 6B MOV L,E
    {"F", "F"},  // 6C MOV L,H
    {"F", "F"},  // 6D MOV L,L
    {"F R", "F R"},  // 6E MOV L,M
    {"F", "F"},  // 6F MOV L,A
    {"F W", "F W"},  // 70 MOV M,B
    {"F W", "F W"},  // 71 MOV M,C
    {"F W", "F W"},  // 72 MOV M,D
    {"F W", "F W"},  // 73 MOV M,E
    {"F W", "F W"},  // 74 MOV M,H
    {"F W", "F W"},  // 75 MOV M,L
    {"F H", "F H"},  // 76 HLT
    {"F W", "F W"},  // 77 MOV M,A
    {"F", "F"},  // 78 MOV A,B
    {"F", "F"},  // 79 MOV A,C
    {"F", "F"},  // 7A MOV A,D
    {"F", "F"},  // 7B MOV A,E
    {"F", "F"},  // 7C MOV A,H
    {"F", "F"},  // 7D MOV A,L
    {"F R", "F R"},  // 7E MOV A,M
    {"F", "F"},  // 7F MOV A,A
    {"F", "F"},  // 80 ADD B
    {"F", "F"},  // 81 ADD C
    {"F", "F"},  // 82 ADD D
    {"F", "F"},  // 83 ADD E
    {"F", "F"},  // 84 ADD H
    {"F", "F"},  // 85 ADD L
    {"F R", "F R"},  // 86 ADD M
    {"F", "F"},  // 87 ADD A
    {"F", "F"},  // 88 ADC B
    {"F", "F"},  // 89 ADC C
    {"F", "F"},  // 8A ADC D
    {"F", "F"},  // 8B ADC E
    {"F", "F"},  // 8C ADC H
    {"F", "F"},  // 8D ADC L
    {"F R", "F R"},  // 8E ADC M
    {"F", "F"},  // 8F ADC A
    {"F", "F"},  // 90 SUB B
    {"F", "F"},  // 91 SUB C
    {"F", "F"},  // 92 SUB D
    {"F", "F"},  // 93 SUB E
    {"F", "F"},  // 94 SUB H
    {"F", "F"},  // 95 SUB L
    {"F R", "F R"},  // 96 SUB M
    {"F", "F"},  // 97 SUB A
    {"F", "F"},  // 98 SBB B
    {"F", "F"},  // 99 SBB C
    {"F", "F"},  // 9A SBB D
    {"F", "F"},  // 9B SBB E
    {"F", "F"},  // 9C SBB H
    {"F", "F"},  // 9D SBB L
    {"F R", "F R"},  // 9E SBB M
    {"F", "F"},  // 9F SBB A
    {"F", "F"},  // A0 ANA B
    {"F", "F"},  // A1 ANA C
    {"F", "F"},  // A2 ANA D
    {"F", "F"},  // A3 ANA E
    {"F", "F"},  // A4 ANA H
    {"F", "F"},  // A5 ANA L
    {"F R", "F R"},  // A6 ANA M
    {"F", "F"},  // A7 ANA A
    {"F", "F"},  // A8 XRA B
    {"F", "F"},  // A9 XRA C
    {"F", "F"},  // AA XRA D
    {"F", "F"},  // AB XRA E
    {"F", "F"},  // AC XRA H
    {"F", "F"},  // AD XRA L
    {"F R", "F R"},  // AE XRA M
    {"F", "F"},  // AF XRA A
    {"F", "F"},  // B0 ORA B
    {"F", "F"},  // B1 ORA C
    {"F", "F"},  // B2 ORA D
    {"F", "F"},  // B3 ORA E
    {"F", "F"},  // B4 ORA H
    {"F", "F"},  // B5 ORA L
    {"F R", "F R"},  // B6 ORA M
    {"F", "F"},  // B7 ORA A
    {"F", "F"},  // B8 CMP B
    {"F", "F"},  // B9 CMP C
    {"F", "F"},  // BA CMP D
    {"F", "F"},  // BB CMP E
    {"F", "F"},  // BC CMP H
    {"F", "F"},  // BD CMP L
    {"F R", "F R"},  // BE CMP M
    {"F", "F"},  // BF CMP A
    {"S", "S R R"},  // C0 RNZ
    {"F R R", "F R R"},  // C1 POP B
    {"F R", "F R R"},  // C2 JNZ a16
    {"F R R", "F R R"},  // C3 JMP a16
    {"S R", "S R R W W"},  // C4 CNZ a16
    {"S W W", "S W W"},  // C5 PUSH B
    {"F R", "F R"},  // C6 ADI d8
    {"S W W", "S W W"},  // C7 RST 0
    {"S", "S R R"},  // C8 RZ
    {"F R R", "F R R"},  // C9 RET
    {"F R", "F R R"},  // CA JZ a16
    {"S", "S W W"},  // CB RSTV
    {"S R", "S R R W W"},  // CC CZ a16
    {"S R R W W", "S R R W W"},  // CD CALL a16
    {"F R", "F R"},  // CE ACI d8
    {"S W W", "S W W"},  // CF RST 1
    {"S", "S R R"},  // D0 RNC
    {"F R R", "F R R"},  // D1 POP D
    {"F R", "F R R"},  // D2 JNC a16
    {"F R O", "F R O"},  // D3 OUT p8
    {"S R", "S R R W W"},  // D4 CNC a16
    {"S W W", "S W W"},  // D5 PUSH D
    {"F R", "F R"},  // D6 SUI d8
    {"S W W", "S W W"},  // D7 RST 2
    {"S", "S R R"},  // D8 RC
    {"F W W", "F W W"},  // D9 SHLX
    {"F R", "F R R"},  // DA JC a16
    {"F R I", "F R I"},  // DB IN p8
    {"S R", "S R R W W"},  // DC CC a16
    {"F R", "F R R"},  // DD JNK a16
    {"F R", "F R"},  // DE SBI d8
    {"S W W", "S W W"},  // DF RST 3
    {"S", "S R R"},  // E0 RPO
    {"F R R", "F R R"},  // E1 POP H
    {"F R", "F R R"},  // E2 JPO a16
    {"F R R W W", "F R R W W"},  // E3 XTHL
    {"S R", "S R R W W"},  // E4 CPO a16
    {"S W W", "S W W"},  // E5 PUSH H
    {"F R", "F R"},  // E6 ANI d8
    {"S W W", "S W W"},  // E7 RST 4
    {"S", "S R R"},  // E8 RPE
    {"S", "S"},  // E9 PCHL
    {"F R", "F R R"},  // EA JPE a16
    {"F", "F"},  // EB XCHG
    {"S R", "S R R W W"},  // EC CPE a16
    {"F R R", "F R R"},  // ED LHLX
    {"F R", "F R"},  // EE XRI d8
    {"S W W", "S W W"},  // EF RST 5
    {"S", "S R R"},  // F0 RP
    {"F R R", "F R R"},  // F1 POP PSW
    {"F R", "F R R"},  // F2 JP a16
    {"F", "F"},  // F3 DI
    {"S R", "S R R W W"},  // F4 CP a16
    {"S W W", "S W W"},  // F5 PUSH PSW
    {"F R", "F R"},  // F6 ORI d8
    {"S W W", "S W W"},  // F7 RST 6
    {"S", "S R R"},  // F8 RM
    {"S", "S"},  // F9 SPHL
    {"F R", "F R R"},  // FA JM a16
    {"F", "F"},  // FB EI
    {"S R", "S R R W W"},  // FC CM a16
    {"F R", "F R R"},  // FD JK a16
    {"F R", "F R"},  // FE CPI d8
    {"S W W", "S W W"},  // FF RST 7
}};
// clang-format on

// The interrupt acknowledges (data sheet, "Interrupt acknowledge" and the bus idle row "ACK. OF
// RST, TRAP" of the machine cycle chart): RST 5.5, 6.5, 7.5 and TRAP push the PC after a 6 T
// idle cycle (12 T); INTR with RST n on the bus: an INTA cycle, then the two pushes (12 T).
inline constexpr std::string_view kAckRst = "A W W";
inline constexpr std::string_view kAckIntrRst = "N W W";

struct CycleList {
    std::array<MachineCycle, 6> cycles{};
    int count = 0;
    int tstates = 0;
};

// "S R R W W" -> its cycles (A: AckIdle, N: IntAck).
constexpr CycleList parse_cycles(std::string_view s) {
    CycleList l;
    for (char ch : s) {
        MachineCycle c{};
        switch (ch) {
            case 'F': c = MachineCycle::Fetch4; break;
            case 'S': c = MachineCycle::Fetch6; break;
            case 'R': c = MachineCycle::MemRead; break;
            case 'W': c = MachineCycle::MemWrite; break;
            case 'I': c = MachineCycle::IoRead; break;
            case 'O': c = MachineCycle::IoWrite; break;
            case 'B': c = MachineCycle::BusIdle; break;
            case 'H': c = MachineCycle::Halt; break;
            case 'A': c = MachineCycle::AckIdle; break;
            case 'N': c = MachineCycle::IntAck; break;
            default: continue;
        }
        l.cycles[static_cast<std::size_t>(l.count++)] = c;
        l.tstates += tstates_of(c);
    }
    return l;
}

constexpr CycleList cycles_of(std::uint8_t opcode, bool taken) {
    return parse_cycles(taken ? kCycles[opcode].taken : kCycles[opcode].not_taken);
}

}  // namespace alp85::isa
