// The console: parsing a line, breakpoints and watchpoints, running, and reporting stops.
#include "emu/debug/console.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "emu/util/text.h"

namespace alp85::debug {

namespace {
// The first word of `s` (split at blanks or '/'), and the rest after it.
std::string_view first_word(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])) && s[i] != '/') ++i;
    return s.substr(0, i);
}
// Splits "LOCATION if CONDITION" at a whole-word "if" (any case).
std::pair<std::string_view, std::string_view> split_if(std::string_view s, int& cond_col) {
    for (std::size_t i = 0; i + 2 <= s.size(); ++i) {
        const bool start = i == 0 || std::isspace(static_cast<unsigned char>(s[i - 1]));
        const bool end = i + 2 == s.size() || std::isspace(static_cast<unsigned char>(s[i + 2]));
        if (start && end && std::tolower(static_cast<unsigned char>(s[i])) == 'i' &&
            std::tolower(static_cast<unsigned char>(s[i + 1])) == 'f') {
            cond_col = static_cast<int>(i) + 2;
            return {s.substr(0, i), s.substr(i + 2)};
        }
    }
    return {s, {}};
}
}  // namespace

Console::Console(Debugger& d) : d_(d), table_(own_commands()), vars_(d.variables()) {
    read_source_ = [](const std::string& file) -> std::optional<std::string> {
        std::ifstream in(file, std::ios::binary);
        if (!in) return std::nullopt;
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    };
    // Text and stops of the script commands the fallback runs come as events.
    d_.listen([this](const Event& e) {
        if (!in_fallback_) return;
        switch (e.kind) {
            case Event::Kind::Output: fallback_out_ += e.text + '\n'; break;
            case Event::Kind::Stopped:
                // Its point's commands run once the script command has ended (run_fallback); inside
                // a breakpoint's commands the list that runs them reports the stop.
                fallback_stop_ = e.stop;
                if (!in_commands_) {
                    const std::string stop = describe(e.stop);
                    if (!silent(e.stop)) fallback_out_ += stop;
                }
                break;
            case Event::Kind::ExpectFailed: break;  // the fallback reports the failure
        }
    });
}

