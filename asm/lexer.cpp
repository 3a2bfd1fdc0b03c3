#include "asm/lexer.h"

#include <cctype>

namespace alp85::asm85 {

bool is_name_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '?' || c == '@' || c == '_' || c == '.';
}

bool is_name_char(char c) {
    return is_name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '$';
}

std::string to_upper(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

static int digit_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'Z') return c - 'A' + 10;
    return 99;
}

bool parse_number(std::string_view text, int radix, std::uint32_t& value) {
    std::string d;
    for (char c : text)
        if (c != '$') d += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));  // DR: 1$000B
    if (d.empty()) return false;
    int base = radix;
    char last = d.back();
    // The suffix wins; with a radix of 16, trailing B and D are digits (M80's rule).
    if (last == 'H') base = 16, d.pop_back();
    else if (last == 'O' || last == 'Q') base = 8, d.pop_back();
    else if (last == 'B' && radix <= 11) base = 2, d.pop_back();
    else if (last == 'D' && radix <= 13) base = 10, d.pop_back();
    if (d.empty()) return false;
    std::uint64_t v = 0;
    for (char c : d) {
        int dv = digit_value(c);
        if (dv >= base) return false;
        v = v * static_cast<unsigned>(base) + static_cast<unsigned>(dv);
        if (v > 0xFFFFFFFFu) v = 0x100000000u;  // saturate; caller reports > 16 bits
    }
    value = static_cast<std::uint32_t>(v > 0xFFFFFFFFu ? 0xFFFFFFFFu : v);
    return true;
}

std::vector<Token> tokenize(std::string_view line, LexError& error, int radix) {
    std::vector<Token> out;
    std::size_t i = 0;
    const std::size_t n = line.size();
    while (i < n) {
        char c = line[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\x1a') { ++i; continue; }
        if (c == ';') break;
        Token t;
        t.col = static_cast<int>(i);
        if (std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t j = i;
            while (j < n && (std::isalnum(static_cast<unsigned char>(line[j])) || line[j] == '$')) ++j;
            t.kind = Tok::Number;
            t.len = static_cast<int>(j - i);
            t.text = to_upper(line.substr(i, j - i));
            t.bad = !parse_number(line.substr(i, j - i), radix, t.value);  // reported where used
            i = j;
        } else if (is_name_start(c)) {
            std::size_t j = i;
            while (j < n && is_name_char(line[j])) ++j;
            t.kind = Tok::Ident;
            t.len = static_cast<int>(j - i);
            for (std::size_t k = i; k < j; ++k)
                if (line[k] != '$') t.text += static_cast<char>(std::toupper(static_cast<unsigned char>(line[k])));
            i = j;
        } else if (c == '\'' || c == '"') {
            std::size_t j = i + 1;
            bool closed = false;
            while (j < n) {
                if (line[j] == c) {
                    if (j + 1 < n && line[j + 1] == c) { t.text += c; j += 2; continue; }
                    closed = true;
                    ++j;
                    break;
                }
                t.text += line[j++];
            }
            if (!closed) {
                error = {t.col, "unterminated string"};
                break;
            }
            t.kind = Tok::String;
            t.len = static_cast<int>(j - i);
            i = j;
        } else {
            t.kind = Tok::Punct;
            t.punct = c;
            t.len = 1;
            if (c == ':' && i + 1 < n && line[i + 1] == ':') t.len = 2;  // M80 public label
            i += static_cast<std::size_t>(t.len);
        }
        out.push_back(std::move(t));
    }
    Token end;
    end.kind = Tok::End;
    end.col = static_cast<int>(std::min(i, n));
    out.push_back(end);
    return out;
}

}  // namespace alp85::asm85
