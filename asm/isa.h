// The one opcode table of ALP85: the assembler, the disassembler and the CPU core all read it.
//
// Each of the 256 entries describes the byte as the Intel 8085 decodes it, with the T-states of
// both the 8085 and the 8080 (Intel 8085AH data sheet / MCS-80/85 Family User's Manual, 1983,
// instruction set tables; 8080A data sheet for the 8080 column). Twelve bytes mean something else
// on the 8080: RIM, SIM and the ten undocumented 8085 instructions. For those, `alias8080` names
// the opcode the 8080 executes instead (NOP, JMP, RET or CALL), and the 8080 T-states are the alias's.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace alp85::isa {

// Bits of the 8085 flag register (the low byte of PSW). V and K are undocumented.
enum Flag : std::uint8_t {
    F_CY = 0x01,
    F_V = 0x02,   // signed overflow (8085 only, undocumented)
    F_P = 0x04,
    F_AC = 0x10,
    F_K = 0x20,   // "X5"/UI: V XOR S after arithmetic; carry/borrow of INX/DCX (undocumented)
    F_Z = 0x40,
    F_S = 0x80,
};

// Which processors decode the byte as `mnemonic`.
enum class Set : std::uint8_t {
    Common,     // 8080 and 8085
    Only8085,   // RIM, SIM: documented 8085 additions
    Undoc8085,  // the ten undocumented 8085 instructions
};

// How an instruction changes the flow of control: what steppers, backtraces and reverse execution
// need to know. The `...If` kinds are conditional (RSTV restarts only when V is set). An
// interrupt acknowledge is not an opcode's flow: it is the CPU's.
enum class Flow : std::uint8_t {
    Next,          // falls through to the next instruction
    Jump, JumpIf,  // JMP, Jcc (JNK/JK included)
    JumpIndirect,  // PCHL
    Call, CallIf,  // CALL, Ccc: push the return address
    Restart,       // RST n: pushes the return address
    RestartIf,     // RSTV (8085): RST 8 at 0040H when V is set
    Return, ReturnIf,
    Halt,
};

struct OpInfo {
    std::string_view mnemonic;  // Intel mnemonic
    // Operand template, comma separated. Register and pair names stand for themselves
    // (B C D E H L M A, B D H SP PSW); placeholders: d8 = byte data, d16 = word data,
    // a16 = address, p8 = port; a digit is RST's restart number.
    std::string_view operands;
    std::uint8_t length;         // bytes on the 8085
    std::uint8_t t8085;          // T-states; for conditional jumps/calls/returns: condition false
    std::uint8_t t8085_taken;    // condition true (equal to t8085 for unconditional instructions)
    std::uint8_t t8080;          // 8080 T-states of what the 8080 executes (see alias8080)
    std::uint8_t t8080_taken;
    Set set;
    std::uint8_t alias8080;      // the opcode an 8080 executes for this byte (itself if Common)
    std::string_view alt;        // second mnemonic the assembler accepts (JNX5, JX5), or empty
    Flow flow = Flow::Next;      // of the 8085's instruction (an 8080 executes alias8080's)
};

