// The line tokenizer: names, numbers, strings and punctuation of one source line.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace alp85::asm85 {

enum class Tok : std::uint8_t { Ident, Number, String, Punct, End };

struct Token {
    Tok kind = Tok::End;
    std::string text;        // Ident: upper case, '$' separators removed; String: the characters
    std::uint32_t value = 0; // Number
    int col = 0;             // 0-based offset of the first character in the line
    int len = 0;             // characters in the source
    char punct = 0;          // Punct: the character ('$' = location counter, ':' also for '::')
    bool bad = false;        // Number: malformed (reported when evaluated)
};

struct LexError {
    int col = 0;
    std::string message;
};

// Characters that may start / continue a name (Intel, DR and M80 rules merged).
bool is_name_start(char c);
bool is_name_char(char c);

// Tokenizes `line` up to a ';' comment. Stops at the first error (reported in `error`).
// `radix` is the default base of numbers without a suffix (M80 .RADIX).
std::vector<Token> tokenize(std::string_view line, LexError& error, int radix = 10);

// Parses a number with an optional H, O, Q, B, D suffix; false if malformed or > 0xFFFF... values
// are kept to 32 bits and reduced by the caller.
bool parse_number(std::string_view digits, int radix, std::uint32_t& value);

std::string to_upper(std::string_view s);

}  // namespace alp85::asm85
