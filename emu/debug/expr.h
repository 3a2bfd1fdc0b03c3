// The debugger's expressions: `print`, `set`, breakpoint and watchpoint conditions, `display`.
//
//   numbers   12  0CH  0x0C  1100B  14Q  'A'          (as the command language writes them)
//   registers the CPU's description (emu/core/cpu_registers.h): A F B C D E H L PSW BC DE HL SP PC,
//             M (= [HL]), or with a $ ($A, $PC)
//   flags     S Z AC P CY V K (X5 for K) (0 or 1), or $S ...
//             $T: the T-state counter; $NAME: a variable
//   symbols   OUT  YAC+1  &Z   (a bare name is a register or flag first: &NAME is always the symbol),
//             spelled as asm85 spells them (a letter, _ ? @ or . first; then digits and $ too)
//   memory    [HL]  byte[1B30H]  word[YAC]  (little-endian 16 bits)
//   operators unary - ! ~; * / %; + -; << >>; < <= > >=; == !=; &; ^; |; &&; ||; parentheses
//
// Parsed once (symbols resolved then) and evaluated many times: a breakpoint's condition costs a
// tree walk at that address only. Evaluation reads the machine through its side-effect-free views.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "emu/board/machine.h"
#include "emu/program/symbols.h"

namespace alp85::debug {

// A parse or evaluation error; `col` is 1-based within the text given to parse (0: none).
struct ExprError {
    int col = 0;
    std::string message;
};

class Expr {
public:
    // What a bare name means first: the expression's registers and flags, or (for locations:
    // `break Z` is the routine Z, not the zero flag) the program's symbols.
    enum class Names : std::uint8_t { RegistersFirst, SymbolsFirst };

    // nullopt and `error` (with its column, plus `col_base`) when `text` is not an expression.
    // `variables`: the front end's convenience variables ($t0 = a number), read as constants.
    using Variables = std::map<std::string, std::int64_t>;
    static std::optional<Expr> parse(std::string_view text, const SymbolTable& symbols, ExprError& error,
                                     Names names = Names::RegistersFirst, int col_base = 0,
                                     const Variables* variables = nullptr);

    // What a text reads before any symbol is known (the script language checks a script before its
    // loads have run): its names, each with its column (plus `col_base`) and whether it must be a
    // symbol (&NAME) or may be a register or flag; and its value when it reads no name, register,
    // flag, memory or time. A bare name is a symbol first (Names::SymbolsFirst). nullopt and `error`
    // when `text` is not an expression (1/0 included).
    struct Name {
        std::string name;  // upper case
        int col = 0;
        bool symbol_only = false;  // &NAME
        bool machine = false;      // also the name of a register or flag
    };
    struct Shape {
        std::vector<Name> names;
        std::optional<std::int64_t> constant;
    };
    static std::optional<Shape> shape(std::string_view text, ExprError& error, int col_base = 0);

    // The value now; throws ExprError for a division by zero.
    std::int64_t eval(const Machine& m) const { return eval(&m, root_); }
    // Width of the value in bits, for printing: 8 (a byte register, a flag's byte, byte[...]) or 16.
    int width() const { return width_; }
    const std::string& text() const { return text_; }

    // `set LVALUE = VALUE`: registers, flags, memory. False when the expression is not one of these.
    bool assignable() const;
    // Writes v (truncated to the target's width); returns an error message or "" (no memory there).
    std::string assign(Machine& m, std::int64_t v) const;

    enum class Kind : std::uint8_t {
        Number, Reg, Flag, Time, Mem8, Mem16,
        Var,  // a convenience variable ($NAME), read when evaluated
        Neg, Not, Compl,
        Mul, Div, Mod, Add, Sub, Shl, Shr, Lt, Le, Gt, Ge, Eq, Ne, BitAnd, BitXor, BitOr, And, Or,
    };
    struct Node {
        Kind kind = Kind::Number;
        std::int64_t value = 0;  // Number: the value; Reg: its index in cpu::description(); Flag: its bit
        int a = -1, b = -1;      // operands (node indices)
        int col = 0;
    };

private:
    std::int64_t eval(const Machine* m, int node) const;  // m: null for a constant (shape)

    std::vector<Node> nodes_;
    std::vector<std::string> var_names_;       // Var nodes: their names (value: the index)
    const Variables* vars_ = nullptr;          // where Var nodes are read
    int root_ = -1;
    int width_ = 16;
    std::string text_;
    friend class ExprParser;
};

// The flag bit of a flag's name or alias in the CPU's description (emu/core/cpu_registers.h), or nullopt.
std::optional<std::uint8_t> flag_named(std::string_view upper_name);
// A $NAME the machine gives and nothing can set: $T and $TIME, the T-state counter.
bool read_only_named(std::string_view upper_name);

}  // namespace alp85::debug
