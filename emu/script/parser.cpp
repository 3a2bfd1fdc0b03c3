#include "emu/script/parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "emu/board/board_map.h"
#include "emu/util/input_file.h"
#include "emu/util/text.h"

namespace alp85::script {
namespace {

struct Token {
    std::string text;
    int col = 0;        // 1-based
    bool quoted = false;
};


class LineParser {
public:
    LineParser(std::string_view line, const std::string& file, int line_no, std::vector<ParseError>& errors)
        : line_(line), file_(file), line_no_(line_no), errors_(errors) {}

    std::optional<Command> parse() {
        if (!tokenize()) return std::nullopt;
        if (tokens_.empty()) return std::nullopt;
        Command c;
        c.where = {file_, line_no_, tokens_[0].col};
        c.line = std::string(line_);
        const std::string verb = to_upper(tokens_[0].text);
        pos_ = 1;
        const auto& table = verbs();
        const auto it = std::find_if(table.begin(), table.end(), [&](const Verb& v) { return to_upper(v.info.name) == verb; });
        if (it == table.end()) return fail(tokens_[0], fmt::format("unknown command '{}'", tokens_[0].text));
        if (!(this->*(it->parse))(c)) return std::nullopt;
        if (pos_ < tokens_.size()) return fail(tokens_[pos_], fmt::format("unexpected '{}'", tokens_[pos_].text));
        return c;
    }

    // The language's commands: one row each, what the line parser runs and what help, completion
    // and the docs list (script::commands()).
    struct Verb {
        CommandInfo info;
        bool (LineParser::*parse)(Command&);
    };
    static const std::vector<Verb>& verbs() {
        using F = std::vector<std::string_view>;
        static const std::vector<Verb> table = {
            {{"board", "board NAME: the board the script runs on (alp85, sdk85); the script's first command"}, &LineParser::board},
            {{"load", "load FILE [at ADDR]: an .asm (assembled, its symbols and lines kept), .hex or .bin (at ADDR) image", {}, true}, &LineParser::load},
            {{"monitor", "monitor: the ALP 85 monitor ROM at 0000H and its symbols"}, &LineParser::monitor},
            {{"firmware", "firmware NAME: built-in firmware with its symbols and lines (thesis, thesis-fixed, master, monitor)"}, &LineParser::firmware},
            {{"reset", "reset: RESET IN now (CPU, 8155, 8279); expect time counts from here"}, &LineParser::reset},
            {{"press", "press KEY [hold TIME] [gap TIME]: a key pressed, held (30ms), released, then the gap (30ms) run"}, &LineParser::press},
            {{"type", "type KEY...: each key pressed in turn (type R 7 0800 EXEC)"}, &LineParser::type},
            {{"keydown", "keydown KEY: a key down now, without running"}, &LineParser::keydown},
            {{"keyup", "keyup KEY: a key up now, without running"}, &LineParser::keyup},
            {{"run", "run TIME | run until ADDR [timeout TIME] | run until axis X|Y|Z steps [OP] N [timeout TIME]: run for TIME, or until the PC reaches ADDR (passing breakpoints) or the axis its position", F{"UNTIL"}, false}, &LineParser::run},
            {{"wait", "wait display \"TEXT\" [timeout TIME]: run until the display reads TEXT (5s)"}, &LineParser::wait},
            {{"step", "step [N]: N instructions"}, &LineParser::step},
            {{"break", "break ADDR: a breakpoint (the debugger's break is taken at its prompt)"}, &LineParser::brk},
            {{"delete", "delete ADDR|all: breakpoints (the debugger's delete is taken at its prompt)"}, &LineParser::del},
            {{"expect", "expect display|mem|word|reg|flag|port|symbol|time|halted|running|axis|count|lost ...: fails unless the machine shows it (docs/scripting.md)",
              F{"DISPLAY", "MEM", "WORD", "REG", "FLAG", "PORT", "SYMBOL", "TIME", "HALTED", "RUNNING", "AXIS", "COUNT", "LOST"}, false}, &LineParser::expect},
            {{"set", "set mem ADDR VALUE... | set reg REG VALUE: memory or a register", F{"MEM", "REG"}, false}, &LineParser::set},
            {{"save", "save FILE: a snapshot of the whole machine", {}, true}, &LineParser::save},
            {{"restore", "restore FILE: the machine as a snapshot holds it", {}, true}, &LineParser::restore},
            {{"print", "print display [text] | print axes | print time | print board | print \"TEXT\"...: the display, the tool's axes, the time, the board's maps and wiring, a message",
              F{"\"", "DISPLAY", "AXES", "TIME", "BOARD"}, false}, &LineParser::print},
            {{"motor", "motor ideal|physical: the stepper motors' model from now on"}, &LineParser::motor},
            {{"feedback", "feedback scale|commanded: what the transducers read from now on"}, &LineParser::feedback},
            {{"new", "new workpiece: every table wound back to its power-on position"}, &LineParser::new_workpiece},
            {{"mark", "mark: the time print time also counts from"}, &LineParser::mark},
            {{"option", "option NAME on|off: a board option (the ALP 85's expansion: the 4 KB expansion EPROM at 3000H; the SDK-85's ram2: its second 8155)"}, &LineParser::option},
            {{"record", "record FILE.csv [every TIME] | record signals FILE.vcd [PIN...] [every TIME] | record stop: the tool or the pins", {}, true}, &LineParser::record},
            {{"plot", "plot toolpath|time FILE.svg|FILE.png [from X,Y to X,Y]: what record FILE.csv recorded", {}, true}, &LineParser::plot},
        };
        return table;
    }

private:
    // ---- tokens --------------------------------------------------------------------------------
    bool tokenize() {
        std::size_t i = 0;
        while (i < line_.size()) {
            const char ch = line_[i];
            if (std::isspace(static_cast<unsigned char>(ch))) {
                ++i;
                continue;
            }
            if (ch == '#' || ch == ';') break;
            Token t;
            t.col = static_cast<int>(i) + 1;
            if (ch == '"') {
                t.quoted = true;
                ++i;
                bool closed = false;
                while (i < line_.size()) {
                    if (line_[i] == '\\' && i + 1 < line_.size()) {
                        t.text += line_[i + 1];
                        i += 2;
                    } else if (line_[i] == '"') {
                        closed = true;
                        ++i;
                        break;
                    } else {
                        t.text += line_[i++];
                    }
                }
                if (!closed) {
                    error(t.col, "string has no closing quote");
                    return false;
                }
            } else {
                // A word; blanks inside parentheses or brackets belong to it: (X1 + 1) is one value.
                int depth = 0;
                while (i < line_.size() && line_[i] != '"' &&
                       (depth > 0 || !std::isspace(static_cast<unsigned char>(line_[i])))) {
                    if (line_[i] == '(' || line_[i] == '[') ++depth;
                    else if ((line_[i] == ')' || line_[i] == ']') && depth > 0) --depth;
                    t.text += line_[i++];
                }
            }
            tokens_.push_back(std::move(t));
        }
        return true;
    }

