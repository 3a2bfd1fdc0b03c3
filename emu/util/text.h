// Small text helpers shared by the layers (one definition each).
#pragma once

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace alp85 {

// ASCII upper case: symbol names, command words.
inline std::string to_upper(std::string_view s) {
    std::string u(s);
    std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return u;
}

// ASCII lower case: protocol header names, file names compared without case.
inline std::string to_lower(std::string_view s) {
    std::string u(s);
    std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return u;
}

// A file's extension in lower case, with its dot (".asm"): what decides how an image is read.
inline std::string lower_extension(const std::filesystem::path& p) {
    std::string e = p.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return e;
}

// `s` without leading and trailing blanks; `col`, if given, advances past the leading ones (the
// column of what is left, for error messages).
inline std::string_view trim_blanks(std::string_view s, int* col = nullptr) {
    std::size_t a = 0;
    while (a < s.size() && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    std::size_t b = s.size();
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    if (col) *col += static_cast<int>(a);
    return s.substr(a, b - a);
}

// An address as the listings write it: "1B32H".
inline std::string hex4h(std::uint16_t v) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    return {kDigits[v >> 12], kDigits[(v >> 8) & 15], kDigits[(v >> 4) & 15], kDigits[v & 15], 'H'};
}

// Text for XML (JUnit reports, SVG titles): the five entities escaped; control characters XML 1.0
// does not allow become '?'.
inline std::string xml_escape(std::string_view s) {
    std::string out;
    for (char ch : s) {
        switch (ch) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default:
                // XML 1.0 allows no control characters other than tab, newline and return.
                if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n' && ch != '\r') out += '?';
                else out += ch;
        }
    }
    return out;
}

// A number as the 8085 world writes it: 12, 12D, 0CH, 0xC, 1100B, 14O/14Q (a hex number starts
// with a digit). nullopt if it is not one.
inline std::optional<std::int64_t> parse_int(std::string_view text) {
    if (text.empty()) return std::nullopt;
    std::string s = to_upper(text);
    int base = 10;
    bool prefixed = false;  // 0x: the prefix, not a leading digit, says it is a number
    if (s.size() > 2 && s[0] == '0' && s[1] == 'X') {
        base = 16;
        prefixed = true;
        s = s.substr(2);
    } else if (s.size() > 1 && s.back() == 'H') {
        base = 16;
        s.pop_back();
    } else if (s.size() > 1 && (s.back() == 'O' || s.back() == 'Q')) {
        base = 8;
        s.pop_back();
    } else if (s.size() > 1 && s.back() == 'B') {
        base = 2;
        s.pop_back();
    } else if (s.size() > 1 && s.back() == 'D') {
        s.pop_back();
    }
    if (s.empty() || s.size() > 16 || (!prefixed && !std::isdigit(static_cast<unsigned char>(s[0])))) return std::nullopt;
    std::uint64_t v = 0;  // 16 hex digits fill all 64 bits: kept as the machine word's bits
    for (char ch : s) {
        int d;
        if (ch >= '0' && ch <= '9') d = ch - '0';
        else if (ch >= 'A' && ch <= 'F') d = ch - 'A' + 10;
        else return std::nullopt;
        if (d >= base) return std::nullopt;
        v = v * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(d);
    }
    return static_cast<std::int64_t>(v);
}

}  // namespace alp85
