// Helpers of the parser and session tests: one line that must parse, or fail with exactly one
// error; a Session on the board's test programs that runs script lines.
#pragma once

#include <gtest/gtest.h>

#include "emu/script/parser.h"
#include "emu/script/session.h"

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

// A Session on tests/board/programs; run() parses one line (numbered on from 1) and executes it.
class SessionLines : public ::testing::Test {
protected:
    SessionLines() : s(SessionOptions{ALP85_BOARD_PROGRAMS, Variant::I8085, {}, nullptr, false}) {}
    Session::Outcome run(std::string_view line) {
        std::vector<ParseError> errors;
        auto c = parse_line(line, "t.alp", ++n, errors);
        EXPECT_TRUE(errors.empty() && c) << line << (errors.empty() ? "" : ": " + errors[0].message);
        return c ? s.execute(*c) : Session::Outcome{Session::Status::Failed, "parse"};
    }
    void ok(std::string_view line) {
        const auto o = run(line);
        EXPECT_EQ(o.status, Session::Status::Ok) << line << "\n" << o.message;
    }
    Session s;
    int n = 0;
};

}  // namespace alp85::script::test