    bool more() const { return pos_ < tokens_.size(); }
    const Token& peek() const { return tokens_[pos_]; }
    int end_col() const { return static_cast<int>(line_.size()) + 1; }
    bool at_word(std::string_view w) const { return more() && !peek().quoted && to_upper(peek().text) == w; }

    void error(int col, std::string message) {
        errors_.push_back({{file_, line_no_, col}, std::move(message), std::string(line_)});
    }
    std::nullopt_t fail(const Token& t, std::string message) {
        error(t.col, std::move(message));
        return std::nullopt;
    }
    bool missing(std::string what) {
        error(more() ? peek().col : end_col(), "expected " + what);
        return false;
    }

    // ---- operands ------------------------------------------------------------------------------
    bool word(std::string_view w) {
        if (!at_word(w)) return missing(fmt::format("'{}'", to_upper(w)));
        ++pos_;
        return true;
    }

    bool string_operand(std::string& out, const char* what) {
        if (!more()) return missing(what);
        out = peek().text;
        ++pos_;
        return true;
    }

    bool quoted(std::string& out, const char* what) {
        if (!more() || !peek().quoted) return missing(what);
        out = peek().text;
        ++pos_;
        return true;
    }

    // address: where an address is expected, a bare number with a leading zero is refused
    // (ambiguous_address).
    bool value(Value& v, const char* what, bool address = false) {
        if (!more() || peek().quoted) return missing(what);
        const Token& t = peek();
        std::string why;
        int at = 1;
        const auto r = parse_value(t.text, what, address, why, at);
        if (!r) {
            error(t.col + at - 1, why);
            return false;
        }
        v = *r;
        v.col = t.col;
        ++pos_;
        return true;
    }

    // The unquoted operand that follows, read by `parse` into `out`; text it refuses is reported
    // by `refused`, a format naming that text ("unknown key '{}'").
    template <class T, class Parse>
    bool parsed(T& out, const char* what, const Parse& parse, std::string_view refused) {
        if (!more() || peek().quoted) return missing(what);
        const auto r = parse(peek().text);
        if (!r) {
            error(peek().col, fmt::format(fmt::runtime(refused), peek().text));
            return false;
        }
        out = *r;
        ++pos_;
        return true;
    }

    bool time(std::uint64_t& out, const char* what) {
        return parsed(out, what, parse_time, "bad time '{}' (a number with a unit: t, us, ms or s)");
    }

    bool key(KeyRef& k) { return parsed(k, "a key name", parse_key, "unknown key '{}'"); }

