// The debugger's expressions against hostile text (issue 23, item 1): 64-bit arithmetic wraps as
// two's complement does (no trap, no undefined behaviour), division by zero is an error, and a
// text nested or chained beyond the depth limit is refused with a message instead of exhausting
// the stack. Expected values by hand from the two's-complement definitions.
#include <cstdint>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "emu/board/machine.h"
#include "emu/debug/expr.h"

namespace alp85::debug {
namespace {

constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();

class Expressions : public ::testing::Test {
protected:
    Machine m;
    SymbolTable symbols;

    std::int64_t value(const std::string& text) {
        ExprError err;
        const auto e = Expr::parse(text, symbols, err);
        EXPECT_TRUE(e) << text << ": " << err.message;
        return e ? e->eval(m) : 0;
    }
    std::string parse_error(const std::string& text) {
        ExprError err;
        const auto e = Expr::parse(text, symbols, err);
        EXPECT_FALSE(e) << "accepted: " << text.substr(0, 40);
        return err.message;
    }
    std::string eval_error(const std::string& text) {
        ExprError err;
        const auto e = Expr::parse(text, symbols, err);
        if (!e) return "parse error: " + err.message;
        try {
            (void)e->eval(m);
        } catch (const ExprError& x) {
            return x.message;
        }
        return "no error";
    }
};

TEST_F(Expressions, DivisionOfTheMostNegativeNumberByMinusOneWraps) {
    // -(-2^63) is 2^63, which wraps to -2^63 in 64 bits; the remainder of any x / -1 is 0.
    EXPECT_EQ(value("(1<<63)/-1"), kMin);
    EXPECT_EQ(value("(1<<63)%-1"), 0);
    EXPECT_EQ(value("7/-1"), -7);
    EXPECT_EQ(value("7%-1"), 0);
    EXPECT_EQ(value("-7/2"), -3);  // C's truncation toward zero
    EXPECT_EQ(value("-7%2"), -1);
}

TEST_F(Expressions, OverflowWrapsInSixtyFourBits) {
    EXPECT_EQ(value("(1<<62)*4"), 0);                   // 2^64 mod 2^64
    EXPECT_EQ(value("((1<<63)-1)+1"), kMin);            // INT64_MAX + 1
    EXPECT_EQ(value("(1<<63)-1"), std::numeric_limits<std::int64_t>::max());
    EXPECT_EQ(value("-(1<<63)"), kMin);
    EXPECT_EQ(value("0xFFFFFFFFFFFFFFFF"), -1);         // 16 hex digits: all 64 bits
}

TEST_F(Expressions, DivisionByZeroIsAnError) {
    EXPECT_EQ(eval_error("1/0"), "division by zero");
    EXPECT_EQ(eval_error("1%(2-2)"), "division by zero");
}

TEST_F(Expressions, DeepNestingIsRefusedNotACrash) {
    const std::string deep = std::string(3000, '(') + "1" + std::string(3000, ')');
    EXPECT_NE(parse_error(deep).find("nested too deeply"), std::string::npos);
    EXPECT_NE(parse_error("[" + deep + "]").find("nested too deeply"), std::string::npos);
    EXPECT_NE(parse_error(std::string(5000, '-') + "1").find("nested too deeply"), std::string::npos);
    EXPECT_NE(parse_error(std::string(5000, '+') + "1").find("nested too deeply"), std::string::npos);
    // 100 levels is well inside the limit and gives the value.
    EXPECT_EQ(value(std::string(100, '(') + "5" + std::string(100, ')')), 5);
    EXPECT_EQ(value(std::string(100, '-') + "5"), 5);  // an even number of negations
}

TEST_F(Expressions, LongChainsAreRefusedNotACrash) {
    std::string sum = "1";
    for (int i = 1; i < 200000; ++i) sum += "+1";
    EXPECT_NE(parse_error(sum).find("too long"), std::string::npos);
    std::string ok = "1";
    for (int i = 1; i < 200; ++i) ok += "+1";
    EXPECT_EQ(value(ok), 200);
}

}  // namespace
}  // namespace alp85::debug