std::vector<Console::CommandDef> Console::own_commands() {
    struct Own {
        std::string_view name;
        std::string_view aliases;  // gdb's short names beside the unique prefixes, blank-separated
        Handler handler;
        std::string_view help;
    };
    static const std::vector<Own> defs = {
        {"break", "b br brea", &Console::cmd_break, "break [LOCATION] [if EXPR]: stop before the instruction at LOCATION (address, symbol, FILE:LINE)"},
        {"tbreak", "tb", &Console::cmd_tbreak, "tbreak [LOCATION] [if EXPR]: a breakpoint deleted at its first stop"},
        {"watch", "wa", &Console::cmd_watch, "watch WHAT [if EXPR]: stop after WHAT changes (memory written with a new value, a port, the machine tool, a chip register)"},
        {"rwatch", "rw", &Console::cmd_rwatch, "rwatch MEMORY [if EXPR]: stop after MEMORY is read"},
        {"awatch", "aw", &Console::cmd_awatch, "awatch MEMORY [if EXPR]: stop after MEMORY is read or written"},
        {"delete", "d", &Console::cmd_delete, "delete [N...|LOCATION|all]: delete breakpoints and watchpoints (all without N)"},
        {"enable", "en", &Console::cmd_enable, "enable [N...]: enable breakpoints and watchpoints"},
        {"disable", "dis disa", &Console::cmd_disable, "disable [N...]: disable breakpoints and watchpoints"},
        {"condition", "cond", &Console::cmd_condition, "condition N [EXPR]: stop at N only when EXPR is not 0 (no EXPR: always)"},
        {"ignore", "", &Console::cmd_ignore, "ignore N COUNT: pass N the next COUNT times"},
        {"commands", "comm", &Console::cmd_commands, "commands [N]: lines up to 'end' run at each stop of N (silent first: no stop report; one that resumes the run ends them; a log point: print ... then continue)"},
        {"continue", "c cont fg", &Console::cmd_continue, "continue [N]: run until a breakpoint or watchpoint (N: ignore this breakpoint N-1 more times)"},
        {"step", "s", &Console::cmd_step, "step [N]: one source line, into CALL and RST"},
        {"stepi", "si", &Console::cmd_stepi, "stepi [N]: one instruction, into CALL and RST"},
        {"next", "n", &Console::cmd_next, "next [N]: one line, a CALL or RST run whole"},
        {"nexti", "ni", &Console::cmd_nexti, "nexti [N]: one instruction, a CALL or RST run whole"},
        {"finish", "fin", &Console::cmd_finish, "finish: run until the current routine returns"},
        {"until", "u", &Console::cmd_until, "until [LOCATION]: run past this instruction in this routine (out of a loop), or to LOCATION"},
        {"advance", "", &Console::cmd_advance, "advance LOCATION: run until LOCATION"},
        {"run", "r", &Console::cmd_run, "run [for] TIME: run for TIME (10ms, 2s, 3070t), stopping at breakpoints; run until ... as in scripts"},
        {"reverse-step", "rs", &Console::cmd_rs, "reverse-step: back one line (into a routine that just returned)"},
        {"reverse-stepi", "rsi", &Console::cmd_rsi, "reverse-stepi: back one instruction"},
        {"reverse-next", "rn", &Console::cmd_rn, "reverse-next: back one line of this routine, a call undone whole"},
        {"reverse-nexti", "rni", &Console::cmd_rn, "reverse-nexti: as reverse-next"},
        {"reverse-finish", "rfin", &Console::cmd_rfin, "reverse-finish: back to the CALL that entered this routine"},
        {"reverse-continue", "rc", &Console::cmd_rc, "reverse-continue: back to the previous breakpoint or watchpoint hit"},
        {"print", "p inspect", &Console::cmd_print, "print[/x|d|t|c] EXPR: registers, flags, [HL], word[1B30H], symbols, arithmetic, comparison"},
        {"set", "", &Console::cmd_set, "set [var] LVALUE = EXPR: a register, flag or memory; set history on|off; set limit TIME: how long continue, finish, until and advance run before they give up (10 min of machine time)"},
        {"display", "disp", &Console::cmd_display, "display[/FMT] EXPR: print EXPR after every stop (no EXPR: now); /i and /s show memory at EXPR as x does (display/i $pc)"},
        {"undisplay", "undisp", &Console::cmd_undisplay, "undisplay [N...]: stop displaying"},
        {"x", "", &Console::cmd_x, "x/NFU ADDRESS: memory; F x d u o t c a s i, U b (byte) or w (16-bit word)"},
        {"list", "l", &Console::cmd_list, "list [LOCATION|FILE:LINE|FIRST,LAST]: source around it (or around the PC); FIRST,LAST: those lines (numbers or locations)"},
        {"disassemble", "disas", &Console::cmd_disassemble, "disassemble [LOCATION] [N]: N instructions with symbols and source lines"},
        {"backtrace", "bt where", &Console::cmd_backtrace, "backtrace: the routines called, from the return addresses on the stack"},
        {"frame", "f", &Console::cmd_frame, "frame [N]: select frame N of the backtrace (no N: show the selected one)"},
        {"up", "", &Console::cmd_up, "up [N]: select the frame N (default 1) calls out, the caller's"},
        {"down", "do", &Console::cmd_down, "down [N]: select the frame N (default 1) calls in"},
        {"jump", "j", &Console::cmd_jump, "jump LOCATION: continue at LOCATION (the PC set there, then continue)"},
        {"info", "i", &Console::cmd_info, "info registers|breakpoints|watchpoints|displays|display|board|PART (8155, 8279, ...)|axis [X|Y|Z]|line|frame|symbol ADDR"},
        {"timing", "", &Console::cmd_timing, "timing: the machine cycles of the next instruction as the 8085 data sheet draws them (IO/M, S1 S0, RD/WR, A15-A8, AD7-AD0; docs/signals.md)"},
        {"history", "", &Console::cmd_history, "history [N]: the last N instructions (default 10) with the registers each changed"},
        {"echo", "", &Console::cmd_echo, "echo TEXT: show TEXT (\\n a new line, \\t a tab, \\\\ a backslash); no new line of its own, as gdb's"},
        {"output", "", &Console::cmd_output, "output[/x|d|t|c] EXPR: EXPR's value alone, without $N = and without a new line (for breakpoint commands)"},
        {"expect", "", &Console::cmd_expect, "expect EXPR: an error unless EXPR is not 0 (for batch sessions); the script language's expect forms work too"},
        {"help", "h", &Console::cmd_help, "help [COMMAND]"},
        {"quit", "q exit", &Console::cmd_quit, "quit"},
    };
    std::vector<CommandDef> out;
    for (const Own& o : defs) {
        CommandDef c;
        c.name = o.name;
        for (std::string_view rest = o.aliases; !rest.empty();) {
            const std::size_t blank = rest.find(' ');
            c.aliases.push_back(rest.substr(0, blank));
            rest = blank == std::string_view::npos ? std::string_view{} : rest.substr(blank + 1);
        }
        c.handler = o.handler;
        c.help = o.help;
        out.push_back(std::move(c));
    }
    return out;
}

void Console::add_commands(const std::vector<CommandDef>& defs) {
    for (CommandDef c : defs) {
        c.handler = nullptr;
        table_.push_back(std::move(c));
    }
}

const Console::CommandDef* Console::added_form(const CommandDef& own, std::string_view rest) const {
    const std::string up = to_upper(trim_blanks(rest));
    const std::string next = up.substr(0, up.find(' '));
    for (const CommandDef& c : table_) {
        if (c.handler || c.name != own.name) continue;
        for (std::string_view f : c.forms)
            if (f == "\"" ? up.starts_with('"') : next == f) return &c;
    }
    return nullptr;
}

const Console::CommandDef* Console::find_command(std::string_view word, std::string& error) const {
    const std::string w = [&] {
        std::string s(word);
        std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        return s;
    }();
    // The console's own commands, by name, alias or prefix; an added one is the fallback's.
    for (const CommandDef& c : table_) {
        if (!c.handler) continue;
        if (c.name == w) return &c;
        for (std::string_view a : c.aliases)
            if (a == w) return &c;
    }
    // gdb: a unique prefix of a command's name
    const CommandDef* found = nullptr;
    for (const CommandDef& c : table_) {
        if (c.handler && w.size() >= 2 && c.name.substr(0, w.size()) == w) {
            if (found) {
                error = fmt::format("ambiguous command '{}' ({}, {}, ...)", word, found->name, c.name);
                return nullptr;
            }
            found = &c;
        }
    }
    return found;
}

std::optional<std::string_view> Console::command_name(std::string_view word) const {
    std::string err;
    const CommandDef* c = find_command(word, err);
    if (!c) return std::nullopt;
    return c->name;
}

std::string Console::error(int col, std::string message) {
    ++errors_;
    const std::string where = origin_file_.empty() ? fmt::format("column {}", col)
                                                   : fmt::format("{}:{}:{}", origin_file_, origin_line_, col);
    return fmt::format("{}: error: {}\n  {}\n  {}^\n", where, message, line_, std::string(static_cast<std::size_t>(std::max(col - 1, 0)), ' '));
}

