// The machine as a debug client sees it: scopes of named values (registers and flags, the
// firmware's variables, one scope per part from its description, the display), the call stack,
// and the values of expressions. Plain functions of the Debugger, no protocol.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emu/debug/debugger.h"

namespace alp85::dap {

// variablesReference numbers: fixed, since the views are computed afresh at each request.
inline constexpr std::int64_t kRegisterScope = 1, kFlagScope = 2, kInterruptScope = 3, kFirmwareScope = 10,
                              kDisplayScope = 40;
// The parts (Machine::parts(), in order): part i's scope is kPartScope * (i + 1), the fields of
// its j-th value kPartScope * (i + 1) + j + 1.
inline constexpr std::int64_t kPartScope = 1000;

struct ScopeInfo {
    std::string name;
    std::int64_t ref;
    std::string hint;  // DAP presentationHint: "registers", "locals", ""
};
std::vector<ScopeInfo> scope_list(const debug::Debugger& d);

struct Variable {
    std::string name, value, type;
    std::int64_t children = 0;            // a variablesReference to expand, or 0
    std::optional<std::uint16_t> memory;  // where it lives, for the client's memory view
    bool read_only = false;
};
// The variables under `ref` (empty for an unknown reference).
std::vector<Variable> list_variables(const debug::Debugger& d, std::int64_t ref);
// setVariable: registers, flags, firmware variables. Returns "" or why not.
std::string assign_variable(debug::Debugger& d, std::int64_t ref, const std::string& name, std::int64_t value);

// A firmware variable's size: the distance to the next RAM symbol, at most a word (the thesis's
// variables are words and bytes; 3-byte slots hold 16-bit values).
std::uint16_t variable_size(const SymbolTable& symbols, std::uint16_t address);

// A register, pair, flag, symbol (a RAM variable shows its contents) or number, as text;
// nullopt with `error` when the text is none of these.
std::optional<std::string> expression_value(const debug::Debugger& d, const std::string& text, std::string& error);

struct CallFrame {
    std::string name;                 // "ROUTINE (ADDR)" (SymbolTable::routine_at), or "ADDR" alone
    std::uint16_t pc = 0;
    std::optional<SourceLine> line;
};
// Innermost first: the Debugger's backtrace, callers whose return address lies at or above
// `stack_base` (the top the program gave its stack) left out as stale.
std::vector<CallFrame> call_frames(const debug::Debugger& d);
// The same frames as the Debugger gives them (return address and its slot).

}  // namespace alp85::dap