// clang-format off
inline constexpr std::array<OpInfo, 256> kOpcodes{{
    {"NOP", "", 1, 4, 4, 4, 4, Set::Common, 0x00, ""},  // 00
    {"LXI", "B,d16", 3, 10, 10, 10, 10, Set::Common, 0x01, ""},  // 01
    {"STAX", "B", 1, 7, 7, 7, 7, Set::Common, 0x02, ""},  // 02
    {"INX", "B", 1, 6, 6, 5, 5, Set::Common, 0x03, ""},  // 03
    {"INR", "B", 1, 4, 4, 5, 5, Set::Common, 0x04, ""},  // 04
    {"DCR", "B", 1, 4, 4, 5, 5, Set::Common, 0x05, ""},  // 05
    {"MVI", "B,d8", 2, 7, 7, 7, 7, Set::Common, 0x06, ""},  // 06
    {"RLC", "", 1, 4, 4, 4, 4, Set::Common, 0x07, ""},  // 07
    {"DSUB", "", 1, 10, 10, 4, 4, Set::Undoc8085, 0x00, ""},  // 08
    {"DAD", "B", 1, 10, 10, 10, 10, Set::Common, 0x09, ""},  // 09
    {"LDAX", "B", 1, 7, 7, 7, 7, Set::Common, 0x0A, ""},  // 0A
    {"DCX", "B", 1, 6, 6, 5, 5, Set::Common, 0x0B, ""},  // 0B
    {"INR", "C", 1, 4, 4, 5, 5, Set::Common, 0x0C, ""},  // 0C
    {"DCR", "C", 1, 4, 4, 5, 5, Set::Common, 0x0D, ""},  // 0D
    {"MVI", "C,d8", 2, 7, 7, 7, 7, Set::Common, 0x0E, ""},  // 0E
    {"RRC", "", 1, 4, 4, 4, 4, Set::Common, 0x0F, ""},  // 0F
    {"ARHL", "", 1, 7, 7, 4, 4, Set::Undoc8085, 0x00, ""},  // 10
    {"LXI", "D,d16", 3, 10, 10, 10, 10, Set::Common, 0x11, ""},  // 11
    {"STAX", "D", 1, 7, 7, 7, 7, Set::Common, 0x12, ""},  // 12
    {"INX", "D", 1, 6, 6, 5, 5, Set::Common, 0x13, ""},  // 13
    {"INR", "D", 1, 4, 4, 5, 5, Set::Common, 0x14, ""},  // 14
    {"DCR", "D", 1, 4, 4, 5, 5, Set::Common, 0x15, ""},  // 15
    {"MVI", "D,d8", 2, 7, 7, 7, 7, Set::Common, 0x16, ""},  // 16
    {"RAL", "", 1, 4, 4, 4, 4, Set::Common, 0x17, ""},  // 17
    {"RDEL", "", 1, 10, 10, 4, 4, Set::Undoc8085, 0x00, ""},  // 18
    {"DAD", "D", 1, 10, 10, 10, 10, Set::Common, 0x19, ""},  // 19
    {"LDAX", "D", 1, 7, 7, 7, 7, Set::Common, 0x1A, ""},  // 1A
    {"DCX", "D", 1, 6, 6, 5, 5, Set::Common, 0x1B, ""},  // 1B
    {"INR", "E", 1, 4, 4, 5, 5, Set::Common, 0x1C, ""},  // 1C
    {"DCR", "E", 1, 4, 4, 5, 5, Set::Common, 0x1D, ""},  // 1D
    {"MVI", "E,d8", 2, 7, 7, 7, 7, Set::Common, 0x1E, ""},  // 1E
    {"RAR", "", 1, 4, 4, 4, 4, Set::Common, 0x1F, ""},  // 1F
    {"RIM", "", 1, 4, 4, 4, 4, Set::Only8085, 0x00, ""},  // 20
    {"LXI", "H,d16", 3, 10, 10, 10, 10, Set::Common, 0x21, ""},  // 21
    {"SHLD", "a16", 3, 16, 16, 16, 16, Set::Common, 0x22, ""},  // 22
    {"INX", "H", 1, 6, 6, 5, 5, Set::Common, 0x23, ""},  // 23
    {"INR", "H", 1, 4, 4, 5, 5, Set::Common, 0x24, ""},  // 24
    {"DCR", "H", 1, 4, 4, 5, 5, Set::Common, 0x25, ""},  // 25
    {"MVI", "H,d8", 2, 7, 7, 7, 7, Set::Common, 0x26, ""},  // 26
    {"DAA", "", 1, 4, 4, 4, 4, Set::Common, 0x27, ""},  // 27
    {"LDHI", "d8", 2, 10, 10, 4, 4, Set::Undoc8085, 0x00, ""},  // 28
    {"DAD", "H", 1, 10, 10, 10, 10, Set::Common, 0x29, ""},  // 29
    {"LHLD", "a16", 3, 16, 16, 16, 16, Set::Common, 0x2A, ""},  // 2A
    {"DCX", "H", 1, 6, 6, 5, 5, Set::Common, 0x2B, ""},  // 2B
    {"INR", "L", 1, 4, 4, 5, 5, Set::Common, 0x2C, ""},  // 2C
    {"DCR", "L", 1, 4, 4, 5, 5, Set::Common, 0x2D, ""},  // 2D
    {"MVI", "L,d8", 2, 7, 7, 7, 7, Set::Common, 0x2E, ""},  // 2E
    {"CMA", "", 1, 4, 4, 4, 4, Set::Common, 0x2F, ""},  // 2F
    {"SIM", "", 1, 4, 4, 4, 4, Set::Only8085, 0x00, ""},  // 30
    {"LXI", "SP,d16", 3, 10, 10, 10, 10, Set::Common, 0x31, ""},  // 31
    {"STA", "a16", 3, 13, 13, 13, 13, Set::Common, 0x32, ""},  // 32
    {"INX", "SP", 1, 6, 6, 5, 5, Set::Common, 0x33, ""},  // 33
    {"INR", "M", 1, 10, 10, 10, 10, Set::Common, 0x34, ""},  // 34
    {"DCR", "M", 1, 10, 10, 10, 10, Set::Common, 0x35, ""},  // 35
    {"MVI", "M,d8", 2, 10, 10, 10, 10, Set::Common, 0x36, ""},  // 36
    {"STC", "", 1, 4, 4, 4, 4, Set::Common, 0x37, ""},  // 37
    {"LDSI", "d8", 2, 10, 10, 4, 4, Set::Undoc8085, 0x00, ""},  // 38
    {"DAD", "SP", 1, 10, 10, 10, 10, Set::Common, 0x39, ""},  // 39
    {"LDA", "a16", 3, 13, 13, 13, 13, Set::Common, 0x3A, ""},  // 3A
    {"DCX", "SP", 1, 6, 6, 5, 5, Set::Common, 0x3B, ""},  // 3B
    {"INR", "A", 1, 4, 4, 5, 5, Set::Common, 0x3C, ""},  // 3C
    {"DCR", "A", 1, 4, 4, 5, 5, Set::Common, 0x3D, ""},  // 3D
    {"MVI", "A,d8", 2, 7, 7, 7, 7, Set::Common, 0x3E, ""},  // 3E
    {"CMC", "", 1, 4, 4, 4, 4, Set::Common, 0x3F, ""},  // 3F
    {"MOV", "B,B", 1, 4, 4, 5, 5, Set::Common, 0x40, ""},  // 40
    {"MOV", "B,C", 1, 4, 4, 5, 5, Set::Common, 0x41, ""},  // 41
    {"MOV", "B,D", 1, 4, 4, 5, 5, Set::Common, 0x42, ""},  // 42
    {"MOV", "B,E", 1, 4, 4, 5, 5, Set::Common, 0x43, ""},  // 43
    {"MOV", "B,H", 1, 4, 4, 5, 5, Set::Common, 0x44, ""},  // 44
    {"MOV", "B,L", 1, 4, 4, 5, 5, Set::Common, 0x45, ""},  // 45
    {"MOV", "B,M", 1, 7, 7, 7, 7, Set::Common, 0x46, ""},  // 46
    {"MOV", "B,A", 1, 4, 4, 5, 5, Set::Common, 0x47, ""},  // 47
    {"MOV", "C,B", 1, 4, 4, 5, 5, Set::Common, 0x48, ""},  // 48
    {"MOV", "C,C", 1, 4, 4, 5, 5, Set::Common, 0x49, ""},  // 49
    {"MOV", "C,D", 1, 4, 4, 5, 5, Set::Common, 0x4A, ""},  // 4A
    {"MOV", "C,E", 1, 4, 4, 5, 5, Set::Common, 0x4B, ""},  // 4B
    {"MOV", "C,H", 1, 4, 4, 5, 5, Set::Common, 0x4C, ""},  // 4C
    {"MOV", "C,L", 1, 4, 4, 5, 5, Set::Common, 0x4D, ""},  // 4D
    {"MOV", "C,M", 1, 7, 7, 7, 7, Set::Common, 0x4E, ""},  // 4E
    {"MOV", "C,A", 1, 4, 4, 5, 5, Set::Common, 0x4F, ""},  // 4F
    {"MOV", "D,B", 1, 4, 4, 5, 5, Set::Common, 0x50, ""},  // 50
    {"MOV", "D,C", 1, 4, 4, 5, 5, Set::Common, 0x51, ""},  // 51
    {"MOV", "D,D", 1, 4, 4, 5, 5, Set::Common, 0x52, ""},  // 52
    {"MOV", "D,E", 1, 4, 4, 5, 5, Set::Common, 0x53, ""},  // 53
    {"MOV", "D,H", 1, 4, 4, 5, 5, Set::Common, 0x54, ""},  // 54
    {"MOV", "D,L", 1, 4, 4, 5, 5, Set::Common, 0x55, ""},  // 55
    {"MOV", "D,M", 1, 7, 7, 7, 7, Set::Common, 0x56, ""},  // 56
    {"MOV", "D,A", 1, 4, 4, 5, 5, Set::Common, 0x57, ""},  // 57
    {"MOV", "E,B", 1, 4, 4, 5, 5, Set::Common, 0x58, ""},  // 58
    {"MOV", "E,C", 1, 4, 4, 5, 5, Set::Common, 0x59, ""},  // 59
    {"MOV", "E,D", 1, 4, 4, 5, 5, Set::Common, 0x5A, ""},  // 5A
    {"MOV", "E,E", 1, 4, 4, 5, 5, Set::Common, 0x5B, ""},  // 5B
    {"MOV", "E,H", 1, 4, 4, 5, 5, Set::Common, 0x5C, ""},  // 5C
    {"MOV", "E,L", 1, 4, 4, 5, 5, Set::Common, 0x5D, ""},  // 5D
    {"MOV", "E,M", 1, 7, 7, 7, 7, Set::Common, 0x5E, ""},  // 5E
    {"MOV", "E,A", 1, 4, 4, 5, 5, Set::Common, 0x5F, ""},  // 5F
    {"MOV", "H,B", 1, 4, 4, 5, 5, Set::Common, 0x60, ""},  // 60
    {"MOV", "H,C", 1, 4, 4, 5, 5, Set::Common, 0x61, ""},  // 61
    {"MOV", "H,D", 1, 4, 4, 5, 5, Set::Common, 0x62, ""},  // 62
    {"MOV", "H,E", 1, 4, 4, 5, 5, Set::Common, 0x63, ""},  // 63
    {"MOV", "H,H", 1, 4, 4, 5, 5, Set::Common, 0x64, ""},  // 64
    {"MOV", "H,L", 1, 4, 4, 5, 5, Set::Common, 0x65, ""},  // 65
    {"MOV", "H,M", 1, 7, 7, 7, 7, Set::Common, 0x66, ""},  // 66
    {"MOV", "H,A", 1, 4, 4, 5, 5, Set::Common, 0x67, ""},  // 67
    {"MOV", "L,B", 1, 4, 4, 5, 5, Set::Common, 0x68, ""},  // 68
    {"MOV", "L,C", 1, 4, 4, 5, 5, Set::Common, 0x69, ""},  // 69
    {"MOV", "L,D", 1, 4, 4, 5, 5, Set::Common, 0x6A, ""},  // 6A
    {"MOV", "L,E", 1, 4, 4, 5, 5, Set::Common, 0x6B, ""},  // 6B
    {"MOV", "L,H", 1, 4, 4, 5, 5, Set::Common, 0x6C, ""},  // 6C
    {"MOV", "L,L", 1, 4, 4, 5, 5, Set::Common, 0x6D, ""},  // 6D
    {"MOV", "L,M", 1, 7, 7, 7, 7, Set::Common, 0x6E, ""},  // 6E
    {"MOV", "L,A", 1, 4, 4, 5, 5, Set::Common, 0x6F, ""},  // 6F
    {"MOV", "M,B", 1, 7, 7, 7, 7, Set::Common, 0x70, ""},  // 70
    {"MOV", "M,C", 1, 7, 7, 7, 7, Set::Common, 0x71, ""},  // 71
    {"MOV", "M,D", 1, 7, 7, 7, 7, Set::Common, 0x72, ""},  // 72
    {"MOV", "M,E", 1, 7, 7, 7, 7, Set::Common, 0x73, ""},  // 73
    {"MOV", "M,H", 1, 7, 7, 7, 7, Set::Common, 0x74, ""},  // 74
    {"MOV", "M,L", 1, 7, 7, 7, 7, Set::Common, 0x75, ""},  // 75
    {"HLT", "", 1, 5, 5, 7, 7, Set::Common, 0x76, "", Flow::Halt},  // 76
    {"MOV", "M,A", 1, 7, 7, 7, 7, Set::Common, 0x77, ""},  // 77
    {"MOV", "A,B", 1, 4, 4, 5, 5, Set::Common, 0x78, ""},  // 78
    {"MOV", "A,C", 1, 4, 4, 5, 5, Set::Common, 0x79, ""},  // 79
    {"MOV", "A,D", 1, 4, 4, 5, 5, Set::Common, 0x7A, ""},  // 7A
    {"MOV", "A,E", 1, 4, 4, 5, 5, Set::Common, 0x7B, ""},  // 7B
    {"MOV", "A,H", 1, 4, 4, 5, 5, Set::Common, 0x7C, ""},  // 7C
    {"MOV", "A,L", 1, 4, 4, 5, 5, Set::Common, 0x7D, ""},  // 7D
    {"MOV", "A,M", 1, 7, 7, 7, 7, Set::Common, 0x7E, ""},  // 7E
    {"MOV", "A,A", 1, 4, 4, 5, 5, Set::Common, 0x7F, ""},  // 7F
    {"ADD", "B", 1, 4, 4, 4, 4, Set::Common, 0x80, ""},  // 80
    {"ADD", "C", 1, 4, 4, 4, 4, Set::Common, 0x81, ""},  // 81
    {"ADD", "D", 1, 4, 4, 4, 4, Set::Common, 0x82, ""},  // 82
    {"ADD", "E", 1, 4, 4, 4, 4, Set::Common, 0x83, ""},  // 83
    {"ADD", "H", 1, 4, 4, 4, 4, Set::Common, 0x84, ""},  // 84
    {"ADD", "L", 1, 4, 4, 4, 4, Set::Common, 0x85, ""},  // 85
    {"ADD", "M", 1, 7, 7, 7, 7, Set::Common, 0x86, ""},  // 86
    {"ADD", "A", 1, 4, 4, 4, 4, Set::Common, 0x87, ""},  // 87
    {"ADC", "B", 1, 4, 4, 4, 4, Set::Common, 0x88, ""},  // 88
    {"ADC", "C", 1, 4, 4, 4, 4, Set::Common, 0x89, ""},  // 89
    {"ADC", "D", 1, 4, 4, 4, 4, Set::Common, 0x8A, ""},  // 8A
    {"ADC", "E", 1, 4, 4, 4, 4, Set::Common, 0x8B, ""},  // 8B
    {"ADC", "H", 1, 4, 4, 4, 4, Set::Common, 0x8C, ""},  // 8C
    {"ADC", "L", 1, 4, 4, 4, 4, Set::Common, 0x8D, ""},  // 8D
    {"ADC", "M", 1, 7, 7, 7, 7, Set::Common, 0x8E, ""},  // 8E
    {"ADC", "A", 1, 4, 4, 4, 4, Set::Common, 0x8F, ""},  // 8F
    {"SUB", "B", 1, 4, 4, 4, 4, Set::Common, 0x90, ""},  // 90
    {"SUB", "C", 1, 4, 4, 4, 4, Set::Common, 0x91, ""},  // 91
    {"SUB", "D", 1, 4, 4, 4, 4, Set::Common, 0x92, ""},  // 92
    {"SUB", "E", 1, 4, 4, 4, 4, Set::Common, 0x93, ""},  // 93
    {"SUB", "H", 1, 4, 4, 4, 4, Set::Common, 0x94, ""},  // 94
    {"SUB", "L", 1, 4, 4, 4, 4, Set::Common, 0x95, ""},  // 95
    {"SUB", "M", 1, 7, 7, 7, 7, Set::Common, 0x96, ""},  // 96
    {"SUB", "A", 1, 4, 4, 4, 4, Set::Common, 0x97, ""},  // 97
    {"SBB", "B", 1, 4, 4, 4, 4, Set::Common, 0x98, ""},  // 98
    {"SBB", "C", 1, 4, 4, 4, 4, Set::Common, 0x99, ""},  // 99
    {"SBB", "D", 1, 4, 4, 4, 4, Set::Common, 0x9A, ""},  // 9A
    {"SBB", "E", 1, 4, 4, 4, 4, Set::Common, 0x9B, ""},  // 9B
    {"SBB", "H", 1, 4, 4, 4, 4, Set::Common, 0x9C, ""},  // 9C
    {"SBB", "L", 1, 4, 4, 4, 4, Set::Common, 0x9D, ""},  // 9D
    {"SBB", "M", 1, 7, 7, 7, 7, Set::Common, 0x9E, ""},  // 9E
    {"SBB", "A", 1, 4, 4, 4, 4, Set::Common, 0x9F, ""},  // 9F
    {"ANA", "B", 1, 4, 4, 4, 4, Set::Common, 0xA0, ""},  // A0
    {"ANA", "C", 1, 4, 4, 4, 4, Set::Common, 0xA1, ""},  // A1
    {"ANA", "D", 1, 4, 4, 4, 4, Set::Common, 0xA2, ""},  // A2
    {"ANA", "E", 1, 4, 4, 4, 4, Set::Common, 0xA3, ""},  // A3
    {"ANA", "H", 1, 4, 4, 4, 4, Set::Common, 0xA4, ""},  // A4
    {"ANA", "L", 1, 4, 4, 4, 4, Set::Common, 0xA5, ""},  // A5
    {"ANA", "M", 1, 7, 7, 7, 7, Set::Common, 0xA6, ""},  // A6
    {"ANA", "A", 1, 4, 4, 4, 4, Set::Common, 0xA7, ""},  // A7
    {"XRA", "B", 1, 4, 4, 4, 4, Set::Common, 0xA8, ""},  // A8
    {"XRA", "C", 1, 4, 4, 4, 4, Set::Common, 0xA9, ""},  // A9
    {"XRA", "D", 1, 4, 4, 4, 4, Set::Common, 0xAA, ""},  // AA
    {"XRA", "E", 1, 4, 4, 4, 4, Set::Common, 0xAB, ""},  // AB
    {"XRA", "H", 1, 4, 4, 4, 4, Set::Common, 0xAC, ""},  // AC
    {"XRA", "L", 1, 4, 4, 4, 4, Set::Common, 0xAD, ""},  // AD
    {"XRA", "M", 1, 7, 7, 7, 7, Set::Common, 0xAE, ""},  // AE
    {"XRA", "A", 1, 4, 4, 4, 4, Set::Common, 0xAF, ""},  // AF
    {"ORA", "B", 1, 4, 4, 4, 4, Set::Common, 0xB0, ""},  // B0
    {"ORA", "C", 1, 4, 4, 4, 4, Set::Common, 0xB1, ""},  // B1
    {"ORA", "D", 1, 4, 4, 4, 4, Set::Common, 0xB2, ""},  // B2
    {"ORA", "E", 1, 4, 4, 4, 4, Set::Common, 0xB3, ""},  // B3
    {"ORA", "H", 1, 4, 4, 4, 4, Set::Common, 0xB4, ""},  // B4
    {"ORA", "L", 1, 4, 4, 4, 4, Set::Common, 0xB5, ""},  // B5
    {"ORA", "M", 1, 7, 7, 7, 7, Set::Common, 0xB6, ""},  // B6
    {"ORA", "A", 1, 4, 4, 4, 4, Set::Common, 0xB7, ""},  // B7
    {"CMP", "B", 1, 4, 4, 4, 4, Set::Common, 0xB8, ""},  // B8
    {"CMP", "C", 1, 4, 4, 4, 4, Set::Common, 0xB9, ""},  // B9
    {"CMP", "D", 1, 4, 4, 4, 4, Set::Common, 0xBA, ""},  // BA
    {"CMP", "E", 1, 4, 4, 4, 4, Set::Common, 0xBB, ""},  // BB
    {"CMP", "H", 1, 4, 4, 4, 4, Set::Common, 0xBC, ""},  // BC
    {"CMP", "L", 1, 4, 4, 4, 4, Set::Common, 0xBD, ""},  // BD
    {"CMP", "M", 1, 7, 7, 7, 7, Set::Common, 0xBE, ""},  // BE
    {"CMP", "A", 1, 4, 4, 4, 4, Set::Common, 0xBF, ""},  // BF
    {"RNZ", "", 1, 6, 12, 5, 11, Set::Common, 0xC0, "", Flow::ReturnIf},  // C0
    {"POP", "B", 1, 10, 10, 10, 10, Set::Common, 0xC1, ""},  // C1
    {"JNZ", "a16", 3, 7, 10, 10, 10, Set::Common, 0xC2, "", Flow::JumpIf},  // C2
    {"JMP", "a16", 3, 10, 10, 10, 10, Set::Common, 0xC3, "", Flow::Jump},  // C3
    {"CNZ", "a16", 3, 9, 18, 11, 17, Set::Common, 0xC4, "", Flow::CallIf},  // C4
    {"PUSH", "B", 1, 12, 12, 11, 11, Set::Common, 0xC5, ""},  // C5
    {"ADI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xC6, ""},  // C6
    {"RST", "0", 1, 12, 12, 11, 11, Set::Common, 0xC7, "", Flow::Restart},  // C7
    {"RZ", "", 1, 6, 12, 5, 11, Set::Common, 0xC8, "", Flow::ReturnIf},  // C8
    {"RET", "", 1, 10, 10, 10, 10, Set::Common, 0xC9, "", Flow::Return},  // C9
    {"JZ", "a16", 3, 7, 10, 10, 10, Set::Common, 0xCA, "", Flow::JumpIf},  // CA
    {"RSTV", "", 1, 6, 12, 10, 10, Set::Undoc8085, 0xC3, "", Flow::RestartIf},  // CB
    {"CZ", "a16", 3, 9, 18, 11, 17, Set::Common, 0xCC, "", Flow::CallIf},  // CC
    {"CALL", "a16", 3, 18, 18, 17, 17, Set::Common, 0xCD, "", Flow::Call},  // CD
    {"ACI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xCE, ""},  // CE
    {"RST", "1", 1, 12, 12, 11, 11, Set::Common, 0xCF, "", Flow::Restart},  // CF
    {"RNC", "", 1, 6, 12, 5, 11, Set::Common, 0xD0, "", Flow::ReturnIf},  // D0
    {"POP", "D", 1, 10, 10, 10, 10, Set::Common, 0xD1, ""},  // D1
    {"JNC", "a16", 3, 7, 10, 10, 10, Set::Common, 0xD2, "", Flow::JumpIf},  // D2
    {"OUT", "p8", 2, 10, 10, 10, 10, Set::Common, 0xD3, ""},  // D3
    {"CNC", "a16", 3, 9, 18, 11, 17, Set::Common, 0xD4, "", Flow::CallIf},  // D4
    {"PUSH", "D", 1, 12, 12, 11, 11, Set::Common, 0xD5, ""},  // D5
    {"SUI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xD6, ""},  // D6
    {"RST", "2", 1, 12, 12, 11, 11, Set::Common, 0xD7, "", Flow::Restart},  // D7
    {"RC", "", 1, 6, 12, 5, 11, Set::Common, 0xD8, "", Flow::ReturnIf},  // D8
    {"SHLX", "", 1, 10, 10, 10, 10, Set::Undoc8085, 0xC9, ""},  // D9
    {"JC", "a16", 3, 7, 10, 10, 10, Set::Common, 0xDA, "", Flow::JumpIf},  // DA
    {"IN", "p8", 2, 10, 10, 10, 10, Set::Common, 0xDB, ""},  // DB
    {"CC", "a16", 3, 9, 18, 11, 17, Set::Common, 0xDC, "", Flow::CallIf},  // DC
    {"JNK", "a16", 3, 7, 10, 17, 17, Set::Undoc8085, 0xCD, "JNX5", Flow::JumpIf},  // DD
    {"SBI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xDE, ""},  // DE
    {"RST", "3", 1, 12, 12, 11, 11, Set::Common, 0xDF, "", Flow::Restart},  // DF
    {"RPO", "", 1, 6, 12, 5, 11, Set::Common, 0xE0, "", Flow::ReturnIf},  // E0
    {"POP", "H", 1, 10, 10, 10, 10, Set::Common, 0xE1, ""},  // E1
    {"JPO", "a16", 3, 7, 10, 10, 10, Set::Common, 0xE2, "", Flow::JumpIf},  // E2
    {"XTHL", "", 1, 16, 16, 18, 18, Set::Common, 0xE3, ""},  // E3
    {"CPO", "a16", 3, 9, 18, 11, 17, Set::Common, 0xE4, "", Flow::CallIf},  // E4
    {"PUSH", "H", 1, 12, 12, 11, 11, Set::Common, 0xE5, ""},  // E5
    {"ANI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xE6, ""},  // E6
    {"RST", "4", 1, 12, 12, 11, 11, Set::Common, 0xE7, "", Flow::Restart},  // E7
    {"RPE", "", 1, 6, 12, 5, 11, Set::Common, 0xE8, "", Flow::ReturnIf},  // E8
    {"PCHL", "", 1, 6, 6, 5, 5, Set::Common, 0xE9, "", Flow::JumpIndirect},  // E9
    {"JPE", "a16", 3, 7, 10, 10, 10, Set::Common, 0xEA, "", Flow::JumpIf},  // EA
    {"XCHG", "", 1, 4, 4, 4, 4, Set::Common, 0xEB, ""},  // EB
    {"CPE", "a16", 3, 9, 18, 11, 17, Set::Common, 0xEC, "", Flow::CallIf},  // EC
    {"LHLX", "", 1, 10, 10, 17, 17, Set::Undoc8085, 0xCD, ""},  // ED
    {"XRI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xEE, ""},  // EE
    {"RST", "5", 1, 12, 12, 11, 11, Set::Common, 0xEF, "", Flow::Restart},  // EF
    {"RP", "", 1, 6, 12, 5, 11, Set::Common, 0xF0, "", Flow::ReturnIf},  // F0
    {"POP", "PSW", 1, 10, 10, 10, 10, Set::Common, 0xF1, ""},  // F1
    {"JP", "a16", 3, 7, 10, 10, 10, Set::Common, 0xF2, "", Flow::JumpIf},  // F2
    {"DI", "", 1, 4, 4, 4, 4, Set::Common, 0xF3, ""},  // F3
    {"CP", "a16", 3, 9, 18, 11, 17, Set::Common, 0xF4, "", Flow::CallIf},  // F4
    {"PUSH", "PSW", 1, 12, 12, 11, 11, Set::Common, 0xF5, ""},  // F5
    {"ORI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xF6, ""},  // F6
    {"RST", "6", 1, 12, 12, 11, 11, Set::Common, 0xF7, "", Flow::Restart},  // F7
    {"RM", "", 1, 6, 12, 5, 11, Set::Common, 0xF8, "", Flow::ReturnIf},  // F8
    {"SPHL", "", 1, 6, 6, 5, 5, Set::Common, 0xF9, ""},  // F9
    {"JM", "a16", 3, 7, 10, 10, 10, Set::Common, 0xFA, "", Flow::JumpIf},  // FA
    {"EI", "", 1, 4, 4, 4, 4, Set::Common, 0xFB, ""},  // FB
    {"CM", "a16", 3, 9, 18, 11, 17, Set::Common, 0xFC, "", Flow::CallIf},  // FC
    {"JK", "a16", 3, 7, 10, 17, 17, Set::Undoc8085, 0xCD, "JX5", Flow::JumpIf},  // FD
    {"CPI", "d8", 2, 7, 7, 7, 7, Set::Common, 0xFE, ""},  // FE
    {"RST", "7", 1, 12, 12, 11, 11, Set::Common, 0xFF, "", Flow::Restart},  // FF
}};
// clang-format on

// The flags an instruction writes (whether to a new value or not), by mnemonic: the "Flags"
// lines of the 8085AH data sheet and the MCS-80/85 User's Manual, and for V and K the
// undocumented behaviour of docs/cpu.md. The CPU core writes exactly these bits (and keeps the
// others) and tests/cpu/table_core_test.cpp checks that it does. The 8080 has no V and K.
struct FlagEffect {
    std::string_view mnemonic;
    std::string_view operands;  // empty: any
    std::uint8_t flags;         // on the 8085
};
inline constexpr std::uint8_t kAllFlags = F_S | F_Z | F_K | F_AC | F_P | F_V | F_CY;
inline constexpr std::uint8_t kIncFlags = F_S | F_Z | F_K | F_AC | F_P | F_V;  // INR, DCR: not CY
inline constexpr FlagEffect kFlagEffects[] = {
    {"ADD", "", kAllFlags}, {"ADC", "", kAllFlags}, {"SUB", "", kAllFlags}, {"SBB", "", kAllFlags},
    {"ANA", "", kAllFlags}, {"XRA", "", kAllFlags}, {"ORA", "", kAllFlags}, {"CMP", "", kAllFlags},
    {"ADI", "", kAllFlags}, {"ACI", "", kAllFlags}, {"SUI", "", kAllFlags}, {"SBI", "", kAllFlags},
    {"ANI", "", kAllFlags}, {"XRI", "", kAllFlags}, {"ORI", "", kAllFlags}, {"CPI", "", kAllFlags},
    {"DAA", "", kAllFlags}, {"DSUB", "", kAllFlags}, {"POP", "PSW", kAllFlags},
    {"INR", "", kIncFlags}, {"DCR", "", kIncFlags},
    {"INX", "", F_K}, {"DCX", "", F_K},
    {"DAD", "", F_CY}, {"RLC", "", F_CY}, {"RRC", "", F_CY}, {"RAL", "", F_CY}, {"RAR", "", F_CY},
    {"STC", "", F_CY}, {"CMC", "", F_CY}, {"ARHL", "", F_CY},
    {"RDEL", "", F_CY | F_V},
};

// The flags the instruction a processor executes for `op` writes (none if not listed above).
constexpr std::uint8_t flags_written(std::uint8_t op, bool i8080) {
    const OpInfo& o = kOpcodes[i8080 ? kOpcodes[op].alias8080 : op];
    for (const FlagEffect& e : kFlagEffects)
        if (e.mnemonic == o.mnemonic && (e.operands.empty() || e.operands == o.operands))
            return i8080 ? static_cast<std::uint8_t>(e.flags & ~(F_V | F_K)) : e.flags;
    return 0;
}

// The flow of the instruction a processor executes for `op` (the 8080 runs alias8080: CB is its
// JMP, DD and FD its CALL).
constexpr Flow flow_of(std::uint8_t op, bool i8080) {
    return kOpcodes[i8080 ? kOpcodes[op].alias8080 : op].flow;
}
// CALL, Ccc, RST and RSTV: the instruction may push a return address and go elsewhere (a step
// "over" it runs the routine whole).
constexpr bool may_call(Flow f) {
    return f == Flow::Call || f == Flow::CallIf || f == Flow::Restart || f == Flow::RestartIf;
}
constexpr bool may_return(Flow f) { return f == Flow::Return || f == Flow::ReturnIf; }
constexpr bool may_jump(Flow f) { return f == Flow::Jump || f == Flow::JumpIf || f == Flow::JumpIndirect; }

}  // namespace alp85::isa
