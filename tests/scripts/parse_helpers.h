// Helpers of the parser tests: one line that must parse, or fail with exactly one error.
#pragma once

#include <gtest/gtest.h>

#include "emu/script/parser.h"

namespace alp85::script::test {

inline Command one(std::string_view line) {
    std::vector<ParseError> errors;
    auto c = parse_line(line, "t.alp", 1, errors);
    EXPECT_TRUE(errors.empty()) << (errors.empty() ? "" : errors[0].format());
    EXPECT_TRUE(c.has_value());
    return c.value_or(Command{});
}

// Parsed as line 7 of t.alp.
inline ParseError error_of(std::string_view line) {
    std::vector<ParseError> errors;
    auto c = parse_line(line, "t.alp", 7, errors);
    EXPECT_FALSE(c.has_value());
    EXPECT_EQ(errors.size(), 1u);
    return errors.empty() ? ParseError{} : errors[0];
}

}  // namespace alp85::script::test
