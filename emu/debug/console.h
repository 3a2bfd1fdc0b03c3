// The debugger's command line as a library: one line of text in, the text to show out. `alp85
// debug` puts it behind a terminal (libedit), the GUI behind its command pane, and a DAP server
// may pass its REPL input through it. gdb's names and abbreviations where gdb has one (docs/debugging.md):
//
//   break/b tbreak/tb watch/wa rwatch awatch delete/d enable disable condition ignore commands...end
//   continue/c step/s stepi/si next/n nexti/ni finish/fin until/u advance run [for] TIME
//   reverse-step/rs reverse-stepi/rsi reverse-next/rn reverse-nexti/rni reverse-finish/rfin
//   reverse-continue/rc  print/p x display/disp undisplay set list/l disassemble/disas
//   backtrace/bt frame/f up down jump/j info/i (registers breakpoints watchpoints display displays
//   PART axis line frame symbol) history echo output help quit/q
//
// A line it does not know goes to the fallback: `alp85 debug` passes it to the script language
// and adds the script's commands to the console's one table (add_commands), so every script
// command works at the prompt too and help and completion list it.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "emu/debug/debugger.h"
#include "emu/debug/expr.h"

namespace alp85::debug {

class Console {
public:
    // Runs a line the console does not know; appends what to show to `out`. Returns false when the
    // line failed (an error, a failed expectation): the console counts it as an error.
    using Fallback = std::function<bool(std::string_view line, std::string& out)>;
    // The text of a source file (for list and stop reports); default: read from disk.
    using SourceReader = std::function<std::optional<std::string>(const std::string& file)>;

    explicit Console(Debugger& d);

    void set_fallback(Fallback f) { fallback_ = std::move(f); }
    // Where lines come from, for error messages ("session.gdb:12:5: error: ..."); empty: "column N".
    void set_origin(std::string file, int line) {
        origin_file_ = std::move(file);
        origin_line_ = line;
    }

    // Runs one line; returns the text to show (each line ending in '\n'), possibly empty.
    std::string execute(std::string_view line);
    // The prompt to show before the next line: "(alp85) ", or ">" while reading commands ... end.
    std::string prompt() const { return collecting_ ? ">" : "(alp85) "; }
    bool quit_requested() const { return quit_; }
    // Errors and failed fallback lines so far (batch sessions end with status 1 after one).
    int errors() const { return errors_; }
    // Command names and symbols that complete `word` (at the start of the line: commands).
    // After a command that takes a file name (load, save, restore, record, plot, source, ...; given
    // as `command`) or for a word that looks like a path, the files and folders that complete it.
    std::vector<std::string> complete(std::string_view word, bool first_word, std::string_view command = {}) const;
    // What `alp85 debug` says when it starts at a terminal (as gdb's banner).
    std::string banner() const;
    // The command a word names: its name for the name itself, an alias or a unique prefix ("c",
    // "cont" -> "continue"); nullopt for none (or an ambiguous prefix). For front ends that run
    // some commands their own way (DAP begins the runs as resumable ones).
    std::optional<std::string_view> command_name(std::string_view word) const;
    // The stop as the console reports it (header, source line, displays); no commands run.
    std::string describe(const Stop& s);
    // What `info WHAT` shows (registers, a part by its name, axis, breakpoints, ...), for panes.
    std::string info(std::string_view what) { return cmd_info(what, 1); }
    // A line of a loaded program's source (read once, kept), or nullopt.
    std::optional<std::string> source_line(const SourceLine& l);