std::string Console::execute(std::string_view line) {
    line_ = std::string(line);
    if (!in_commands_) d_.interrupt_clear();  // a Ctrl-C during a breakpoint's commands ends them
    if (collecting_) {
        const std::string_view t = trim_blanks(line);
        if (to_upper(t) == "END") {
            collecting_ = false;
            d_.set_commands(collect_for_, collected_);
            return {};
        }
        collected_.emplace_back(t);
        return {};
    }
    int col = 1;
    const std::string_view t = trim_blanks(line, &col);
    if (t.empty() || t.front() == '#') return {};
    const std::string_view word = first_word(t);
    std::string err;
    const CommandDef* c = find_command(word, err);
    if (!err.empty()) return error(col, err);
    // Added commands that share a name with one of the console's take their own forms: the
    // script's print "text", print display, set mem, set reg, run until, expect reg ...
    if (c && added_form(*c, t.substr(word.size()))) c = nullptr;
    if (!c) {
        // The script's run until passes breakpoints (Debugger::run_to): say so, and where it ended.
        const std::string up = to_upper(t);
        if (up.starts_with("RUN ") && to_upper(first_word(trim_blanks(t.substr(3)))) == "UNTIL" &&
            to_upper(first_word(trim_blanks(trim_blanks(t.substr(3)).substr(5)))) != "AXIS") {
            const bool armed = std::any_of(d_.breakpoints().begin(), d_.breakpoints().end(), [](const Breakpoint& b) { return b.enabled; });
            std::string out = armed ? "run until does not stop at breakpoints (advance LOCATION does)\n" : "";
            out += run_fallback(t);
            return out + describe(d_.here(StopReason::Target));
        }
        return run_fallback(t);
    }
    int acol = col + static_cast<int>(word.size());
    const std::string_view args = trim_blanks(t.substr(word.size()), &acol);
    try {
        std::string out = (this->*(c->handler))(args, acol);
        if (d_.take_time_limit_hit()) ++errors_;  // a run stopped at --max-time: the command failed
        return out;
    } catch (const std::exception& e) {  // nothing a command does ends the session
        return error(col, e.what());
    }
}

std::string Console::run_fallback(std::string_view line) {
    if (!fallback_) return error(1, fmt::format("unknown command '{}' (help lists the commands)", first_word(line)));
    in_fallback_ = true;
    fallback_out_.clear();
    fallback_stop_.reset();
    std::string out;
    const bool ok = fallback_(line, out);
    in_fallback_ = false;
    if (!ok) ++errors_;
    out = fallback_out_ + out;
    if (fallback_stop_) {  // press, type, wait ... stopped at a point: its commands run as at any stop
        const Stop s = *fallback_stop_;
        fallback_stop_.reset();
        if (in_commands_) resumed_ = s;
        else out += run_commands(s);
    }
    return out;
}

// ---- reporting stops ----------------------------------------------------------------------------

std::optional<std::string> Console::source_line(const SourceLine& l) {
    auto it = sources_.find(l.file);
    if (it == sources_.end()) {
        std::vector<std::string> lines;
        if (auto text = read_source_(l.file)) {
            std::istringstream in(*text);
            for (std::string s; std::getline(in, s);) {
                if (!s.empty() && s.back() == '\r') s.pop_back();
                lines.push_back(std::move(s));
            }
        }
        it = sources_.emplace(l.file, std::move(lines)).first;
    }
    if (l.line < 1 || static_cast<std::size_t>(l.line) > it->second.size()) return std::nullopt;
    std::string s = it->second[static_cast<std::size_t>(l.line - 1)];
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    return s;
}

std::string Console::location_lines(std::uint16_t pc) {
    if (pc == d_.machine().cpu().regs().pc) pc = d_.where();  // a halted CPU: at its HLT
    const auto frames = d_.backtrace();
    const std::string routine = frames.front().routine ? *frames.front().routine : "??";
    const auto line = d_.program().line_of(pc);
    std::string out = fmt::format("{} ({})", routine, hex4h(pc));
    if (line) out += fmt::format(" at {}:{}", std::filesystem::path(line->file).filename().string(), line->line);
    out += '\n';
    const auto src = line ? source_line(*line) : std::nullopt;
    if (src)
        out += fmt::format("{}\t{}\n", line->line, *src);
    else
        out += fmt::format("{}\t{}\n", hex4h(pc), disassemble(d_.machine().bus(), pc, d_.machine().cpu().variant(), &d_.program()).text);
    return out;
}

