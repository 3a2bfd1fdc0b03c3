// Expressions with Intel ASM80 precedence, evaluated in 16-bit unsigned arithmetic.
//
// Highest to lowest: ( ); HIGH LOW; * / MOD SHL SHR; + - (unary and binary);
// EQ NE LT LE GT GE; NOT; AND; OR XOR. Relations yield 0FFFFH (true) or 0.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "asm/lexer.h"

namespace alp85::asm85 {

struct Value {
    std::uint16_t v = 0;
    bool known = true;  // false: depends on a symbol not (yet) defined
};

struct ExprContext {
    // Value of a name (symbol or, where allowed, register). Reports its own errors.
    std::function<Value(const Token&)> lookup;
    std::function<void(int col, const std::string& msg)> error;
    std::uint16_t pc = 0;  // '$'
    // Whether a name is an instruction mnemonic, and the value of "(mnemonic operands)".
    std::function<bool(const std::string&)> is_mnemonic;
    std::function<Value(std::size_t first, std::size_t last)> instruction;
};

// Evaluates the expression starting at toks[pos]; stops before a ',' or the end token at nesting
// level zero. Returns false after reporting an error. On success pos is left at the stopper.
bool eval_expr(const std::vector<Token>& toks, std::size_t& pos, ExprContext& ctx, Value& out);

// True if the name is an operator word (MOD, AND, HIGH, ...), which can't be a symbol.
bool is_operator_word(const std::string& upper);

}  // namespace alp85::asm85
