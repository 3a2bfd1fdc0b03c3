// The ALP85 command language (docs/scripting.md): one command per line, shared by `alp85 script`
// and the debugger's prompt. A Command is a parsed line; symbols in it are resolved when it runs.
#pragma once

#include <cstdint>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "emu/board/key_press.h"
#include "emu/core/cpu_registers.h"
#include "emu/debug/expr.h"
#include "peripherals/keypad.h"

namespace alp85::script {

struct Location {
    std::string file;
    int line = 0;
    int col = 0;
};

// A NUMBER, or an expression of the debugger's grammar (debug::Expr: SYMBOL, SYMBOL+N,
// (X1 + 1)*2, word[YAC], ...), resolved against the session's symbols when the command runs.
struct Value {
    std::string symbol;  // SYMBOL or SYMBOL+-N: the symbol, upper case (N in number); else empty
    std::int64_t number = 0;  // a number's value, or a constant expression's
    int col = 0;
    std::string text;    // as written, for messages
    bool expression = false;  // reads a name, a register or memory: evaluated when the command runs
    std::vector<debug::Expr::Name> names = {};  // what it reads, for the check before the run (columns in text)
};

// A key as the script names it: the board's button (emu/board/key_press.h schedules it).
struct KeyRef {
    Button kind = Button::Matrix;
    periph::Key key = periph::Key::K0;  // for Matrix
    std::string name;
};

enum class Compare : std::uint8_t { Lt, Le, Eq, Ge, Gt };

enum class Op : std::uint8_t {
    Load, Monitor, Firmware, Reset,
    Press, Type, KeyDown, KeyUp,
    Run, RunUntil, WaitDisplay, Step,
    Break, Delete, DeleteAll,
    ExpectDisplay, ExpectMem, ExpectWord, ExpectReg, ExpectFlag, ExpectPort, ExpectSymbol, ExpectTime,
    ExpectHalted, ExpectRunning,
    Motor, Feedback, NewWorkpiece, PrintAxes, PrintTime, Mark, ExpectAxis, ExpectCount, ExpectLost, RunUntilAxis, Record, RecordStop, Plot,
    SetMem, SetReg,
    Save, Restore,
    Option, Board,
    PrintDisplay, Print, PrintBoard,
};

struct Command {
    Op op = Op::Print;
    Location where;
    std::vector<Location> included_from;  // the `include` lines that brought this line in, innermost first
    std::string line;                   // the source line, for reports
    std::string text;                   // path, display text or message
    std::optional<Value> address;       // load at / run until / break / expect & set mem, word
    std::vector<Value> values;          // data bytes, register/port/symbol values
    std::vector<KeyRef> keys;
    std::uint64_t time = 0;             // run TIME, hold, timeout, expect time (T-states)
    std::uint64_t gap = 0;              // press: gap after release
    const cpu::Register* reg = nullptr; // expect & set reg: in the CPU's description (emu/core/cpu_registers.h)
    std::uint8_t flag = 0;              // flag bit (isa::Flag)
    std::string flag_name;              // as written (CY, C)
    char port = 'A';
    Compare compare = Compare::Eq;
    std::string name;                   // expect symbol NAME
    unsigned count = 1;                 // step N
    // The machine tool (docs/scripting.md, "The machine tool").
    std::uint8_t axis = 0;              // 0 X, 1 Y, 2 Z
    bool in_mm = false;                 // expect axis: mm (else steps)
    double real = 0;                    // expect axis ... mm V; motor: 0 ideal, 1 physical
    double within = 0;                  // expect axis ... mm V within D
    std::int64_t integer = 0;           // steps, counts, lost steps
    std::uint64_t period = 0;           // record ... every T
    bool signals = false;               // record signals FILE.vcd: the pins as a VCD (else the tool as CSV)
    std::vector<Value> pins;            // record signals FILE.vcd PIN...: the pins chosen (text, col)
    std::optional<std::array<double, 4>> ideal_line;  // plot toolpath ... from X,Y to X,Y (mm)
};

// Default times (docs/scripting.md).
inline constexpr std::uint64_t kDefaultHold = kKeyHold;    // 30 ms: 92160 T-states at 3.072 MHz
inline constexpr std::uint64_t kDefaultGap = kKeyGap;      // 30 ms
inline constexpr std::uint64_t kDefaultUntil = 30'720'000;  // 10 s
inline constexpr std::uint64_t kDefaultWait = 15'360'000;   // 5 s
inline constexpr std::uint64_t kDefaultRecordPeriod = 768;  // 0.25 ms: a 400 steps/s axis, ten samples a step
inline constexpr std::uint64_t kDefaultSignalPeriod = 96;   // 31.25 us: record signals' sample clock

}  // namespace alp85::script
