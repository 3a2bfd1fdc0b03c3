// The instruction trace as CSV, one line per executed instruction, shared by `alp85 script
// --trace` and `alp85 cpm --trace`:
//   tstate,pc,opcode,instruction,a,f,b,c,d,e,h,l,sp
//   1234,0800,3E,"MVI A,05H",00,02,...
// tstate is the T-state count before the instruction; registers are those before it, in hex.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "emu/core/i8085.h"

namespace alp85 {

std::string_view trace_csv_header();
// `peek` reads memory without side effects; the instruction is decoded as cpu.variant() does.
std::string trace_csv_line(const I8085& cpu, const std::function<std::uint8_t(std::uint16_t)>& peek);

}  // namespace alp85
