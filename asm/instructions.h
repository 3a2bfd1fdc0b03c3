// The mnemonic index, built once from the shared opcode table (asm/isa.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace alp85::asm85 {

// Opcodes whose mnemonic (or alternative mnemonic, JNX5/JX5) is `upper`; nullptr if none.
const std::vector<std::uint8_t>* find_mnemonic(const std::string& upper);

// The comma-separated parts of an operand template ("B,d16" -> {"B", "d16"}).
std::vector<std::string> template_slots(std::string_view operands);

}  // namespace alp85::asm85