    // One command of the prompt: the console's own (with its handler) or one a layer above added
    // (the fallback runs it: alp85 debug adds the script language's, script::commands()).
    using Handler = std::string (Console::*)(std::string_view args, int col);
    struct CommandDef {
        std::string_view name;
        std::vector<std::string_view> aliases;
        Handler handler = nullptr;  // null: an added command
        std::string_view help;      // "usage: what it does"
        // An added command whose name the console has too: the words after the name that make a
        // line the added one's ("\"": a quoted string). None: the console's takes every line.
        std::vector<std::string_view> forms;
        bool takes_file = false;    // completion offers file names after it
    };
    // Commands the fallback runs, matched by their whole name (the console's own also by alias and
    // by a unique prefix). Views into `defs` are kept: its strings must outlive the console.
    void add_commands(const std::vector<CommandDef>& defs);
    // The one list of commands: the console's, then the added ones. help, completion and
    // docs/debugging.md's table come from it.
    const std::vector<CommandDef>& commands() const { return table_; }

private:
    struct Display {
        int number = 0;
        char format = 0;
        Expr expr;
    };
    static std::vector<CommandDef> own_commands();
    const CommandDef* find_command(std::string_view word, std::string& error) const;
    // The added command that takes a line the console's command `own` would (print "text", set
    // mem, run until, expect reg, ...), or null.
    const CommandDef* added_form(const CommandDef& own, std::string_view rest) const;

    std::string error(int col, std::string message);
    // TEXT (at column `col`) parsed and evaluated now, into `out`; or this line's error: a parse
    // error, or one of evaluation (1/0) — never an exception out of the console.
    std::string evaluate(std::string_view text, int col, Expr::Names names, std::int64_t& out);
    // The same with symbols first, and the value an address: 0000H-FFFFH.
    std::string address(std::string_view text, int col, std::int64_t& out);
    std::string report(const Stop& s);  // describe, then the breakpoint's commands
    // The commands of the point that made stop `s`, and of each stop a resuming command among them
    // reaches (gdb: such a command is the list's last; the lists run one after another, not nested).
    std::string run_commands(Stop s);
    bool silent(const Stop& s) const;  // its commands begin with `silent`: no stop report
    std::string location_lines(std::uint16_t pc);
    std::string run_fallback(std::string_view line);
    std::string format_value(std::int64_t v, int width, char fmt) const;
    // print and output: [/FMT] EXPR evaluated and formatted, as "$N = VALUE\n" when `numbered`
    // (print's history number) or the value alone; `missing` is the error for no expression.
    std::string formatted_expression(std::string_view a, int col, std::string_view missing, bool numbered);
    std::optional<int> number_arg(std::string_view& args, int& col, std::string& err);
    // enable and disable: the points numbered in `a`, or every one.
    std::string set_enabled(std::string_view a, int col, bool on);
    std::string for_each_number(std::string_view a, int col, std::string_view what, const std::function<bool(int)>& act);