std::string Console::describe(const Stop& s) {
    selected_frame_ = 0;  // gdb: a stop selects the innermost frame, and list starts at it again
    next_list_.reset();
    frame_line_.reset();
    std::string out;
    switch (s.reason) {
        case StopReason::Breakpoint:
            if (std::find(temporary_.begin(), temporary_.end(), s.number) != temporary_.end())
                out += fmt::format("\nTemporary breakpoint {}, ", s.number);
            else
                out += s.number ? fmt::format("\nBreakpoint {}, ", s.number) : "\nBreakpoint, ";
            break;
        case StopReason::Watchpoint:
            if (s.number) {
                for (const Change& c : s.changes) {
                    out += fmt::format("\nWatchpoint {}: {}\n", c.number, c.what);
                    if (c.value_only) {
                        out += fmt::format("Value = {}\n", format_value(c.new_value, 8, 0));
                    } else if (c.digits == 0) {
                        out += fmt::format("Old value = {}\nNew value = {}\n", c.old_value, c.new_value);
                    } else {
                        const int w = c.digits == 4 ? 16 : 8;
                        out += fmt::format("Old value = {}\nNew value = {}\n", format_value(c.old_value, w, 0),
                                           format_value(c.new_value, w, 0));
                    }
                }
                if (s.after)
                    out += fmt::format("after {}  {}\n", hex4h(*s.after),
                                       disassemble(d_.machine().bus(), *s.after, d_.machine().cpu().variant(), &d_.program()).text);
            } else {
                out += fmt::format("\nWatchpoint at {}\n", s.data ? hex4h(*s.data) : "?");
            }
            break;
        case StopReason::Finished: out += "Run till exit: returned to "; break;
        case StopReason::Interrupted: out += "\nInterrupted (Ctrl-C) at "; break;
        case StopReason::HistoryStart: out += fmt::format("\n{}: at ", s.message); break;
        case StopReason::Error: out += fmt::format("\nStopped: {}\n", s.message); break;
        case StopReason::Runaway: out += fmt::format("\nStopped: {}\n", s.message); break;
        case StopReason::Halted: out += fmt::format("\n[{}]\n", s.message); break;
        case StopReason::Paused: out += "\nPaused at "; break;
        case StopReason::Deadline:
            if (!s.message.empty()) out += fmt::format("{}: at ", s.message);
            break;
        default: break;
    }
    out += location_lines(s.pc);
    out += show_displays();
    return out;
}

bool Console::silent(const Stop& s) const {
    const std::vector<std::string> c = d_.commands_for(s);
    return !c.empty() && to_upper(trim_blanks(c.front())) == "SILENT";
}

std::string Console::report(const Stop& s) {
    if (in_commands_) {  // a breakpoint's command resumed the run: the list running it goes on from s
        resumed_ = s;
        return {};
    }
    std::string out = describe(s);
    if (silent(s)) out.clear();
    return out + run_commands(s);
}

std::string Console::run_commands(Stop s) {
    // As gdb: a command that runs the machine (continue, step, jump, run, a script's press ...) ends
    // its list, and the stop it reaches is reported here and runs its own point's commands, one list
    // after another instead of one inside the other (a log point, hit after hit). Commands that keep
    // resuming get 10000 stops or the machine time of one continue, then the prompt comes back (in a
    // batch session too: a breakpoint whose commands jump back to it would otherwise never end).
    constexpr int kMaxStops = 10000;
    std::string out;
    std::uint64_t ran = 0;  // machine time the commands have run, forwards or back
    for (int stops = 0;; ++stops) {
        const std::vector<std::string> list = d_.commands_for(s);
        if (list.empty() || quit_) return out;
        if (stops == kMaxStops || ran >= d_.continue_limit()) {
            out += fmt::format("Stopped: the commands of {} {} resumed the run {} times ({:.1f} s of simulated time); "
                               "the session goes on here, continue goes on\n",
                               s.reason == StopReason::Watchpoint ? "watchpoint" : "breakpoint", s.number, stops,
                               board::ms_from_tstates(ran) / 1000.0);
            return out;
        }
        resumed_.reset();
        in_commands_ = true;
        struct Leave {  // whatever happens in them, the console is out of the commands after the list
            bool& flag;
            ~Leave() { flag = false; }
        } leave{in_commands_};
        for (std::size_t i = 0; i < list.size() && !quit_; ++i) {
            if (i == 0 && to_upper(trim_blanks(list[i])) == "SILENT") continue;
            const std::uint64_t before = d_.machine().now();
            out += execute(list[i]);
            const std::uint64_t after = d_.machine().now();
            ran += after > before ? after - before : before - after;
            if (after != before || resumed_) break;  // it ran the machine: the list ends with it
        }
        in_commands_ = false;
        if (!resumed_) return out;
        s = *resumed_;
        resumed_.reset();
        const std::string stop = describe(s);
        if (!silent(s)) out += stop;
    }
}

// ---- breakpoints and watchpoints ------------------------------------------------------------------

namespace {
// The column in the command line of column `c` (1-based) of the location or the condition.
int error_column(int col, int ccol, std::string_view cond, const Debugger::Added& r) {
    if (!r.in_condition) return col + std::max(r.col, 1) - 1;
    int lead = 0;
    trim_blanks(cond, &lead);
    return col + ccol + lead + std::max(r.col, 1) - 1;
}
}  // namespace

std::string Console::cmd_break(std::string_view a, int col) { return breakpoint(a, col, false); }
std::string Console::cmd_tbreak(std::string_view a, int col) { return breakpoint(a, col, true); }

// break|tbreak [LOCATION] [if EXPR]: gdb's report, with a note when a source line had no code and
// the point went to the next line that has.
std::string Console::breakpoint(std::string_view a, int col, bool temporary) {
    int ccol = 0;
    auto [loc, cond] = split_if(a, ccol);
    loc = trim_blanks(loc);
    const std::string where = loc.empty() ? hex4h(d_.machine().cpu().regs().pc) : std::string(loc);
    const Debugger::Added r = d_.add_breakpoint(where, temporary, trim_blanks(cond));
    if (!r.number) return error(error_column(col, ccol, cond, r), r.error);
    std::string s;
    if (r.bound)
        s = fmt::format("{}:{} has no code: the breakpoint binds to line {}\n",
                        std::filesystem::path(r.bound->file).filename().string(), loc.substr(loc.rfind(':') + 1),
                        r.bound->line);
    const Breakpoint* b = d_.breakpoint(r.number);
    if (temporary) temporary_.push_back(b->number);
    s += fmt::format("{} {} at {}", temporary ? "Temporary breakpoint" : "Breakpoint", b->number, hex4h(b->address));
    if (b->line)
        s += fmt::format(": file {}, line {}.", std::filesystem::path(b->line->file).filename().string(), b->line->line);
    return s + '\n';
}

