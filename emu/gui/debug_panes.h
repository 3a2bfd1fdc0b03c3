// The debugger's panes (`alp85 gui --debug`), in place of the machine tool's views: source with the
// current line and breakpoints (a click on a line sets or clears one), registers and flags,
// disassembly, memory, the parts (a tab each, from their descriptions), a watch list, step/next/finish and their reverse
// buttons, and the debugger's command line. They drive the same script::DebugShell (and so the same
// Machine and debug::Debugger) as `alp85 debug`: a button is a request (Continue, Step, ...) the
// window carries out through the Debugger; the command line is a line of the console.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "emu/program/symbols.h"
#include "emu/script/debug_shell.h"

namespace alp85::gui {

struct DebugPanes {
    std::string file;         // the source shown
    int first = 1;            // its first line shown
    std::uint16_t last_pc = 0xFFFF;
    std::uint64_t last_t = ~0ull;
    std::string command;      // the command line being typed
    std::deque<std::string> log;
    std::vector<std::string> watches{"word[YAC]", "word[XAC]", "word[1B30H]"};
    std::string new_watch;
    std::string memory = "1B00H";
    std::string registers;         // text, refreshed when the machine moved
    struct PartPane {
        std::string name;                // the part's name: the tab's label
        std::vector<std::string> lines;  // its description as `info PART` renders it
    };
    std::vector<PartPane> parts;   // every part that describes itself, in the machine's order
    std::string shown_part;        // the tab to bring forward (a test, or empty: the user's choice)
    // The source pane follows the PC, unless the user chose what it shows (a file from the
    // chooser, `list X`, a frame of the call stack, the wheel): that stays, while the machine runs
    // too, until the next stop.
    bool pinned = false;
    std::vector<debug::Frame> frames;  // the call stack, refreshed with the registers
    std::vector<std::string> files;    // every source of the loaded program's map, for the chooser
    // A run button pressed this frame: the app carries it out on the Debugger.
    enum class Request : std::uint8_t {
        None, Continue, Pause, Step, Next, Finish, ReverseContinue, ReverseStep, ReverseNext, ReverseFinish,
    };
    Request request = Request::None;

    // The source line shown in row i, or nullopt.
    std::optional<SourceLine> line_in_row(int row) const;
    // Shows `l` (the PC's line, or a line to click).
    void show(const SourceLine& l);
    // Shows `l` at the user's choice (centred, pinned).
    void show_chosen(const SourceLine& l);
    void add_log(const std::string& text);
};

// The Registers pane's text: the CPU's description (emu/core/cpu_registers.h) as rows of each
// pair's two bytes, beside them the registers that stand alone, the memory a pair addresses
// ([HL]) and HALTED; then the flags, the interrupt state and the time.
std::string registers_text(const debug::Debugger& d);
// The parts' panes as the chip pane draws them (every part with a description).
std::vector<DebugPanes::PartPane> part_panes(script::DebugShell& shell);
// A command line typed while the machine runs: those that only arm a stop or list (break, tbreak,
// watch, rwatch, awatch, display, info breakpoints) run at once; the others (a step, a memory
// write, ...) would take the machine from under the run and are answered "pause first".
bool runs_while_running(std::string_view line);
// Runs a typed line as the command pane does and logs it; while `running` a line that cannot run
// now is answered, not run. Returns the answer and whether it ran.
struct Typed {
    std::string out;
    bool ran = false;
};
Typed run_typed(DebugPanes& p, script::DebugShell& shell, const std::string& line, bool running);
// A part's lines in its tab of the chip pane, wrapped at the pane's width (none is cut off).
void draw_part_lines(const DebugPanes::PartPane& part);
// Draws the panes; lines the user asked for (buttons, the command line) are run on `shell`.
void draw_debug_panes(DebugPanes& p, script::DebugShell& shell, bool running);
// The source line a `list` command line shows first (list FILE:LINE, list N, list SYMBOL or
// address), or nullopt (a plain `list`, a line that is not a list, or one that names no line).
std::optional<SourceLine> list_target(const DebugPanes& p, script::DebugShell& shell, std::string_view line);
// A click on source row `row`: sets a breakpoint on that line, or deletes the one there.
void toggle_breakpoint(DebugPanes& p, script::DebugShell& shell, int row);

}  // namespace alp85::gui
