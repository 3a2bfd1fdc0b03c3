// Parsing the command language: a line of text to a Command, or an error with its column.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/script/command.h"

namespace alp85::script {

struct ParseError {
    Location where;
    std::string message;
    std::string line;
    std::string format() const;  // file:line:col: error: message, the line and a caret
};

// Where a command stands, for reports: "file:line", then the include lines that brought it in,
// innermost first, as parse errors name them: "common.alp:8 (included from top.alp:1)".
std::string place_of(const Command& c);
// The same chain alone, each " (included from FILE:LINE)": appended to a message about the line.
std::string included_from(const Command& c);

// A command of the language, as the debugger's help and completion list it and docs/scripting.md
// documents it (tests/scripts/command_table_test.cpp holds the docs to this list).
struct CommandInfo {
    std::string_view name;  // as written, lower case
    std::string_view help;  // "usage: what it does"
    // Where the debugger has a command of the same name (run, expect, set, print), the words after
    // the name that make a line this one's ("\"": a quoted string); empty: the debugger's takes it.
    std::vector<std::string_view> forms = {};
    bool takes_file = false;  // names a file: completion offers file names after it
};
const std::vector<CommandInfo>& commands();

// One line. An empty or comment-only line gives nullopt and no error.
std::optional<Command> parse_line(std::string_view line, const std::string& file, int line_no,
                                  std::vector<ParseError>& errors);

// A whole script: every line, every error (not only the first). `included`, when given, gets the
// path of every file an `include` read (the session's inputs, which no output may overwrite).
std::vector<Command> parse_script(std::string_view text, const std::string& file, std::vector<ParseError>& errors,
                                  std::vector<std::string>* included = nullptr);

// Pieces the debugger's prompt and the runner reuse.
std::optional<std::int64_t> parse_number(std::string_view text);     // 12, 0CH, 0xC, 1100B, 14O/14Q
std::optional<std::uint64_t> parse_time(std::string_view text);      // 3070t, 250us, 10ms, 1.5s
// Where an address is expected, a bare decimal number with a leading zero ("0800") is refused:
// on an 8085 board it is surely meant as hex, and read as decimal it would silently misplace an
// image (0800 = 0320H, inside the monitor). Returns the error message with the hint to write
// 0800H, or an empty string when `text` is not such a number.
std::string ambiguous_address(std::string_view text);
// A NUMBER, or any other value as a debug::Expr (SYMBOL, SYMBOL+N, (X1 + 1)*2; a bare name a
// symbol first), `what` naming it in messages; with `address`, the leading-zero rule above. An
// expression that reads nothing (2*3) is a number. On error: nullopt, the message, and its 1-based
// column within `text`.
std::optional<Value> parse_value(std::string_view text, std::string_view what, bool address, std::string& error,
                                 int& error_col);
std::optional<KeyRef> parse_key(std::string_view text);
// Keys separated by spaces, as typed on the keypad: "R 7 0800 EXEC" is R 7 0 8 0 0 EXEC (a word
// that is not a key name but is all hex digits is typed digit by digit). On error: nullopt, the
// message, and the 0-based offset of the word in `text`.
std::optional<std::vector<KeyRef>> parse_key_list(std::string_view text, std::string& error, std::size_t& offset);
// A register the script reads and sets (expect reg, set reg): one of the CPU's description
// (emu/core/cpu_registers.h), any case, but memory (M, which `expect mem` and `set mem` reach).
const cpu::Register* parse_reg(std::string_view text);

}  // namespace alp85::script