std::string Console::cmd_watch(std::string_view a, int col) { return watch(a, col, WatchKind::Write); }
std::string Console::cmd_rwatch(std::string_view a, int col) { return watch(a, col, WatchKind::Read); }
std::string Console::cmd_awatch(std::string_view a, int col) { return watch(a, col, WatchKind::Access); }

// watch [byte|word] EXPR | EXPR..EXPR | port N [in|out] [== V] | axis X|Y|Z steps|count|lost|endstop
//       | PART FIELD (a watch name of the part's description: 8155 porta, 8279 fifo)     [if EXPR]
std::string Console::watch(std::string_view a, int col, WatchKind kind) {
    int ccol = 0;
    auto [what_text, cond] = split_if(a, ccol);
    int wcol = col;
    std::string_view w = trim_blanks(what_text, &wcol);
    if (w.empty()) return error(col, "expected what to watch: memory (YAC, word YAC, 1B30H..1B35H), port N, axis X count, 8155 porta, 8279 fifo");
    std::vector<std::string> words;
    std::vector<int> cols;  // of each word in the line
    for (std::size_t i = 0; i < w.size();) {
        while (i < w.size() && std::isspace(static_cast<unsigned char>(w[i]))) ++i;
        const std::size_t start = i;
        while (i < w.size() && !std::isspace(static_cast<unsigned char>(w[i]))) ++i;
        if (i > start) {
            words.push_back(to_upper(w.substr(start, i - start)));
            cols.push_back(wcol + static_cast<int>(start));
        }
    }
    WatchSpec spec;
    spec.kind = kind;
    auto bad = [&](std::string msg, std::size_t word = 0) {
        return error(word < cols.size() ? cols[word] : wcol + static_cast<int>(w.size()), std::move(msg));
    };
    // A port or value: a number, a symbol, or hex without its leading 0 (F9H: no symbol is named so).
    auto byte_value = [&](const std::string& text) -> std::optional<std::int64_t> {
        if (auto v = parse_int(text)) return v;
        if (auto v = d_.program().value_of(text)) return *v;
        if (text.size() > 1 && text.back() == 'H') return parse_int("0" + text);
        return std::nullopt;
    };
    const bool memory_only = kind != WatchKind::Write;
    if (words[0] == "PORT") {
        if (memory_only) return bad("rwatch and awatch watch memory; 'watch port N [in|out]' watches a port");
        if (words.size() < 2) return bad("expected a port number: watch port F9H [in|out] [== VALUE]", 1);
        const auto p = byte_value(words[1]);
        if (!p || *p < 0 || *p > 255) return bad(fmt::format("bad port '{}' (00H-FFH)", words[1]), 1);
        spec.kind = WatchKind::Port;
        spec.first = spec.last = static_cast<std::uint16_t>(*p);
        std::size_t i = 2;
        if (i < words.size() && (words[i] == "IN" || words[i] == "OUT")) spec.dir = words[i++] == "IN" ? PortDir::In : PortDir::Out;
        if (i < words.size() && (words[i] == "==" || words[i] == "=" || words[i] == "VALUE")) {
            if (i + 1 >= words.size()) return bad("expected a value after ==", i + 1);
            const auto v = byte_value(words[i + 1]);
            if (!v || *v < 0 || *v > 255) return bad(fmt::format("bad value '{}' (00H-FFH)", words[i + 1]), i + 1);
            spec.value = static_cast<std::uint8_t>(*v);
            i += 2;
        }
        if (i != words.size()) return bad(fmt::format("unexpected '{}'", words[i]), i);
        spec.what = fmt::format("port {:02X}H{}{}", spec.first, spec.dir == PortDir::Out ? " out" : spec.dir == PortDir::In ? " in" : "",
                                spec.value ? fmt::format(" == {:02X}H", *spec.value) : "");
    } else if (words[0] == "AXIS") {
        if (memory_only) return bad("rwatch and awatch watch memory; 'watch axis X count' watches the machine tool");
        if (words.size() != 3 || words[1].size() != 1 || words[1][0] < 'X' || words[1][0] > 'Z')
            return bad("expected: watch axis X|Y|Z steps|count|lost|endstop", 1);
        spec.kind = WatchKind::Tool;
        spec.axis = static_cast<periph::MachineTool::Axis>(words[1][0] - 'X');
        static const std::map<std::string, ToolQuantity> q = {
            {"STEPS", ToolQuantity::Steps}, {"COUNT", ToolQuantity::Count}, {"LOST", ToolQuantity::Lost}, {"ENDSTOP", ToolQuantity::EndStop}};
        const auto it = q.find(words[2]);
        if (it == q.end()) return bad(fmt::format("no machine-tool quantity '{}' (steps, count, lost, endstop)", words[2]), 2);
        spec.quantity = it->second;
        spec.what = fmt::format("axis {} {}", words[1], to_upper(words[2]) == "ENDSTOP" ? "end stop" : std::string(trim_blanks(words[2])));
        std::transform(spec.what.begin(), spec.what.end(), spec.what.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        spec.what[5] = words[1][0];
    } else if (const auto [part, part_words] = part_named(words); part && !(memory_only && part_words == words.size())) {
        // PART FIELD: a value the part describes (its watch name: watch 8155 porta, watch 8279 fifo)
        const periph::Description d = d_.describe(*part);
        std::string field;
        for (std::size_t i = part_words; i < words.size(); ++i) field += (field.empty() ? "" : " ") + words[i];
        const periph::Field* f = d.find_watch(field);
        if (memory_only || !f) {
            std::string names;
            for (const std::string& n : d.watch_names()) names += (names.empty() ? "" : "|") + n;
            if (names.empty()) return bad(fmt::format("the {} has nothing to watch", part->name()));
            if (memory_only)
                return bad(fmt::format("rwatch and awatch watch memory; 'watch {} {}' watches a part", part->name(), f ? f->watch : d.watch_names().front()));
            return bad(fmt::format("expected: watch {} {}", part->name(), names), part_words);
        }
        spec.kind = WatchKind::Part;
        spec.part = std::string(part->name());
        spec.field = f->watch;
        spec.what = fmt::format("{} {}", part->name(), f->watch);
    } else {
        // Memory: [byte|word] EXPR, or EXPR..EXPR
        std::string_view m = w;
        int mcol = wcol;
        std::size_t size = 1;
        const std::string first = to_upper(first_word(m));
        if ((first == "BYTE" || first == "WORD") && m.size() > first.size() && std::isspace(static_cast<unsigned char>(m[first.size()]))) {
            size = first == "WORD" ? 2 : 1;
            mcol += static_cast<int>(first.size());
            m = trim_blanks(m.substr(first.size()), &mcol);
        }
        const auto dots = m.find("..");
        auto bound = [&](std::string_view text, int at, std::int64_t& out) {
            text = trim_blanks(text, &at);
            return address(text, at, out);
        };
        std::int64_t lo = 0, hi = 0;
        if (dots != std::string_view::npos) {
            if (std::string e = bound(m.substr(0, dots), mcol, lo); !e.empty()) return e;
            if (std::string e = bound(m.substr(dots + 2), mcol + static_cast<int>(dots) + 2, hi); !e.empty()) return e;
            if (hi < lo) return error(mcol, "a range is FIRST..LAST with FIRST <= LAST");
        } else {
            if (std::string e = bound(m, mcol, lo); !e.empty()) return e;
            hi = std::min<std::int64_t>(lo + static_cast<std::int64_t>(size) - 1, 0xFFFF);
        }
        spec.first = static_cast<std::uint16_t>(lo);
        spec.last = static_cast<std::uint16_t>(hi);
        const auto name = d_.program().data_name_at(spec.first);
        const std::string label = name && dots == std::string_view::npos ? fmt::format("{} ", *name) : "";
        if (spec.first == spec.last) spec.what = fmt::format("byte {}({})", label, hex4h(spec.first));
        else if (spec.last == spec.first + 1) spec.what = fmt::format("word {}({})", label, hex4h(spec.first));
        else spec.what = fmt::format("{}..{}", hex4h(spec.first), hex4h(spec.last));
    }
    const Debugger::Added r = d_.add_watchpoint(spec, trim_blanks(cond));
    if (!r.number) return error(error_column(col, ccol, cond, r), r.error);
    const char* kind_name = spec.kind == WatchKind::Read ? "Read watchpoint" : spec.kind == WatchKind::Access ? "Access watchpoint" : "Watchpoint";
    return fmt::format("{} {}: {}\n", kind_name, r.number, spec.what);
}

std::optional<int> Console::number_arg(std::string_view& args, int& col, std::string& err) {
    const std::string_view w = first_word(args);
    const auto n = parse_int(w);
    if (w.empty() || !n || *n <= 0 || *n > 1'000'000) {
        err = error(col, w.empty() ? "expected a number" : fmt::format("bad number '{}'", w));
        return std::nullopt;
    }
    col += static_cast<int>(w.size());
    args = trim_blanks(args.substr(w.size()), &col);
    return static_cast<int>(*n);
}

// "N N ...": `act` on each number (of a breakpoint, a display...); an unknown one is reported
// ("no WHAT number N"), the rest done.
std::string Console::for_each_number(std::string_view a, int col, std::string_view what,
                                     const std::function<bool(int)>& act) {
    std::string out;
    while (!a.empty()) {
        std::string err;
        const int at = col;
        const auto n = number_arg(a, col, err);
        if (!n) return out + err;
        if (!act(*n)) out += error(at, fmt::format("no {} number {}", what, *n));
    }
    return out;
}

std::string Console::cmd_delete(std::string_view a, int col) {
    if (a.empty() || to_upper(a) == "ALL") {
        d_.remove_all();
        return {};
    }
    if (!std::isdigit(static_cast<unsigned char>(a.front())) || a.find_first_not_of("0123456789 ") != std::string_view::npos) {
        // A location, as the script language's delete ADDRESS.
        const auto loc = d_.locate(a);
        if (!loc.error.empty()) return error(col + std::max(loc.col, 1) - 1, loc.error);
        for (std::uint16_t addr : loc.addresses)
            if (!d_.remove_breakpoints_at(addr)) return error(col, fmt::format("no breakpoint at {}", hex4h(addr)));
        return {};
    }
    return for_each_number(a, col, "breakpoint or watchpoint", [&](int n) { return d_.remove(n); });
}

std::string Console::set_enabled(std::string_view a, int col, bool on) {
    if (a.empty()) {
        for (const auto& b : d_.breakpoints()) d_.enable(b.number, on);
        for (const auto& w : d_.watchpoints()) d_.enable(w.number, on);
        return {};
    }
    return for_each_number(a, col, "breakpoint or watchpoint", [&](int n) { return d_.enable(n, on); });
}

std::string Console::cmd_enable(std::string_view a, int col) { return set_enabled(a, col, true); }

std::string Console::cmd_disable(std::string_view a, int col) { return set_enabled(a, col, false); }

std::string Console::cmd_condition(std::string_view a, int col) {
    std::string err;
    const int at = col;
    const auto n = number_arg(a, col, err);
    if (!n) return err;
    int ecol = 0;
    const std::string e = d_.set_condition(*n, a, ecol);
    if (!e.empty()) return error(ecol ? col + ecol - 1 : at, e);
    return a.empty() ? fmt::format("Breakpoint {} now unconditional.\n", *n) : std::string();
}

std::string Console::cmd_ignore(std::string_view a, int col) {
    std::string err;
    const int at = col;
    const auto n = number_arg(a, col, err);
    if (!n) return err;
    const auto count = parse_int(a);
    if (!count || *count < 0) return error(col, "expected a count: ignore N COUNT");
    if (!d_.set_ignore(*n, static_cast<unsigned>(*count))) return error(at, fmt::format("no breakpoint or watchpoint number {}", *n));
    return fmt::format("Will ignore next {} crossings of breakpoint {}.\n", *count, *n);
}

std::string Console::cmd_commands(std::string_view a, int col) {
    int n = 0;
    if (a.empty()) {
        n = std::max(d_.breakpoints().empty() ? 0 : d_.breakpoints().back().number,
                     d_.watchpoints().empty() ? 0 : d_.watchpoints().back().number);
        if (!n) return error(col, "no breakpoints or watchpoints");
    } else {
        std::string err;
        const auto v = number_arg(a, col, err);
        if (!v) return err;
        n = *v;
    }
    if (!d_.breakpoint(n) && !d_.watchpoint(n)) return error(col, fmt::format("no breakpoint or watchpoint number {}", n));
    if (in_commands_) return error(col, "commands cannot be given inside a breakpoint's commands");
    collecting_ = true;
    collect_for_ = n;
    collected_.clear();
    return {};
}

// ---- running ------------------------------------------------------------------------------------

std::string Console::cmd_continue(std::string_view a, int col) {
    if (!a.empty()) {
        std::string err;
        const auto n = number_arg(a, col, err);
        if (!n) return err;
        // gdb: continue N ignores the breakpoint stopped at N-1 more times.
        for (const auto& b : d_.breakpoints())
            if (b.address == d_.machine().cpu().regs().pc) d_.set_ignore(b.number, static_cast<unsigned>(*n - 1));
    }
    return report(d_.cont());
}

std::string Console::repeat(std::string_view a, int col, Stop (Debugger::*op)()) {
    int n = 1;
    if (!a.empty()) {
        std::string err;
        const auto v = number_arg(a, col, err);
        if (!v) return err;
        n = *v;
    }
    Stop s;
    for (int i = 0; i < n; ++i) {
        s = (d_.*op)();
        if (s.reason != StopReason::Step && s.reason != StopReason::Finished) break;
    }
    return report(s);
}

std::string Console::cmd_step(std::string_view a, int col) { return repeat(a, col, &Debugger::step); }
std::string Console::cmd_stepi(std::string_view a, int col) { return repeat(a, col, &Debugger::stepi); }
std::string Console::cmd_next(std::string_view a, int col) { return repeat(a, col, &Debugger::next); }
std::string Console::cmd_nexti(std::string_view a, int col) { return repeat(a, col, &Debugger::next); }
std::string Console::cmd_finish(std::string_view a, int col) {
    if (!a.empty()) return error(col, "finish takes no argument");
    const auto frames = d_.backtrace();
    std::string out;
    if (frames.size() > 1)
        out = fmt::format("Run till exit from {} ({})\n", frames[0].routine ? *frames[0].routine : "??", hex4h(frames[0].pc));
    return out + report(d_.finish());
}

std::string Console::cmd_until(std::string_view a, int col) {
    if (a.empty()) return report(d_.until());
    const auto loc = d_.locate(a);
    if (!loc.error.empty()) return error(col + std::max(loc.col, 1) - 1, loc.error);
    return report(d_.until(loc.addresses.front()));
}

std::string Console::cmd_advance(std::string_view a, int col) {
    if (a.empty()) return error(col, "expected a location: advance LOCATION");
    const auto loc = d_.locate(a);
    if (!loc.error.empty()) return error(col + std::max(loc.col, 1) - 1, loc.error);
    return report(d_.advance(loc.addresses.front()));
}

// TIME: a number and a unit (t, us, ms, s), in T-states.
std::optional<std::uint64_t> Console::tstates_of(std::string_view a) {
    std::size_t i = 0;
    while (i < a.size() && (std::isdigit(static_cast<unsigned char>(a[i])) || a[i] == '.')) ++i;
    const std::string unit = to_upper(a.substr(i));
    const double v = i ? std::strtod(std::string(a.substr(0, i)).c_str(), nullptr) : -1;
    constexpr double hz = board::kCpuHz;
    const double scale = unit == "T" ? 1 : unit == "US" ? hz / 1e6 : unit == "MS" ? hz / 1e3 : unit == "S" ? hz : -1;
    if (v < 0 || scale < 0 || v * scale > 1e18) return std::nullopt;
    return static_cast<std::uint64_t>(v * scale + 0.5);
}

std::string Console::cmd_run(std::string_view a, int col) {
    if (to_upper(first_word(a)) == "FOR") {
        col += 3;
        a = trim_blanks(a.substr(3), &col);
    }
    if (a.empty()) return error(col, "expected a time: run [for] TIME (10ms, 2s, 3070t)");
    const auto t = tstates_of(a);
    if (!t) return error(col, fmt::format("bad time '{}' (a number with a unit: t, us, ms or s)", a));
    const Stop s = d_.run_for(*t);
    if (s.reason == StopReason::Deadline) return {};
    return report(s);
}

std::string Console::cmd_rs(std::string_view, int) { return report(d_.reverse_step()); }
std::string Console::cmd_rsi(std::string_view, int) { return report(d_.reverse_stepi()); }
std::string Console::cmd_rn(std::string_view, int) { return report(d_.reverse_next()); }
std::string Console::cmd_rfin(std::string_view, int) { return report(d_.reverse_finish()); }
std::string Console::cmd_rc(std::string_view, int) { return report(d_.reverse_continue()); }

// A console command's help, and that of the added command of the same name whose forms it hands
// over (help print: the debugger's print, then the script's print display ...), as one text.
std::string Console::whole_help(const CommandDef& c) const {
    std::string out(c.help);
    if (!c.handler) return out;
    const std::string w = to_upper(c.name);
    for (const CommandDef& d : table_)
        if (!d.handler && to_upper(d.name) == w) out += fmt::format("; as in scripts: {}", d.help);
    return out;
}

std::string Console::cmd_help(std::string_view a, int col) {
    if (!a.empty()) {
        std::string err;
        const CommandDef* c = find_command(a, err);
        if (c) return whole_help(*c) + '\n';
        // A command of the script's alone (each of its entries: expect has several).
        std::string out;
        const std::string w = to_upper(a);
        for (const CommandDef& d : table_)
            if (!d.handler && to_upper(d.name) == w) out += std::string(d.help) + '\n';
        if (out.empty()) return error(col, err.empty() ? fmt::format("no command '{}'", a) : err);
        return out;
    }
    // Each command whole: its names, then its help wrapped at 100 columns under the names.
    constexpr std::size_t kWidth = 100, kIndent = 6;
    auto entry = [&](const CommandDef& c) {
        std::string names(c.name);
        for (std::string_view al : c.aliases) names += fmt::format(", {}", al);
        std::string out = fmt::format("  {}\n", names);
        std::string line(kIndent, ' ');
        const std::string text = whole_help(c);
        std::string_view rest = text;
        while (!rest.empty()) {
            const std::size_t sp = rest.find(' ');
            const std::string_view word = rest.substr(0, sp);
            if (line.size() > kIndent && line.size() + 1 + word.size() > kWidth) {
                out += line + '\n';
                line.assign(kIndent, ' ');
            }
            if (line.size() > kIndent) line += ' ';
            line += word;
            rest = sp == std::string_view::npos ? std::string_view{} : rest.substr(sp + 1);
        }
        return out + line + '\n';
    };
    std::string out = "Debugger commands (gdb's names; docs/debugging.md); help COMMAND for one:\n";
    for (const CommandDef& c : table_)
        if (c.handler) out += entry(c);
    if (std::any_of(table_.begin(), table_.end(), [](const CommandDef& c) { return !c.handler; })) {
        out += "Script commands (docs/scripting.md), at this prompt too:\n";
        for (const CommandDef& c : table_)
            if (!c.handler) out += entry(c);
    }
    return out;
}

std::string Console::cmd_quit(std::string_view, int) {
    quit_ = true;
    return {};
}

std::string Console::banner() const {
    return fmt::format("alp85 debug: the ALP 85's 8085 under a gdb-like debugger; {} symbols loaded.\n"
                       "Type \"help\" for the commands (gdb's names), \"help COMMAND\" for one; docs/debugging.md.\n",
                       d_.program().size());
}

namespace {
// The files and folders whose names complete `word` (a folder ends in '/'); a leading quote kept.
std::vector<std::string> file_names(std::string_view word) {
    std::vector<std::string> out;
    std::string w(word);
    std::string quote;
    if (!w.empty() && w.front() == '"') {
        quote = "\"";
        w.erase(0, 1);
    }
    const auto slash = w.rfind('/');
    const std::string dir = slash == std::string::npos ? "" : w.substr(0, slash + 1);
    const std::string stem = slash == std::string::npos ? w : w.substr(slash + 1);
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir.empty() ? "." : dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (!name.starts_with(stem) || (stem.empty() && name.starts_with('.'))) continue;
        std::error_code e2;
        out.push_back(quote + dir + name + (it->is_directory(e2) ? "/" : ""));
    }
    return out;
}
}  // namespace

