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

// One line. An empty or comment-only line gives nullopt and no error.
std::optional<Command> parse_line(std::string_view line, const std::string& file, int line_no,
                                  std::vector<ParseError>& errors);

// A whole script: every line, every error (not only the first).
std::vector<Command> parse_script(std::string_view text, const std::string& file, std::vector<ParseError>& errors);

// Pieces the debugger's prompt and the runner reuse.
std::optional<std::int64_t> parse_number(std::string_view text);     // 12, 0CH, 0xC, 1100B, 14O/14Q
std::optional<std::uint64_t> parse_time(std::string_view text);      // 3070t, 250us, 10ms, 1.5s
std::optional<KeyRef> parse_key(std::string_view text);
std::optional<Reg> parse_reg(std::string_view text);
std::string_view reg_name(Reg r);

}  // namespace alp85::script