    bool reg(const cpu::Register*& r) {
        // parse_reg's null for no register, as an empty optional
        const auto known = [](std::string_view text) -> std::optional<const cpu::Register*> {
            const cpu::Register* v = parse_reg(text);
            return v ? std::optional(v) : std::nullopt;
        };
        return parsed(r, "a register", known, "unknown register '{}'");
    }

    // An address or symbol into c.address.
    bool address(Command& c, const char* what) {
        Value v;
        if (!value(v, what, true)) return false;
        c.address = v;
        return true;
    }

    // The word `w` next makes the command `op`, with nothing after it (record stop, delete all).
    bool word_alone(Command& c, std::string_view w, Op op) {
        if (!at_word(w)) return false;
        ++pos_;
        c.op = op;
        return true;
    }

    bool optional_time(std::string_view w, std::uint64_t& out) {
        if (!at_word(w)) return true;
        ++pos_;
        return time(out, "a time");
    }

    // ---- verbs ---------------------------------------------------------------------------------
    bool load(Command& c) {
        c.op = Op::Load;
        if (!string_operand(c.text, "a file name")) return false;
        if (!at_word("AT")) return true;
        ++pos_;
        return address(c, "an address");
    }
    bool monitor(Command& c) {
        c.op = Op::Monitor;
        return true;
    }
    bool firmware(Command& c) {
        c.op = Op::Firmware;
        return string_operand(c.text, "a firmware name (thesis, thesis-fixed, master, monitor)");
    }
    bool reset(Command& c) {
        c.op = Op::Reset;
        return true;
    }
    // The command `op` on the one key that follows.
    bool one_key(Command& c, Op op) {
        c.op = op;
        KeyRef k;
        if (!key(k)) return false;
        c.keys.push_back(k);
        return true;
    }
    bool press(Command& c) {
        if (!one_key(c, Op::Press)) return false;
        c.time = kDefaultHold;
        c.gap = kDefaultGap;
        while (at_word("HOLD") || at_word("GAP")) {
            if (at_word("HOLD")) {
                if (!optional_time("HOLD", c.time)) return false;
            } else if (!optional_time("GAP", c.gap)) {
                return false;
            }
        }
        return true;
    }
    bool type(Command& c) {
        c.op = Op::Type;
        c.time = kDefaultHold;
        c.gap = kDefaultGap;
        if (!more()) return missing("one or more key names");
        while (more()) {
            KeyRef k;
            if (!key(k)) return false;
            c.keys.push_back(k);
        }
        return true;
    }
    bool keydown(Command& c) { return one_key(c, Op::KeyDown); }
    bool keyup(Command& c) { return one_key(c, Op::KeyUp); }
    // ---- the machine tool ---------------------------------------------------------------------
    bool tool_axis(Command& c) {
        if (!more() || peek().quoted) return missing("an axis (X, Y or Z)");
        const std::string a = to_upper(peek().text);
        if (a != "X" && a != "Y" && a != "Z") return fail(peek(), fmt::format("unknown axis '{}' (X, Y or Z)", peek().text)), false;
        c.axis = static_cast<std::uint8_t>(a[0] == 'X' ? 0 : a[0] == 'Y' ? 1 : 2);
        ++pos_;
        return true;
    }
    void optional_compare(Command& c) {
        static const std::map<std::string, Compare> ops = {
            {"<", Compare::Lt}, {"<=", Compare::Le}, {"=", Compare::Eq}, {"==", Compare::Eq},
            {">=", Compare::Ge}, {">", Compare::Gt}};
        c.compare = Compare::Eq;
        if (!more() || peek().quoted) return;
        if (const auto o = ops.find(peek().text); o != ops.end()) {
            c.compare = o->second;
            ++pos_;
        }
    }
    bool integer(std::int64_t& out, const char* what) {
        if (!more() || peek().quoted) return missing(what);
        std::string_view t = peek().text;
        const bool neg = !t.empty() && (t[0] == '-' || t[0] == '+') ? (t[0] == '-') : false;
        if (!t.empty() && (t[0] == '-' || t[0] == '+')) t.remove_prefix(1);
        const auto n = parse_number(t);
        if (!n) return fail(peek(), fmt::format("expected {}, found '{}'", what, peek().text)), false;
        out = neg ? -*n : *n;
        ++pos_;
        return true;
    }
    bool real_number(double& out, const char* what) {
        if (!more() || peek().quoted) return missing(what);
        const std::string& t = peek().text;
        char* end = nullptr;
        out = std::strtod(t.c_str(), &end);
        if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(out))
            return fail(peek(), fmt::format("expected {} (a decimal number), found '{}'", what, t)), false;
        ++pos_;
        return true;
    }
    // expect axis X steps [cmp] N | expect axis X mm [cmp] V [within D]
    bool axis_position(Command& c) {
        if (!tool_axis(c)) return false;
        if (at_word("MM")) {
            ++pos_;
            c.in_mm = true;
            optional_compare(c);
            if (!real_number(c.real, "a position in mm")) return false;
            c.within = 0.0005;  // half a micrometre: "=" on a position computed in doubles
            if (at_word("WITHIN")) {
                ++pos_;
                if (!real_number(c.within, "a tolerance in mm")) return false;
                if (c.within < 0) return error(c.where.col, "a tolerance is not negative"), false;
            }
            return true;
        }
        if (!word("STEPS")) return false;
        optional_compare(c);
        return integer(c.integer, "a number of steps");
    }
    // One of two words (given in upper case): c.real = 0 for the first, 1 for the second.
    bool one_of(Command& c, std::string_view first, std::string_view second, const char* what) {
        for (int i = 0; i < 2; ++i) {
            if (at_word(i == 0 ? first : second)) {
                c.real = i;
                ++pos_;
                return true;
            }
        }
        std::string both = fmt::format("{} or {}", first, second);
        std::transform(both.begin(), both.end(), both.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
        if (more()) return fail(peek(), fmt::format("unknown {} '{}' ({})", what, peek().text, both)), false;
        return missing(fmt::format("a {} ({})", what, both));
    }
    bool motor(Command& c) {
        c.op = Op::Motor;
        return one_of(c, "IDEAL", "PHYSICAL", "motor model");
    }
    // option NAME on|off: an option of one of the boards (c.name, c.real 1 = on); the Session
    // refuses one its board lacks.
    bool option(Command& c) {
        c.op = Op::Option;
        if (!more()) return missing("a board option (expansion, ram2)");
        const Token& t = peek();
        for (const board::Board* b : board::kBoards)
            for (const board::BoardOption& o : b->options)
                if (!t.quoted && to_upper(o.name) == to_upper(t.text)) c.name = std::string(o.name);
        if (c.name.empty()) return fail(t, fmt::format("unknown board option '{}' (expansion, ram2)", t.text)), false;
        ++pos_;
        return one_of(c, "OFF", "ON", "state");
    }
    // board NAME: the board the script is run on (the runner builds it; docs/scripting.md).
    bool board(Command& c) {
        c.op = Op::Board;
        if (!more()) return missing(fmt::format("a board ({})", board::board_names()));
        const Token& t = peek();
        for (const board::Board* b : board::kBoards)
            if (!t.quoted && to_upper(b->name) == to_upper(t.text)) c.name = std::string(b->name);
        if (c.name.empty()) return fail(t, fmt::format("unknown board '{}' ({})", t.text, board::board_names())), false;
        ++pos_;
        return true;
    }
    bool mark(Command& c) {
        c.op = Op::Mark;
        return true;
    }
    // new workpiece: the operator's set-up (MachineTool::set_up_workpiece).
    bool new_workpiece(Command& c) {
        c.op = Op::NewWorkpiece;
        if (at_word("WORKPIECE")) return ++pos_, true;
        if (more()) return fail(peek(), fmt::format("unknown '{}' after new (new workpiece)", peek().text)), false;
        return missing("'workpiece' (new workpiece)");
    }
    bool feedback(Command& c) {
        c.op = Op::Feedback;
        return one_of(c, "SCALE", "COMMANDED", "feedback");
    }
    bool record(Command& c) {
        if (word_alone(c, "STOP", Op::RecordStop)) return true;
        c.op = Op::Record;
        // record signals FILE.vcd [PIN...] [every T]; a CSV file named "signals" is `record "signals"`.
        if (at_word("SIGNALS")) {
            ++pos_;
            c.signals = true;
            if (!string_operand(c.text, "a VCD file name")) return false;
            c.period = kDefaultSignalPeriod;
            while (more() && !at_word("EVERY")) {
                if (peek().quoted) return fail(peek(), fmt::format("a pin name is a word, not a string: {}", peek().text)), false;
                Value v;
                v.text = peek().text;
                v.col = peek().col;
                c.pins.push_back(std::move(v));
                ++pos_;
            }
        } else {
            if (!string_operand(c.text, "a CSV file name, 'signals FILE.vcd' or 'stop'")) return false;
            c.period = kDefaultRecordPeriod;
        }
        if (at_word("EVERY")) {
            ++pos_;
            if (!time(c.period, "a sampling period")) return false;
            if (c.period == 0) return error(c.where.col, "a sampling period is not zero"), false;
        }
        return true;
    }
    bool point(double& x, double& y) {
        if (!more() || peek().quoted) return missing("a point X,Y in mm");
        const std::string& t = peek().text;
        const auto comma = t.find(',');
        char* end = nullptr;
        if (comma != std::string::npos) {
            const std::string xs = t.substr(0, comma), ys = t.substr(comma + 1);
            x = std::strtod(xs.c_str(), &end);
            const bool okx = !xs.empty() && end == xs.c_str() + xs.size();
            y = std::strtod(ys.c_str(), &end);
            const bool oky = !ys.empty() && end == ys.c_str() + ys.size();
            if (okx && oky && std::isfinite(x) && std::isfinite(y)) {
                ++pos_;
                return true;
            }
        }
        return fail(peek(), fmt::format("expected a point X,Y in mm, found '{}'", t)), false;
    }
    bool plot(Command& c) {
        c.op = Op::Plot;
        if (!more()) return missing("what to plot (toolpath or time)");
        if (at_word("TOOLPATH")) c.name = "TOOLPATH";
        else if (at_word("TIME")) c.name = "TIME";
        else return fail(peek(), fmt::format("unknown plot '{}' (toolpath or time)", peek().text)), false;
        ++pos_;
        if (!string_operand(c.text, "an output file (.svg or .png)")) return false;
        std::string ext = c.text.size() >= 4 ? to_upper(c.text.substr(c.text.size() - 4)) : "";
        if (ext != ".SVG" && ext != ".PNG") return error(c.where.col, "a plot is written as .svg or .png"), false;
        if (c.name == "TOOLPATH" && at_word("FROM")) {
            ++pos_;
            std::array<double, 4> l{};
            if (!point(l[0], l[1]) || !word("TO") || !point(l[2], l[3])) return false;
            c.ideal_line = l;
        }
        return true;
    }

    bool run(Command& c) {
        if (at_word("UNTIL")) {
            ++pos_;
            if (at_word("AXIS")) {
                ++pos_;
                c.op = Op::RunUntilAxis;
                if (!tool_axis(c) || !word("STEPS")) return false;
                optional_compare(c);
                if (!integer(c.integer, "a number of steps")) return false;
                c.time = kDefaultUntil;
                return optional_time("TIMEOUT", c.time);
            }
            c.op = Op::RunUntil;
            if (!address(c, "an address or symbol")) return false;
            c.time = kDefaultUntil;
            return optional_time("TIMEOUT", c.time);
        }
        c.op = Op::Run;
        return time(c.time, "a time (e.g. 100ms) or 'until'");
    }
    bool wait(Command& c) {
        c.op = Op::WaitDisplay;
        if (!word("DISPLAY")) return false;
        if (!quoted(c.text, "the display text in quotes")) return false;
        c.time = kDefaultWait;
        return optional_time("TIMEOUT", c.time);
    }
    bool step(Command& c) {
        c.op = Op::Step;
        if (more()) {
            const auto n = parse_number(peek().text);
            if (!n || *n < 1 || *n > 100'000'000) {
                error(peek().col, fmt::format("bad step count '{}'", peek().text));
                return false;
            }
            c.count = static_cast<unsigned>(*n);
            ++pos_;
        }
        return true;
    }
    bool brk(Command& c) {
        c.op = Op::Break;
        return address(c, "an address or symbol");
    }
    bool del(Command& c) {
        if (word_alone(c, "ALL", Op::DeleteAll)) return true;
        c.op = Op::Delete;
        return address(c, "an address, a symbol or 'all'");
    }
    bool values(Command& c, const char* what) {
        if (!more()) return missing(what);
        while (more()) {
            Value v;
            if (!value(v, what)) return false;
            c.values.push_back(v);
        }
        return true;
    }
    bool expect(Command& c) {
        if (!more()) return missing("what to expect (display, mem, word, reg, flag, port, symbol, time, halted, running, axis, count, lost)");
        const Token& what = peek();
        const std::string w = to_upper(what.text);
        ++pos_;
        if (w == "DISPLAY") {
            c.op = Op::ExpectDisplay;
            return quoted(c.text, "the display text in quotes");
        }
        if (w == "MEM" || w == "WORD") {
            c.op = w == "MEM" ? Op::ExpectMem : Op::ExpectWord;
            Value a;
            if (!value(a, "an address", true)) return false;
            c.address = a;
            if (c.op == Op::ExpectWord) {
                Value v;
                if (!value(v, "a value")) return false;
                c.values.push_back(v);
                return true;
            }
            return values(c, "one or more byte values");
        }
        if (w == "REG") {
            c.op = Op::ExpectReg;
            Value v;
            return reg(c.reg) && value(v, "a value") && (c.values.push_back(v), true);
        }
        if (w == "FLAG") {
            c.op = Op::ExpectFlag;
            if (!more()) return missing("a flag (S Z AC P CY V K)");
            const cpu::Flag* f = cpu::description().find_flag(peek().text);
            if (!f) return fail(peek(), fmt::format("unknown flag '{}'", peek().text)), false;
            c.flag = f->bit;
            c.flag_name = to_upper(peek().text);
            ++pos_;
            Value v;
            if (!value(v, "0 or 1")) return false;
            if (v.expression || (v.number != 0 && v.number != 1))
                return error(v.col, "a flag is 0 or 1"), false;
            c.values.push_back(v);
            return true;
        }
        if (w == "PORT") {
            c.op = Op::ExpectPort;
            if (!more()) return missing("a port (A, B or C)");
            const std::string p = to_upper(peek().text);
            if (p != "A" && p != "B" && p != "C") return fail(peek(), fmt::format("unknown port '{}'", peek().text)), false;
            c.port = p[0];
            ++pos_;
            Value v;
            return value(v, "a value") && (c.values.push_back(v), true);
        }
        if (w == "SYMBOL") {
            c.op = Op::ExpectSymbol;
            if (!more() || peek().quoted) return missing("a symbol name");
            c.name = to_upper(peek().text);
            ++pos_;
            Value v;
            return value(v, "a value") && (c.values.push_back(v), true);
        }
        if (w == "AXIS") {
            c.op = Op::ExpectAxis;
            return axis_position(c);
        }
        if (w == "COUNT" || w == "LOST") {
            c.op = w == "COUNT" ? Op::ExpectCount : Op::ExpectLost;
            if (!tool_axis(c)) return false;
            optional_compare(c);
            return integer(c.integer, w == "COUNT" ? "a transducer count" : "a number of lost steps");
        }
        if (w == "TIME") {
            c.op = Op::ExpectTime;
            if (!more()) return missing("a comparison (< <= = >= >)");
            static const std::map<std::string, Compare> ops = {
                {"<", Compare::Lt}, {"<=", Compare::Le}, {"=", Compare::Eq}, {"==", Compare::Eq},
                {">=", Compare::Ge}, {">", Compare::Gt}};
            const auto o = ops.find(peek().text);
            if (o == ops.end()) return fail(peek(), fmt::format("unknown comparison '{}'", peek().text)), false;
            c.compare = o->second;
            ++pos_;
            return time(c.time, "a time");
        }
        if (w == "HALTED") {
            c.op = Op::ExpectHalted;
            return true;
        }
        if (w == "RUNNING") {
            c.op = Op::ExpectRunning;
            return true;
        }
        return fail(what, fmt::format("cannot expect '{}' (display, mem, word, reg, flag, port, symbol, time, halted, running)", what.text)), false;
    }
    bool set(Command& c) {
        if (at_word("MEM")) {
            ++pos_;
            c.op = Op::SetMem;
            Value a;
            if (!value(a, "an address", true)) return false;
            c.address = a;
            return values(c, "one or more byte values");
        }
        if (at_word("REG")) {
            ++pos_;
            c.op = Op::SetReg;
            Value v;
            return reg(c.reg) && value(v, "a value") && (c.values.push_back(v), true);
        }
        return missing("'mem' or 'reg'");
    }
    bool save(Command& c) {
        c.op = Op::Save;
        return string_operand(c.text, "a snapshot file name");
    }
    bool restore(Command& c) {
        c.op = Op::Restore;
        return string_operand(c.text, "a snapshot file name");
    }
    bool print(Command& c) {
        // print board: the board's description (memory map, devices, wiring, keys, display)
        for (const auto& [word, op] : {std::pair{"AXES", Op::PrintAxes}, {"TIME", Op::PrintTime}, {"BOARD", Op::PrintBoard}})
            if (at_word(word)) {
                ++pos_;
                c.op = op;
                return true;
            }
        if (at_word("DISPLAY")) {
            ++pos_;
            c.op = Op::PrintDisplay;
            if (at_word("TEXT")) {  // the display as quoted text instead of seven-segment art
                ++pos_;
                c.text = "text";
            }
            return true;
        }
        c.op = Op::Print;
        while (more()) {
            if (!c.text.empty()) c.text += ' ';
            c.text += peek().text;
            ++pos_;
        }
        return true;
    }

    std::string_view line_;
    const std::string& file_;
    int line_no_;
    std::vector<ParseError>& errors_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

}  // namespace

const std::vector<CommandInfo>& commands() {
    static const std::vector<CommandInfo> list = [] {
        std::vector<CommandInfo> out;
        for (const auto& v : LineParser::verbs()) out.push_back(v.info);
        return out;
    }();
    return list;
}

std::string ParseError::format() const {
    if (where.line == 0) return fmt::format("{}: error: {}\n", where.file, message);  // the whole file
    std::string caret(static_cast<std::size_t>(std::max(where.col, 1) - 1), ' ');
    for (std::size_t i = 0; i < caret.size() && i < line.size(); ++i)
        if (line[i] == '\t') caret[i] = '\t';
    return fmt::format("{}:{}:{}: error: {}\n {}\n {}^\n", where.file, where.line, where.col, message, line, caret);
}

std::string included_from(const Command& c) {
    std::string s;
    for (const Location& l : c.included_from) s += fmt::format(" (included from {}:{})", l.file, l.line);
    return s;
}

std::string place_of(const Command& c) { return fmt::format("{}:{}{}", c.where.file, c.where.line, included_from(c)); }

std::optional<Command> parse_line(std::string_view line, const std::string& file, int line_no,
                                  std::vector<ParseError>& errors) {
    return LineParser(line, file, line_no, errors).parse();
}

namespace {

constexpr std::size_t kMaxIncludeDepth = 16;

// "" and the text, or why the file cannot be read.
std::string read_script(const std::filesystem::path& path, std::string& text) {
    try {
        text = read_input(path, FileKind::Script);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

// `include FILE` (FILE quoted when it has blanks): the name, and the column where it starts; nullopt
// when the line is no include.
std::optional<std::pair<std::string, int>> include_of(std::string_view line) {
    int col = 1;
    std::string_view s = trim_blanks(line, &col);
    if (s.size() < 7 || to_upper(s.substr(0, 7)) != "INCLUDE" || (s.size() > 7 && !std::isspace(static_cast<unsigned char>(s[7]))))
        return std::nullopt;
    int at = col + 7;
    std::string_view rest = trim_blanks(s.substr(7), &at);
    if (const auto hash = rest.find(" #"); hash != std::string_view::npos && (rest.empty() || rest.front() != '"'))
        rest = trim_blanks(rest.substr(0, hash));
    if (rest.size() >= 2 && rest.front() == '"' && rest.back() == '"') rest = rest.substr(1, rest.size() - 2), ++at;
    return std::pair{std::string(rest), at};
}

// chain: the canonical paths of the files being read (a cycle test); from: the include lines
// being read, outermost first.
void parse_into(std::string_view text, const std::string& file, std::vector<ParseError>& errors,
                std::vector<Command>& out, std::vector<std::string>& chain, std::vector<Location>& from,
                std::vector<std::string>* included) {
    int n = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++n;
        if (const auto inc = include_of(line)) {
            // Relative to the including file's folder; a cycle or a missing file is the include
            // line's error, and an error inside says which lines included it.
            auto fail = [&](std::string why, int col) {
                errors.push_back({{file, n, col}, std::move(why), std::string(line)});
            };
            const std::size_t first_error = errors.size();
            if (inc->first.empty()) {
                fail("expected: include FILE", inc->second);
            } else {
                std::filesystem::path path = inc->first;
                if (path.is_relative()) path = std::filesystem::path(file).parent_path() / path;
                std::error_code ec;
                const std::string key = std::filesystem::weakly_canonical(path, ec).string();
                std::string body, unread;
                if (std::find(chain.begin(), chain.end(), key) != chain.end()) {
                    fail(fmt::format("'{}' includes itself (through {} file{})", inc->first, chain.size(),
                                     chain.size() == 1 ? "" : "s"),
                         inc->second);
                } else if (chain.size() > kMaxIncludeDepth) {  // chain: the top script and 16 levels below it
                    fail(fmt::format("includes nested deeper than {}", kMaxIncludeDepth), inc->second);
                } else if (unread = read_script(path, body); !unread.empty()) {
                    fail(unread, inc->second);
                } else {
                    if (included) included->push_back(path.string());
                    chain.push_back(key);
                    from.push_back({file, n, inc->second});
                    parse_into(body, path.string(), errors, out, chain, from, included);
                    from.pop_back();
                    chain.pop_back();
                    for (std::size_t i = first_error; i < errors.size(); ++i)
                        errors[i].message += fmt::format(" (included from {}:{})", file, n);
                }
            }
        } else if (auto c = parse_line(line, file, n, errors)) {
            c->included_from.assign(from.rbegin(), from.rend());
            out.push_back(std::move(*c));
        }
        if (end == text.size()) break;
        start = end + 1;
    }
}

}  // namespace

std::vector<Command> parse_script(std::string_view text, const std::string& file, std::vector<ParseError>& errors,
                                  std::vector<std::string>* included) {
    std::vector<Command> out;
    std::error_code ec;
    std::vector<std::string> chain{std::filesystem::weakly_canonical(file, ec).string()};
    std::vector<Location> from;
    parse_into(text, file, errors, out, chain, from, included);
    return out;
}

std::optional<Value> parse_value(std::string_view text, std::string_view what, bool address, std::string& error,
                                 int& error_col) {
    Value v;
    v.col = 1;
    v.text = std::string(text);
    error_col = 1;
    // A word of letters and digits that begins with a digit is a number.
    if (!text.empty() && std::isdigit(static_cast<unsigned char>(text[0])) &&
        std::all_of(text.begin(), text.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)); })) {
        if (address) {
            if (std::string why = ambiguous_address(text); !why.empty()) {
                error = std::move(why);
                return std::nullopt;
            }
        }
        const auto n = parse_number(text);
        if (!n) {
            error = fmt::format("bad number '{}'", text);
            return std::nullopt;
        }
        v.number = *n;
        return v;
    }
    // Anything else is the debugger's expression (debug::Expr), a bare name a symbol first.
    debug::ExprError why;
    const auto shape = debug::Expr::shape(text, why);
    if (!shape) {
        error_col = std::max(why.col, 1);
        error = why.col <= 1 && !text.empty() && why.message.starts_with("unexpected")
                    ? fmt::format("expected {}, found '{}'", what, text)
                    : why.message;
        return std::nullopt;
    }
    if (shape->constant) {
        v.number = *shape->constant;
        return v;
    }
    v.expression = true;
    v.names = shape->names;
    // SYMBOL+-N, the form scripts have always written: its parts name it in messages.
    const std::size_t split = text.find_first_of("+-", 1);
    const std::string_view head = text.substr(0, split);
    if (shape->names.size() == 1 && shape->names[0].col == 1 && shape->names[0].name.size() == head.size()) {
        const auto n = split == std::string_view::npos ? std::optional<std::int64_t>(0) : parse_number(text.substr(split + 1));
        if (n) {
            v.symbol = shape->names[0].name;
            v.number = split != std::string_view::npos && text[split] == '-' ? -*n : *n;
        }
    }
    return v;
}

