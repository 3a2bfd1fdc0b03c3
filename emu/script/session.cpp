#include "emu/script/session.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "emu/board/snapshot_file.h"
#include "emu/plot/plot.h"
#include "emu/util/atomic_file.h"
#include "emu/util/input_file.h"
#include "emu/debug/trace_csv.h"
#include "emu/util/text.h"
#include "peripherals/seven_segment.h"

namespace alp85::script {
namespace {

std::string rtrim(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

std::string hex(std::int64_t v, int digits) { return fmt::format("{:0{}X}H", v, digits); }


// The command that writes a file, as a refusal names it.
const char* op_word(Op op) { return op == Op::Save ? "save" : op == Op::Record ? "record" : "plot"; }

}  // namespace

Session::Session(SessionOptions options)
    : options_(std::move(options)),
      machine_(std::make_unique<Machine>(Machine::Options{options_.cpu})),
      debugger_(*machine_) {
    if (options_.max_time != ~std::uint64_t{0})
        debugger_.set_time_limit(options_.max_time,
                                 fmt::format("the machine-time limit was reached: {} of machine time (--max-time; "
                                             "a longer run needs a larger one)",
                                             format_limit(options_.max_time)));
    // A table reaching an end stop is reported as it happens (the screw stalls the motor there).
    machine_->tool().on_end_stop([this](periph::MachineTool::Axis axis, bool high, std::uint64_t t) {
        if (debugger_.replaying()) return;  // said the first time
        debugger_.emit({debug::Event::Kind::Output, {},
                        fmt::format("machine tool: the {} table reached its {} end stop at {}", "XYZ"[static_cast<int>(axis)],
                                    high ? "high" : "low", format_time(t - time_origin_)),
                        {}});
    });
    // The text front ends (alp85 script, alp85 run) read the events as they always printed them.
    if (std::ostream* out = options_.out) {
        debugger_.listen([out, verbose = options_.verbose](const debug::Event& e) {
            switch (e.kind) {
                case debug::Event::Kind::Output: *out << e.text << '\n'; break;
                case debug::Event::Kind::Stopped:
                    // A stop the script goes on from (and checks with expect reg PC) is progress:
                    // shown with -v only, so that a passing script is quiet.
                    if (!verbose) break;
                    *out << fmt::format("{}:{}: stopped at {} {}\n", e.origin.file, e.origin.line, debug::name(e.stop.reason),
                                        hex(e.stop.reason == debug::StopReason::Watchpoint ? *e.stop.data : e.stop.pc, 4));
                    break;
                case debug::Event::Kind::ExpectFailed: break;  // the runner reports the outcome
            }
        });
    }
}

// A --max-time as given: "1 h", "90 s", "250 ms".
std::string Session::format_limit(std::uint64_t t) {
    const double s = static_cast<double>(t) / board::kCpuHz;
    if (t % (3600ull * board::kCpuHz) == 0) return fmt::format("{} h", t / (3600ull * board::kCpuHz));
    if (s >= 1) return fmt::format("{:g} s", s);
    return fmt::format("{:g} ms", s * 1000);
}

std::string Session::format_time(std::uint64_t t) {
    return fmt::format("{:.3f} ms ({} T-states)", board::ms_from_tstates(t), t);
}

std::string Session::where_now() const {
    return fmt::format("at {}, PC={}, display \"{}\"", format_time(elapsed()), hex(machine_->cpu().regs().pc, 4),
                       machine_->display_text());
}

std::filesystem::path Session::resolve(const std::string& path) const {
    std::filesystem::path p(path);
    return p.is_absolute() ? p : options_.base_dir / p;
}

std::filesystem::path Session::resolve_output(const std::string& path) const {
    std::filesystem::path p(path);
    if (p.is_absolute() || out_dir_.empty()) return resolve(path);
    return out_dir_ / p;
}

std::optional<std::int64_t> Session::resolve(const Value& v, std::string& error) const {
    if (v.symbol.empty()) return v.number;
    const auto value = debugger_.program().value_of(v.symbol);
    if (!value) {
        error = fmt::format("unknown symbol '{}'", v.symbol);
        return std::nullopt;
    }
    // A symbol moved by its offset stays a 16-bit value: AUS-70000 is no address (it would wrap to F438H).
    const std::int64_t sum = *value + v.number;
    if (sum < 0 || sum > 0xFFFF) {
        error = fmt::format("{} is {:04X}H {} {} = {}, outside 0000H-0FFFFH", v.text, *value, v.number < 0 ? '-' : '+',
                            v.number < 0 ? -v.number : v.number, sum);
        return std::nullopt;
    }
    return sum;
}

Session::Outcome Session::fail(const Command& c, std::string what) const {
    if (c.where.line == 0) return {Status::Failed, std::move(what)};  // a front end's typed call: no script line
    return {Status::Failed, fmt::format("{}: {}\n  {}\n  {}", place_of(c), rtrim(c.line), what, where_now())};
}

Session::Outcome Session::fail_expect(const Command& c, const std::string& expected, const std::string& actual) const {
    debugger_.emit({debug::Event::Kind::ExpectFailed, debugger_.here(debug::StopReason::Condition),
                    fmt::format("expected: {}; actual: {}", expected, actual), origin(c)});
    return {Status::Failed, fmt::format("{}: expectation failed: {}\n  expected: {}\n  actual:   {}\n  {}",
                                        place_of(c), rtrim(c.line), expected, actual, where_now())};
}

void Session::add_input(const std::filesystem::path& path, std::string role) {
    if (path.empty()) return;
    for (const std::string& w : written_)
        if (same_file(w, path.string())) return;  // the session's own output, read back
    for (const NamedPath& in : inputs_)
        if (same_file(in.path, path.string())) return;
    inputs_.push_back({path.string(), std::move(role)});
}

void Session::add_output(const std::filesystem::path& path, std::string role) {
    if (!path.empty()) outputs_.push_back({path.string(), std::move(role)});
}

std::string Session::output_problem(const std::filesystem::path& path, const std::string& role) const {
    if (path.empty()) return role + ": an empty file name";
    if (std::string clash = output_clash(inputs_, {{path.string(), role}}); !clash.empty()) return clash + "; nothing written";
    for (const NamedPath& o : outputs_)
        if (same_file(o.path, path.string()))
            return fmt::format("{} '{}' is {} '{}': one would overwrite the other; nothing written", role, path.string(),
                               o.role, o.path);
    return {};
}

void Session::set_trace(std::ostream* out) {
    trace_ = out;
    if (!out) {
        machine_->set_trace({});
        return;
    }
    *out << trace_csv_header();
    machine_->set_trace([this](const I8085& cpu) {
        *trace_ << trace_csv_line(cpu, [this](std::uint16_t a) { return machine_->peek(a); });
    });
}

void Session::check(const std::vector<Command>& commands, std::vector<ParseError>& errors) {
    std::set<std::string> known;  // symbols defined by loads so far
    std::set<std::string> saved;  // snapshot files an earlier command writes
    bool recorded = false;        // a record command came before
    auto err = [&](const Command& c, int col, std::string msg) {
        errors.push_back({{c.where.file, c.where.line, col}, std::move(msg) + included_from(c), c.line});
    };
    auto col_of = [](const Command& c, const std::string& text) {
        const auto p = c.line.find(text);
        return p == std::string::npos ? c.where.col : static_cast<int>(p) + 1;
    };
    auto check_value = [&](const Command& c, const Value& v, std::int64_t lo, std::int64_t hi, const char* what) {
        if (!v.symbol.empty()) {
            if (!known.count(v.symbol)) err(c, v.col, fmt::format("unknown symbol '{}' (no source loaded before this line defines it)", v.symbol));
            return;
        }
        if (v.number < lo || v.number > hi) err(c, v.col, fmt::format("{} {} is out of range ({}..{})", what, v.text, lo, hi));
    };
    for (const Command& c : commands) {
        switch (c.op) {
            case Op::Load: {
                const auto path = resolve(c.text);
                const int col = col_of(c, c.text);
                if (const std::string why = program_file_problem(path); !why.empty()) {
                    err(c, col, why);
                    break;
                }
                const std::string ext = lower_extension(path);
                if ((ext == ".bin" || ext == ".rom") && !c.address) {
                    err(c, col, "a binary image needs 'at ADDRESS'");
                    break;
                }
                if (c.address) check_value(c, *c.address, 0, 0xFFFF, "address");
                try {
                    LoadOptions lo;
                    if (c.address)  // a number is checked where it goes; a symbol's address is known at run time
                        lo.address = c.address->symbol.empty() && c.address->number >= 0 && c.address->number <= 0xFFFF
                                         ? static_cast<std::uint16_t>(c.address->number)
                                         : std::uint16_t{0};
                    LoadedImage img = read_image(path, lo);
                    if (!c.address || c.address->symbol.empty()) check_board_regions(img, path);
                    for (const std::string& w : img.warnings)
                        if (std::find(warnings_.begin(), warnings_.end(), w) == warnings_.end()) warnings_.push_back(w);
                    for (const auto& s : img.symbols) known.insert(s.name);
                    if (!c.address) assembled_[path.string()] = std::move(img);
                } catch (const LoadError& e) {
                    err(c, col, e.what());
                }
                break;
            }
            case Op::Restore:
                if (saved.count(resolve_output(c.text).string())) break;
                if (const std::string why = input_problem(resolve_output(c.text)); !why.empty())
                    err(c, col_of(c, c.text), fmt::format("snapshot: {}", why));
                break;
            case Op::Save: saved.insert(resolve_output(c.text).string()); break;
            case Op::Monitor:
                if (!options_.monitor_rom) err(c, c.where.col, "this alp85 was built without the monitor ROM");
                else
                {
                    const firmware::Firmware rom = options_.monitor_rom();
                    for (const auto& s : rom.symbols.names()) known.insert(s.first);
                }
                break;
            case Op::Firmware: {
                const auto fw = firmware::find(c.text);
                if (!fw) {
                    std::string names;
                    for (const auto& e : firmware::builtin()) names += (names.empty() ? "" : ", ") + std::string(e.name);
                    err(c, col_of(c, c.text), fmt::format("no firmware '{}' in this alp85 (built in: {})", c.text, names));
                } else {
                    for (const auto& s : fw->symbols.names()) known.insert(s.first);
                }
                break;
            }
            case Op::Record:
                if (!c.signals) {
                    recorded = true;
                    break;
                }
                for (const Value& v : c.pins)
                    if (const std::string why = debug::SignalRecorder::check_selection(*machine_, {v.text}); !why.empty())
                        err(c, v.col, why);
                break;
            case Op::Plot:
                if (!recorded) err(c, c.where.col, "nothing recorded to plot: a 'record FILE.csv' must come first");
                break;
            case Op::RunUntil:
            case Op::Break:
            case Op::Delete: check_value(c, *c.address, 0, 0xFFFF, "address"); break;
            case Op::ExpectMem:
            case Op::SetMem:
                check_value(c, *c.address, 0, 0xFFFF, "address");
                for (const Value& v : c.values) check_value(c, v, -128, 255, "byte");
                break;
            case Op::ExpectWord:
                check_value(c, *c.address, 0, 0xFFFF, "address");
                check_value(c, c.values[0], -32768, 0xFFFF, "word");
                break;
            case Op::ExpectReg:
            case Op::SetReg:
                check_value(c, c.values[0], -(std::int64_t{1} << (c.reg->width - 1)), c.reg->mask(), "value");
                break;
            case Op::ExpectPort: check_value(c, c.values[0], 0, 0xFF, "value"); break;
            case Op::ExpectSymbol:
                if (!known.count(c.name)) err(c, col_of(c, c.name), fmt::format("unknown symbol '{}'", c.name));
                check_value(c, c.values[0], -32768, 0xFFFF, "value");
                break;
            default: break;
        }
    }
    // Every file the script reads, at any line, before any output is checked: `save x.asm` on
    // line 2 destroys the `load x.asm` of line 1 as surely as one of a later line.
    std::vector<std::filesystem::path> written;  // a snapshot saved before it is restored is no input
    std::set<std::string> scripts;               // each file once (a stat per comparison)
    for (const Command& c : commands) {
        if (c.where.line > 0 && scripts.insert(c.where.file).second)
            add_input(c.where.file, "an included script");  // the top one was added as "the script"
        if (c.op == Op::Load) add_input(resolve(c.text), "a program the script loads");
        if (c.op == Op::Save) written.push_back(resolve_output(c.text));
        if (c.op == Op::Restore &&
            std::none_of(written.begin(), written.end(), [&](const auto& w) { return same_file(w, resolve_output(c.text)); }))
            add_input(resolve_output(c.text), "a snapshot the script restores");
    }
    for (const Command& c : commands)
        if (c.op == Op::Save || c.op == Op::Record || c.op == Op::Plot)
            if (const std::string why = output_problem(resolve_output(c.text), op_word(c.op)); !why.empty())
                err(c, col_of(c, c.text), why);
}

Session::Outcome Session::load(const Command& c, const Boot* boot) {
    const auto path = resolve(c.text);
    try {
        LoadOptions lo;
        if (boot) lo.assembler.defines = boot->defines;
        if (c.address) {
            std::string e;
            const auto a = resolve(*c.address, e);
            if (!a) return fail(c, e);
            lo.address = static_cast<std::uint16_t>(*a);
        }
        const auto cached = assembled_.find(path.string());
        LoadedImage img = cached != assembled_.end() && !lo.address && lo.assembler.defines.empty() ? cached->second
                                                                                                    : read_image(path, lo);
        check_board_regions(img, path);
        machine_->load(img.segments);
        add_input(path, "a program the session loaded");
        if (img.assembly)
            debugger_.program().add_assembly(*img.assembly);
        else
            for (const auto& s : img.symbols) debugger_.program().add(s.name, s.value, asm85::kind_name(s.kind));
        placed(img.segments);
        last_start_ = img.start;
        if (!img.start && !img.segments.empty()) last_start_ = img.segments.front().address;
        if (report_) report_->warnings.insert(report_->warnings.end(), img.warnings.begin(), img.warnings.end());
    } catch (const LoadError& e) {
        return fail(c, e.what());
    } catch (const std::out_of_range& e) {
        return fail(c, fmt::format("{}: {}", path.string(), e.what()));
    }
    return {};
}

// A run in slices of pace_slice_ with the pace hook called between them (a window drawing the
// machine at real time); the same instructions run as in one piece.
debug::Stop Session::run_paced(std::uint64_t until, const std::function<bool()>& condition, const debug::Origin& o) {
    if (!pace_) return debugger_.run_until(until, condition, o);
    for (;;) {
        const std::uint64_t slice_end = std::min(until, machine_->now() + pace_slice_);
        const debug::Stop s = debugger_.run_until(slice_end, condition, o);
        if (s.reason != debug::StopReason::Deadline || machine_->now() >= until) return s;
        pace_(machine_->now());
    }
}

Session::Outcome Session::press(const Command& c, const KeyRef& key, std::uint64_t hold, std::uint64_t gap) {
    Machine& m = *machine_;
    const Button button = key.kind;
    if (button == Button::Reset) time_origin_ = m.now();
    run_paced(schedule_press(m, button, key.key, hold, gap), {}, origin(c));
    return {};
}

Session::Outcome Session::expect(const Command& c) {
    const Machine& m = *machine_;
    std::string e;
    auto value = [&](const Value& v) { return resolve(v, e); };
    switch (c.op) {
        case Op::ExpectDisplay: {
            const std::string actual = m.display_text();
            if (rtrim(actual) != rtrim(c.text)) return fail_expect(c, fmt::format("\"{}\"", c.text), fmt::format("\"{}\"", actual));
            return {};
        }
        case Op::ExpectMem: {
            const auto a = value(*c.address);
            if (!a) return fail(c, e);
            std::string exp, act;
            bool same = true;
            for (std::size_t i = 0; i < c.values.size(); ++i) {
                const auto v = value(c.values[i]);
                if (!v) return fail(c, e);
                const std::uint8_t want = static_cast<std::uint8_t>(*v);
                const std::uint8_t got = m.peek(static_cast<std::uint16_t>(*a + static_cast<std::int64_t>(i)));
                same = same && want == got;
                exp += (i ? " " : "") + hex(want, 2);
                act += (i ? " " : "") + hex(got, 2);
            }
            if (!same) return fail_expect(c, fmt::format("{} at {}", exp, hex(*a, 4)), act);
            return {};
        }
        case Op::ExpectWord: {
            const auto a = value(*c.address);
            const auto v = value(c.values[0]);
            if (!a || !v) return fail(c, e);
            const std::uint16_t got = static_cast<std::uint16_t>(m.peek(static_cast<std::uint16_t>(*a)) |
                                                                 m.peek(static_cast<std::uint16_t>(*a + 1)) << 8);
            if (got != static_cast<std::uint16_t>(*v)) return fail_expect(c, hex(static_cast<std::uint16_t>(*v), 4), hex(got, 4));
            return {};
        }
        case Op::ExpectReg: {
            const auto v = value(c.values[0]);
            if (!v) return fail(c, e);
            const int digits = c.reg->width > 8 ? 4 : 2;
            const std::uint16_t want = static_cast<std::uint16_t>(*v & c.reg->mask());
            const std::uint16_t got = c.reg->read(m.cpu().regs());
            if (want != got) return fail_expect(c, fmt::format("{} = {}", c.reg->name, hex(want, digits)), hex(got, digits));
            return {};
        }
        case Op::ExpectFlag: {
            const bool want = c.values[0].number != 0;
            const bool got = (cpu::description().flag_register()->read(m.cpu().regs()) & c.flag) != 0;
            if (want != got) return fail_expect(c, fmt::format("{} = {}", c.flag_name, want ? 1 : 0), got ? "1" : "0");
            return {};
        }
        case Op::ExpectPort: {
            const auto v = value(c.values[0]);
            if (!v) return fail(c, e);
            const auto& latch = m.rio().state().latch;
            const std::uint8_t got = latch[static_cast<std::size_t>(c.port - 'A')];
            if (got != static_cast<std::uint8_t>(*v))
                return fail_expect(c, fmt::format("port {} latch = {}", c.port, hex(*v, 2)), hex(got, 2));
            return {};
        }
        case Op::ExpectSymbol: {
            const auto v = value(c.values[0]);
            if (!v) return fail(c, e);
            const auto actual = debugger_.program().value_of(c.name);
            if (!actual) return fail(c, fmt::format("unknown symbol '{}'", c.name));
            if (*actual != static_cast<std::uint16_t>(*v)) return fail_expect(c, hex(*v & 0xFFFF, 4), hex(*actual, 4));
            return {};
        }
        case Op::ExpectTime: {
            const std::uint64_t t = elapsed();
            bool ok = false;
            const char* op = "";
            switch (c.compare) {
                case Compare::Lt: ok = t < c.time, op = "<"; break;
                case Compare::Le: ok = t <= c.time, op = "<="; break;
                case Compare::Eq: ok = t == c.time, op = "="; break;
                case Compare::Ge: ok = t >= c.time, op = ">="; break;
                case Compare::Gt: ok = t > c.time, op = ">"; break;
            }
            if (!ok) return fail_expect(c, fmt::format("time {} {}", op, format_time(c.time)), format_time(t));
            return {};
        }
        case Op::ExpectHalted:
            if (!m.cpu().halted()) return fail_expect(c, "the CPU halted", "running");
            return {};
        case Op::ExpectRunning:
            if (m.cpu().halted()) return fail_expect(c, "the CPU running", "halted");
            return {};
        default: return {};
    }
}

namespace {
template <class T>
bool compare(T actual, Compare op, T want) {
    switch (op) {
        case Compare::Lt: return actual < want;
        case Compare::Le: return actual <= want;
        case Compare::Eq: return actual == want;
        case Compare::Ge: return actual >= want;
        case Compare::Gt: return actual > want;
    }
    return false;
}
const char* compare_text(Compare op) {
    switch (op) {
        case Compare::Lt: return "< ";
        case Compare::Le: return "<= ";
        case Compare::Eq: return "";
        case Compare::Ge: return ">= ";
        case Compare::Gt: return "> ";
    }
    return "";
}
periph::MachineTool::Axis tool_axis(const Command& c) { return static_cast<periph::MachineTool::Axis>(c.axis); }
char axis_name(const Command& c) { return "XYZ"[c.axis % 3]; }
// The table's position as whole steps: the nearest step (a settled physical rotor rests within a
// fraction of a step of it).
std::int64_t whole_steps(const periph::MachineTool& tool, periph::MachineTool::Axis a) {
    return std::llround(tool.table_steps(a));
}
}  // namespace

std::string Session::axes_text() const {
    const periph::MachineTool& tool = machine_->tool();
    std::string out = fmt::format("machine tool ({} motors, transducers on the {}):",
                                  tool.model() == periph::MachineTool::MotorModel::Ideal ? "ideal" : "physical",
                                  tool.feedback() == periph::MachineTool::Feedback::Scale ? "scale" : "commanded steps");
    for (int a = 0; a < 3; ++a) {
        const auto axis = static_cast<periph::MachineTool::Axis>(a);
        const auto stop = tool.end_stop(axis);
        out += fmt::format("\n  {}  {:6} steps  {:9.3f} mm  count {:6}  commanded {:6}  lost {}{}", "XYZ"[a],
                           whole_steps(tool, axis), tool.table_mm(axis), tool.transducer_count(axis),
                           tool.commanded_steps(axis), tool.lost_steps(axis),
                           stop.at ? (stop.at > 0 ? "  at its high end stop" : "  at its low end stop") : "");
    }
    return out;
}

Session::Outcome Session::write_recording() {
    recorder_.stop();
    if (const std::string why = output_problem(record_path_, "record"); !why.empty()) return fail(record_command_, why);
    try {
        AtomicOutput file(record_path_);
        recorder_.write_csv(file.stream());
        file.commit();
    } catch (const std::exception& x) {
        return fail(record_command_, x.what());
    }
    if (recorder_.full())
        return fail(record_command_,
                    fmt::format("the recording reached its cap of {} samples: '{}' holds the first {} (record with a "
                                "longer period, e.g. every 1ms)",
                                debug::ToolRecorder::kMaxSamples, record_path_.string(), debug::ToolRecorder::kMaxSamples));
    return {};
}

Session::Outcome Session::write_signals() {
    if (const std::string why = output_problem(signals_.path(), "record"); !why.empty()) {
        signals_.abandon();
        return fail(signals_command_, why);
    }
    try {
        signals_.stop();
    } catch (const std::exception& x) {
        return fail(signals_command_, x.what());
    }
    return {};
}

Session::Outcome Session::finish() { return stop_recordings(); }

// Writes every recording running: the pins' VCD and the tool's CSV (the first failure is told).
Session::Outcome Session::stop_recordings() {
    Outcome o;
    if (signals_.recording()) o = write_signals();
    if (recorder_.recording()) {
        const Outcome csv = write_recording();
        if (o.status == Status::Ok) o = csv;
    }
    return o;
}

Session::Outcome Session::tool_command(const Command& c) {
    Machine& m = *machine_;
    periph::MachineTool& tool = m.tool();
    const auto axis = tool_axis(c);
    tool.advance(m.now());
    switch (c.op) {
        case Op::Motor:
            tool.set_model(c.real == 0 ? periph::MachineTool::MotorModel::Ideal : periph::MachineTool::MotorModel::Physical);
            return {};
        case Op::Feedback:
            tool.set_feedback(c.real == 0 ? periph::MachineTool::Feedback::Scale : periph::MachineTool::Feedback::Commanded);
            return {};
        case Op::PrintAxes: output(c, axes_text()); return {};
        case Op::PrintTime:
            output(c, mark_ ? fmt::format("time: {} since the mark, {} since the last reset",
                                          format_time(m.now() - *mark_), format_time(elapsed()))
                            : fmt::format("time: {} since the last reset", format_time(elapsed())));
            return {};
        case Op::Mark: mark_ = m.now(); return {};
        case Op::NewWorkpiece: tool.set_up_workpiece(m.now()); return {};
        case Op::ExpectAxis: {
            if (c.in_mm) {
                const double mm = tool.table_mm(axis);
                const bool ok = c.compare == Compare::Eq ? std::abs(mm - c.real) <= c.within
                                                         : compare(mm, c.compare, c.real);
                if (!ok)
                    return fail_expect(c, fmt::format("axis {} at {}{:.4f} mm{}", axis_name(c), compare_text(c.compare), c.real,
                                                      c.compare == Compare::Eq ? fmt::format(" within {} mm", c.within) : ""),
                                       fmt::format("{:.4f} mm", mm));
                return {};
            }
            const std::int64_t steps = whole_steps(tool, axis);
            if (!compare(steps, c.compare, c.integer))
                return fail_expect(c, fmt::format("axis {} at {}{} steps", axis_name(c), compare_text(c.compare), c.integer),
                                   fmt::format("{} steps ({:.3f})", steps, tool.table_steps(axis)));
            return {};
        }
        case Op::ExpectCount:
        case Op::ExpectLost: {
            const bool count = c.op == Op::ExpectCount;
            const std::int64_t v = count ? tool.transducer_count(axis) : tool.lost_steps(axis);
            if (!compare(v, c.compare, c.integer))
                return fail_expect(c, fmt::format("{} {} {}{}", count ? "count" : "lost steps", axis_name(c),
                                                  compare_text(c.compare), c.integer),
                                   std::to_string(v));
            return {};
        }
        case Op::RunUntilAxis: {
            const debug::Stop stop = run_paced(
                m.now() + c.time, [&] { return compare(whole_steps(tool, axis), c.compare, c.integer); }, origin(c));
            if (stop.reason == debug::StopReason::Condition) return {};
            if (stop.reason == debug::StopReason::Breakpoint)
                return fail(c, fmt::format("stopped at breakpoint {} before axis {} reached {}{} steps", hex(stop.pc, 4),
                                           axis_name(c), compare_text(c.compare), c.integer));
            return fail(c, fmt::format("axis {} did not reach {}{} steps within {} (it is at {} steps)", axis_name(c),
                                       compare_text(c.compare), c.integer, format_time(c.time), whole_steps(tool, axis)));
        }
        case Op::Record:
            if (c.signals) {
                if (signals_.recording()) {
                    if (Outcome o = write_signals(); o.status != Status::Ok) return o;
                }
                const auto path = resolve_output(c.text);
                if (const std::string why = output_problem(path, "record"); !why.empty()) return fail(c, why);
                std::vector<std::string> pins;
                for (const Value& v : c.pins) pins.push_back(v.text);
                try {
                    signals_.start(m, path, pins, c.period);
                } catch (const std::exception& x) {
                    return fail(c, x.what());
                }
                signals_command_ = c;
                return {};
            }
            if (recorder_.recording()) {
                if (Outcome o = write_recording(); o.status != Status::Ok) return o;
            }
            if (const std::string why = output_problem(resolve_output(c.text), "record"); !why.empty()) return fail(c, why);
            record_path_ = resolve_output(c.text);
            record_command_ = c;
            recorder_.start(m, c.period);
            return {};
        case Op::RecordStop: {
            // Ends every recording running: the tool's CSV and the pins' VCD.
            if (!recorder_.recording() && !signals_.recording())
                return fail(c, "no recording to stop (record FILE.csv or record signals FILE.vcd starts one)");
            return stop_recordings();
        }
        case Op::Plot: {
            const auto& samples = recorder_.samples();
            if (samples.size() < 2) return fail(c, "nothing recorded to plot (record FILE.csv first, then run)");
            if (const std::string why = output_problem(resolve_output(c.text), "plot"); !why.empty()) return fail(c, why);
            if (recorder_.recording()) {
                // Include the present moment (the last sample may be up to one period old).
                m.tool().advance(m.now());
            }
            try {
                if (c.name == "TOOLPATH") {
                    plot::Series path{"table (X, Y)", {}};
                    for (const auto& smp : samples) path.points.push_back({smp.axes[0].mm, smp.axes[1].mm});
                    const plot::Point a = c.ideal_line ? plot::Point{(*c.ideal_line)[0], (*c.ideal_line)[1]} : path.points.front();
                    const plot::Point b = c.ideal_line ? plot::Point{(*c.ideal_line)[2], (*c.ideal_line)[3]} : path.points.back();
                    plot::write_toolpath(resolve_output(c.text).string(), "Toolpath", {path}, std::make_pair(a, b));
                } else {
                    std::vector<plot::Series> series;
                    for (int a = 0; a < 3; ++a) {
                        plot::Series axis{std::string(1, "XYZ"[a]), {}};
                        for (const auto& smp : samples)
                            axis.points.push_back({static_cast<double>(smp.t - samples.front().t) / board::kCpuHz,
                                                   smp.axes[static_cast<std::size_t>(a)].mm});
                        series.push_back(std::move(axis));
                    }
                    plot::write_time_series(resolve_output(c.text).string(), "Table position against time", series,
                                            "position (mm)");
                }
            } catch (const plot::PlotError& x) {
                return fail(c, x.what());
            }
            return {};
        }
        default: return {};
    }
}

namespace {
Command typed(Op op, std::string text = {}) {
    Command c;
    c.op = op;
    c.where = {"(front end)", 0, 0};
    c.text = std::move(text);
    c.line = c.text;
    return c;
}
}  // namespace

void Session::placed(const std::vector<ImageSegment>& segments) {
    if (!report_) return;
    for (const ImageSegment& s : segments)
        for (std::size_t i = 0; i < s.bytes.size(); ++i) report_->code.set((s.address + i) & 0xFFFF);
}

Session::Outcome Session::boot(const Boot& b, BootReport* report) {
    if (report) {
        *report = {};
        for (const board::MemoryRegion& r : machine_->memory_map())
            if (r.kind == board::MemoryKind::Ram)
                for (unsigned a = r.base; a < r.base + r.size; ++a) report->code.set(a);
    }
    report_ = report;
    const Outcome o = boot_steps(b);
    report_ = nullptr;
    return o;
}

Session::Outcome Session::boot_steps(const Boot& b) {
    if (b.motor)
        if (Outcome o = set_motor(*b.motor); o.status != Status::Ok) return o;
    if (b.monitor)
        if (Outcome o = load_monitor(); o.status != Status::Ok) return o;
    std::optional<std::uint16_t> start;  // where a board without the monitor starts
    for (const std::string& f : b.firmware) {
        if (Outcome o = load_firmware(f); o.status != Status::Ok) return o;
        if (const auto fw = firmware::find(f); fw && !fw->segments.empty()) start = fw->segments.front().address;
    }
    for (const Boot::Image& i : b.images) {
        Command c = typed(Op::Load, i.path.string());
        if (i.address) c.address = Value{{}, *i.address, 0, hex(*i.address, 4)};
        Outcome o = load(c, &b);
        debugger_.state_changed(false);  // as execute() after a load
        if (o.status != Status::Ok) return o;
        if (last_start_) start = last_start_;
    }
    for (const std::filesystem::path& m : b.maps) {
        const auto map = resolve(m.string());
        add_input(map, "a program's map");
        if (std::string why = debugger_.program().load_map_file(map.string()); !why.empty()) return {Status::Failed, std::move(why)};
    }
    if (!b.reset) return {};
    if (Outcome o = reset(); o.status != Status::Ok) return o;
    if (b.pc_at_program && start) machine_->cpu().regs().pc = *start;
    std::uint64_t t = machine_->now() + b.boot_time;
    for (const KeyRef& k : b.keys) {
        key(k.kind, k.key, true, t);
        key(k.kind, k.key, false, t + kKeyHold);
        t += kKeyHold + kKeyGap;
    }
    return {};
}

Session::Outcome Session::load_monitor() { return execute(typed(Op::Monitor)); }
Session::Outcome Session::load_firmware(const std::string& name) { return execute(typed(Op::Firmware, name)); }

Session::Outcome Session::load_image(const std::filesystem::path& path, std::optional<std::uint16_t> address) {
    Command c = typed(Op::Load, path.string());
    if (address) c.address = Value{{}, *address, 0, hex(*address, 4)};
    return execute(c);
}

Session::Outcome Session::reset() { return execute(typed(Op::Reset)); }
Session::Outcome Session::save(const std::filesystem::path& path) { return execute(typed(Op::Save, path.string())); }
Session::Outcome Session::restore(const std::filesystem::path& path) { return execute(typed(Op::Restore, path.string())); }

Session::Outcome Session::record(const std::filesystem::path& csv, std::uint64_t period) {
    Command c = typed(Op::Record, csv.string());
    c.period = period;
    return execute(c);
}
Session::Outcome Session::trace_signals(const std::vector<std::string>& pins, std::uint64_t span) {
    try {
        pane_trace_.start(*machine_, pins, span);
    } catch (const std::exception& x) {
        return {Status::Failed, x.what()};
    }
    return {};
}

Session::Outcome Session::record_signals(const std::filesystem::path& vcd, const std::vector<std::string>& pins,
                                         std::uint64_t period) {
    Command c = typed(Op::Record, vcd.string());
    c.signals = true;
    c.period = period;
    for (const std::string& p : pins) c.pins.push_back({{}, 0, 0, p});
    return execute(c);
}

Session::Outcome Session::record_stop() { return execute(typed(Op::RecordStop)); }

Session::Outcome Session::plot_toolpath(const std::filesystem::path& out) {
    Command c = typed(Op::Plot, out.string());
    c.name = "TOOLPATH";
    return execute(c);
}

Session::Outcome Session::new_workpiece() { return execute(typed(Op::NewWorkpiece)); }

Session::Outcome Session::set_motor(periph::MachineTool::MotorModel model) {
    Command c = typed(Op::Motor);
    c.real = model == periph::MachineTool::MotorModel::Ideal ? 0 : 1;
    return execute(c);
}

void Session::key(Button button, periph::Key k, bool down, std::optional<std::uint64_t> at) {
    Machine& m = *machine_;
    schedule_key(m, button, k, down, at.value_or(m.now()));
    if (button == Button::Reset && down) time_origin_ = m.now();
}

void Session::set_pc(std::uint16_t pc) {
    machine_->cpu().regs().pc = pc;
    debugger_.state_changed();  // the timeline changes here: history after now is another run's
}

void Session::sample_tool(std::uint64_t period, std::function<void(const debug::ToolSample&)> sample) {
    if (!sample) {
        machine_->set_sampler(0, {});
        return;
    }
    machine_->set_sampler(period, [this, sample = std::move(sample)](std::uint64_t t) {
        sample(debug::sample_tool(machine_->tool(), t));
    });
}

Session::Outcome Session::execute(const Command& c) {
    Outcome o = run_command(c);
    if (debugger_.take_time_limit_hit()) o = fail(c, debugger_.time_limit_message());
    // The machine changed outside its run: reverse execution's history ends here.
    switch (c.op) {
        case Op::Load: case Op::Monitor: case Op::Firmware: case Op::Reset: case Op::Motor: case Op::Feedback: case Op::NewWorkpiece:
        case Op::SetMem: case Op::SetReg: case Op::Restore: case Op::Option:
            debugger_.state_changed(c.op == Op::Restore);
            break;
        default: break;
    }
    return o;
}

Session::Outcome Session::run_command(const Command& c) {
    Machine& m = *machine_;
    if (options_.verbose) output(c, fmt::format("[{}] {}:{}: {}", format_time(elapsed()), c.where.file, c.where.line, rtrim(c.line)));
    std::string e;
    switch (c.op) {
        case Op::Load: return load(c);
        case Op::Monitor:
            if (!options_.monitor_rom) return fail(c, "this alp85 was built without the monitor ROM");
            {
                const firmware::Firmware rom = options_.monitor_rom();
                m.load(rom.segments);
                debugger_.program().add_table(rom.symbols);
                placed(rom.segments);
            }
            return {};
        case Op::Firmware: {
            const auto fw = firmware::find(c.text);
            if (!fw) return fail(c, fmt::format("no firmware '{}' in this alp85", c.text));
            if (fw->expansion_eprom) m.set_expansion_eprom(true);  // the EPROM it is in goes in with it
            m.load(fw->segments);
            debugger_.program().add_table(fw->symbols);
            placed(fw->segments);
            return {};
        }
        case Op::Reset:
            m.reset();
            time_origin_ = m.now();
            return {};
        case Op::Press: return press(c, c.keys[0], c.time, c.gap);
        case Op::Type:
            for (const KeyRef& k : c.keys)
                if (Outcome o = press(c, k, c.time, c.gap); o.status != Status::Ok) return o;
            return {};
        case Op::KeyDown:
        case Op::KeyUp: {
            const bool down = c.op == Op::KeyDown;
            const KeyRef& k = c.keys[0];
            if (k.kind == Button::Matrix) m.key_at(k.key, down, m.now());
            else if (k.kind == Button::Vect) m.vect_intr_at(down, m.now());
            else {
                m.reset_key_at(down, m.now());
                if (down) time_origin_ = m.now();
            }
            m.run_for(0);  // deliver it now
            return {};
        }
        case Op::Run:
            run_paced(m.now() + c.time, {}, origin(c));
            return {};
        case Op::RunUntil: {
            const auto a = resolve(*c.address, e);
            if (!a) return fail(c, e);
            const auto target = static_cast<std::uint16_t>(*a);
            if (debugger_.run_to(target, m.now() + c.time).reason != debug::StopReason::Target)
                return fail(c, fmt::format("the PC did not reach {} within {}", hex(target, 4), format_time(c.time)));
            return {};
        }
        case Op::WaitDisplay: {
            const std::string want = rtrim(c.text);
            const debug::Stop stop = run_paced(m.now() + c.time, [&] { return rtrim(m.display_text()) == want; }, origin(c));
            if (stop.reason == debug::StopReason::Condition) return {};
            if (stop.reason == debug::StopReason::Breakpoint || stop.reason == debug::StopReason::Watchpoint)
                return fail(c, fmt::format("stopped at {} {} before the display showed \"{}\"", debug::name(stop.reason),
                                           hex(m.cpu().regs().pc, 4), c.text));
            if (stop.reason == debug::StopReason::Interrupted) return fail(c, "interrupted");
            return fail(c, fmt::format("the display did not show \"{}\" within {}", c.text, format_time(c.time)));
        }
        case Op::Step:
            for (unsigned i = 0; i < c.count; ++i) m.step();
            return {};
        case Op::Break:
        case Op::Delete: {
            const auto a = resolve(*c.address, e);
            if (!a) return fail(c, e);
            if (c.op == Op::Break) debugger_.add_breakpoint_at(static_cast<std::uint16_t>(*a));
            else debugger_.remove_breakpoints_at(static_cast<std::uint16_t>(*a));
            return {};
        }
        case Op::DeleteAll: debugger_.remove_all(); return {};
        case Op::SetMem: {
            const auto a = resolve(*c.address, e);
            if (!a) return fail(c, e);
            for (std::size_t i = 0; i < c.values.size(); ++i) {
                const auto v = resolve(c.values[i], e);
                if (!v) return fail(c, e);
                const auto addr = static_cast<std::uint16_t>(*a + static_cast<std::int64_t>(i));
                if (!m.poke(addr, static_cast<std::uint8_t>(*v)))
                    return fail(c, fmt::format("no memory at {}", hex(addr, 4)));
            }
            return {};
        }
        case Op::SetReg: {
            const auto v = resolve(c.values[0], e);
            if (!v) return fail(c, e);
            c.reg->write(m.cpu().regs(), static_cast<std::uint16_t>(*v & c.reg->mask()));
            return {};
        }
        case Op::Save:
            if (const std::string why = output_problem(resolve_output(c.text), "save"); !why.empty()) return fail(c, why);
            try {
                m.save_snapshot(resolve_output(c.text));
            } catch (const snapshot::SnapshotError& x) {
                return fail(c, x.what());
            }
            written_.push_back(resolve_output(c.text).string());
            return {};
        case Op::Restore:
            try {
                m.load_snapshot(resolve_output(c.text));
            } catch (const snapshot::SnapshotError& x) {
                return fail(c, x.what());
            }
            add_input(resolve_output(c.text), "a snapshot the session restored");
            return {};
        case Op::Option:
            m.set_expansion_eprom(c.real == 1);  // the one board option (board::kBoardOptions)
            return {};
        case Op::Motor:
        case Op::Feedback:
        case Op::NewWorkpiece:
        case Op::PrintAxes:
        case Op::PrintTime:
        case Op::Mark:
        case Op::ExpectAxis:
        case Op::ExpectCount:
        case Op::ExpectLost:
        case Op::RunUntilAxis:
        case Op::Record:
        case Op::RecordStop:
        case Op::Plot: return tool_command(c);
        case Op::PrintDisplay:
            if (c.text == "text") {
                output(c, '"' + m.display_text() + '"');
            } else {
                std::string art;
                for (const std::string& line : m.display_art()) art += (art.empty() ? "" : "\n") + line;
                output(c, art);
            }
            return {};
        case Op::Print: output(c, c.text); return {};
        default: return expect(c);
    }
}

}  // namespace alp85::script