std::vector<std::string> Console::complete(std::string_view word, bool first_word, std::string_view command) const {
    std::vector<std::string> out;
    const std::string up = to_upper(word);
    const std::string cmd = to_upper(command);
    const bool file_command = std::any_of(table_.begin(), table_.end(),
                                          [&](const CommandDef& c) { return c.takes_file && to_upper(c.name) == cmd; });
    if (!first_word && (file_command || word.find('/') != std::string_view::npos || word.starts_with('.') || word.starts_with('"'))) {
        out = file_names(word);
    } else if (first_word) {
        for (const CommandDef& c : table_)
            if (to_upper(c.name).starts_with(up)) out.emplace_back(c.name);
    } else {
        for (const auto& [name, value] : d_.program().names())
            if (name.starts_with(up)) out.push_back(name);
        for (std::string_view s : {"registers", "breakpoints", "displays", "display", "axis", "port", "word", "byte", "count",
                                   "steps", "lost", "endstop"})
            if (to_upper(s).starts_with(up)) out.emplace_back(s);
        // the parts and what their descriptions let one watch
        for (const periph::Part* p : d_.machine().parts()) {
            if (to_upper(p->name()).starts_with(up)) out.emplace_back(p->name());
            for (const std::string& w : d_.describe(*p).watch_names())
                if (to_upper(w).starts_with(up)) out.push_back(w);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace alp85::debug