    // handlers (console.cpp: control and points; console_view.cpp: looking)
    std::string cmd_break(std::string_view a, int col);
    std::string cmd_tbreak(std::string_view a, int col);
    std::string breakpoint(std::string_view a, int col, bool temporary);
    static std::optional<std::uint64_t> tstates_of(std::string_view time);  // 10ms, 2s, 3070t
    std::string cmd_watch(std::string_view a, int col);
    std::string cmd_rwatch(std::string_view a, int col);
    std::string cmd_awatch(std::string_view a, int col);
    std::string watch(std::string_view a, int col, WatchKind kind);
    std::string cmd_delete(std::string_view a, int col);
    std::string cmd_enable(std::string_view a, int col);
    std::string cmd_disable(std::string_view a, int col);
    std::string cmd_condition(std::string_view a, int col);
    std::string cmd_ignore(std::string_view a, int col);
    std::string cmd_commands(std::string_view a, int col);
    std::string cmd_continue(std::string_view a, int col);
    std::string cmd_step(std::string_view a, int col);
    std::string cmd_stepi(std::string_view a, int col);
    std::string cmd_next(std::string_view a, int col);
    std::string cmd_nexti(std::string_view a, int col);
    std::string repeat(std::string_view a, int col, Stop (Debugger::*op)());
    std::string cmd_finish(std::string_view a, int col);
    std::string cmd_until(std::string_view a, int col);
    std::string cmd_advance(std::string_view a, int col);
    std::string cmd_run(std::string_view a, int col);
    std::string cmd_rs(std::string_view a, int col);
    std::string cmd_rsi(std::string_view a, int col);
    std::string cmd_rn(std::string_view a, int col);
    std::string cmd_rfin(std::string_view a, int col);
    std::string cmd_rc(std::string_view a, int col);
    std::string cmd_print(std::string_view a, int col);
    std::string cmd_set(std::string_view a, int col);
    std::string cmd_display(std::string_view a, int col);
    std::string cmd_undisplay(std::string_view a, int col);
    std::string cmd_x(std::string_view a, int col);
    std::string cmd_list(std::string_view a, int col);
    std::string cmd_disassemble(std::string_view a, int col);
    std::string cmd_backtrace(std::string_view a, int col);
    std::string cmd_frame(std::string_view a, int col);
    std::optional<std::size_t> frame_count(std::string_view a, int col, std::string& err);
    std::string cmd_up(std::string_view a, int col);
    std::string cmd_down(std::string_view a, int col);
    std::string cmd_jump(std::string_view a, int col);
    std::string cmd_info(std::string_view a, int col);
    std::string cmd_history(std::string_view a, int col);
    std::string cmd_timing(std::string_view a, int col);
    std::string cmd_echo(std::string_view a, int col);
    std::string cmd_output(std::string_view a, int col);
    std::string cmd_expect(std::string_view a, int col);
    std::string cmd_help(std::string_view a, int col);
    std::string whole_help(const CommandDef& c) const;
    std::string cmd_quit(std::string_view a, int col);
    // info ...
    std::string info_registers();
    std::string info_breakpoints(bool watchpoints_only = false);
    std::string info_symbol(std::string_view a, int col);
    std::string show_frame(std::size_t n);  // "#N ADDR in NAME at FILE:LINE" and its source line
    // x's text for `count` units at `addr` in format `fmt` (x d u o t c a s i) and unit b/w; `next`:
    // the address after them.
    std::string examine(std::uint16_t addr, int count, char fmt, char unit, std::uint16_t& next);
    std::string info_displays();
    std::string info_part(const periph::Part& part);
    // The part whose name the first words (upper case) spell, and how many words that took.
    std::pair<periph::Part*, std::size_t> part_named(const std::vector<std::string>& words) const;
    std::string info_axis(std::string_view which, int col);
    std::string info_display();
    std::string show_displays();
    std::string list_range(std::string_view a, int col);
    std::string list_lines(const std::string& file, int first, int last, int col);
    std::string show_display(const Display& d);

    Debugger& d_;
    std::vector<CommandDef> table_;
    Fallback fallback_;
    SourceReader read_source_;
    std::map<std::string, std::vector<std::string>> sources_;  // file -> lines
    std::vector<Display> displays_;
    Expr::Variables& vars_;  // set $NAME = EXPR: the Debugger's, read by conditions too
    int last_display_ = 0;
    int print_count_ = 0;
    bool quit_ = false;
    int errors_ = 0;
    std::string origin_file_;
    int origin_line_ = 0;
    std::string line_;  // the line being executed (for carets)
    bool collecting_ = false;
    int collect_for_ = 0;
    std::vector<std::string> collected_;
    // x and list continue where they stopped.
    std::uint16_t next_x_ = 0;
    char x_format_ = 'x', x_unit_ = 'b';
    std::optional<SourceLine> next_list_;
    std::size_t selected_frame_ = 0;   // up, down, frame N; 0 again at every stop
    std::optional<SourceLine> frame_line_;  // the selected frame's line: a plain list centres there
    std::vector<int> temporary_;       // tbreak numbers: their stops say "Temporary breakpoint N"
    bool in_fallback_ = false;
    std::string fallback_out_;
    std::optional<Stop> fallback_stop_;  // where a script command the fallback ran stopped
    bool in_commands_ = false;           // a breakpoint's commands are running
    std::optional<Stop> resumed_;        // the stop a resuming command among them reached
};

}  // namespace alp85::debug