std::string ambiguous_address(std::string_view text) {
    if (text.size() < 2 || text[0] != '0' ||
        !std::all_of(text.begin(), text.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
        return {};
    std::string_view digits = text;
    while (digits.size() > 1 && digits[0] == '0') digits.remove_prefix(1);
    const auto n = parse_number(digits);
    return fmt::format("address '{}' is ambiguous: a bare number is decimal ({} = {:04X}H); write {}H for hex "
                       "or {} for decimal",
                       text, *n, *n & 0xFFFF, text, digits);
}

std::optional<std::int64_t> parse_number(std::string_view text) { return parse_int(text); }

std::optional<std::uint64_t> parse_time(std::string_view text) {
    std::string s = to_upper(text);
    std::size_t i = 0;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
    if (i == 0) return std::nullopt;
    const std::string num = s.substr(0, i), unit = s.substr(i);
    if (std::count(num.begin(), num.end(), '.') > 1) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(num.c_str(), &end);
    if (end != num.c_str() + num.size() || !std::isfinite(v)) return std::nullopt;
    double ms;
    if (unit == "T") {
        if (num.find('.') != std::string::npos) return std::nullopt;
        if (v > 1e15) return std::nullopt;
        return static_cast<std::uint64_t>(v);
    } else if (unit == "US") {
        ms = v / 1e3;
    } else if (unit == "MS") {
        ms = v;
    } else if (unit == "S") {
        ms = v * 1e3;
    } else {
        return std::nullopt;
    }
    if (ms * board::kCpuHz / 1000.0 > 1e15) return std::nullopt;  // 10 years of simulated time: surely a typo
    return board::tstates_from_ms(ms);
}

std::optional<KeyRef> parse_key(std::string_view text) {
    const std::string u = to_upper(text);
    if (u == "RESET") return KeyRef{Button::Reset, periph::Key::K0, u};
    if (u == "VECT" || u == "VECTINTR" || u == "VECT_INTR") return KeyRef{Button::Vect, periph::Key::K0, "VECT"};
    if (const auto k = periph::Keypad::find(u)) return KeyRef{Button::Matrix, *k, u};
    return std::nullopt;
}

std::optional<std::vector<KeyRef>> parse_key_list(std::string_view text, std::string& error, std::size_t& offset) {
    std::vector<KeyRef> keys;
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && text[i] == ' ') ++i;
        std::size_t j = i;
        while (j < text.size() && text[j] != ' ') ++j;
        if (j == i) break;
        const std::string_view w = text.substr(i, j - i);
        if (const auto k = parse_key(w)) {
            keys.push_back(*k);
        } else {
            for (char ch : w) {
                const auto digit = std::isxdigit(static_cast<unsigned char>(ch)) ? parse_key(std::string(1, ch)) : std::nullopt;
                if (!digit) {
                    error = "unknown key '" + std::string(w) + "'";
                    offset = i;
                    return std::nullopt;
                }
                keys.push_back(*digit);
            }
        }
        i = j;
    }
    return keys;
}

const cpu::Register* parse_reg(std::string_view text) {
    const cpu::Register* r = cpu::description().find(text);
    return r && r->kind != cpu::Register::Kind::Memory ? r : nullptr;
}

}  // namespace alp85::script
