#include "emu/script/session.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "emu/board/snapshot_file.h"
#include "emu/program/rom_image.h"
#include "emu/plot/plot.h"
#include "asm/files/atomic_file.h"
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
      machine_(std::make_unique<Machine>([&] {
          Machine::Options o;
          o.cpu = options_.cpu;
          o.board = options_.board;
          return o;
      }())),
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
    if (!v.expression) return v.number;
    // The debugger's expression, against the symbols and the machine of now.
    debug::ExprError why;
    const auto e = debug::Expr::parse(v.text, debugger_.program(), why, debug::Expr::Names::SymbolsFirst);
    if (!e) {
        error = why.message;
        return std::nullopt;
    }
    std::int64_t sum = 0;
    try {
        sum = e->eval(*machine_);
    } catch (const debug::ExprError& x) {
        error = fmt::format("{}: {}", v.text, x.message);
        return std::nullopt;
    }
    // A value stays a 16-bit one: AUS-70000 is no address (it would wrap to F438H).
    if (sum < 0 || sum > 0xFFFF) {
        const auto symbol = v.symbol.empty() ? std::nullopt : debugger_.program().value_of(v.symbol);
        error = symbol ? fmt::format("{} is {:04X}H {} {} = {}, outside 0000H-0FFFFH", v.text, *symbol, v.number < 0 ? '-' : '+',
                                     v.number < 0 ? -v.number : v.number, sum)
                       : fmt::format("{} is {}, outside 0000H-0FFFFH", v.text, sum);
        return std::nullopt;
    }
    return sum;
}

Session::Outcome Session::fail_at(const Command* c, std::string what) const {
    if (!c || c->where.line == 0) return {Status::Failed, std::move(what)};  // a front end's typed call: no script line
    return {Status::Failed, fmt::format("{}: {}\n  {}\n  {}", place_of(*c), rtrim(c->line), what, where_now())};
}

debug::Origin Session::origin() const {
    if (!line_) return {"(front end)", 0};
    return {line_->where.file, line_->where.line};
}

Session::Outcome Session::fail_expect(const std::string& expected, const std::string& actual) const {
    debugger_.emit({debug::Event::Kind::ExpectFailed, debugger_.here(debug::StopReason::Condition),
                    fmt::format("expected: {}; actual: {}", expected, actual), origin()});
    if (!line_) return {Status::Failed, fmt::format("expectation failed: expected: {}; actual: {}", expected, actual)};
    return {Status::Failed, fmt::format("{}: expectation failed: {}\n  expected: {}\n  actual:   {}\n  {}",
                                        place_of(*line_), rtrim(line_->line), expected, actual, where_now())};
}

Session::Outcome Session::ran(Outcome o) {
    if (debugger_.take_time_limit_hit()) return fail(debugger_.time_limit_message());
    return o;
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

std::string Session::check_monitor(std::set<std::string>& known) const {
    if (!options_.monitor_rom) return "this alp85 was built without the monitor ROM";
    const firmware::Firmware rom = options_.monitor_rom();
    for (const auto& s : rom.symbols.names()) known.insert(s.first);
    return {};
}

std::string Session::check_firmware(const std::string& name, std::set<std::string>& known) const {
    const auto fw = firmware::find(name);
    if (!fw) {
        std::string names;
        for (const auto& e : firmware::builtin()) names += (names.empty() ? "" : ", ") + std::string(e.name);
        return fmt::format("no firmware '{}' in this alp85 (built in: {})", name, names);
    }
    for (const auto& s : fw->symbols.names()) known.insert(s.first);
    return {};
}

std::string Session::check_program(const std::filesystem::path& file, bool has_address) const {
    const auto path = resolve(file.string());
    if (std::string why = program_file_problem(path); !why.empty()) return why;
    const std::string ext = lower_extension(path);
    if ((ext == ".bin" || ext == ".rom") && !has_address) return "a binary image needs 'at ADDRESS'";
    return {};
}

std::string Session::check_image(const std::filesystem::path& file, const std::optional<Value>& address,
                                 std::set<std::string>& known) {
    const auto path = resolve(file.string());
    try {
        LoadOptions lo;
        if (address)  // a number is checked where it goes; a symbol's address is known at run time
            lo.address = !address->expression && address->number >= 0 && address->number <= 0xFFFF
                             ? static_cast<std::uint16_t>(address->number)
                             : std::uint16_t{0};
        LoadedImage img = read_image(path, lo);
        if (!address || !address->expression) check_board_regions(img, path);
        for (const std::string& w : img.warnings)
            if (std::find(warnings_.begin(), warnings_.end(), w) == warnings_.end()) warnings_.push_back(w);
        for (const auto& s : img.symbols) known.insert(s.name);
        if (!address) assembled_[path.string()] = std::move(img);
    } catch (const LoadError& e) {
        return e.what();
    }
    return {};
}

std::vector<std::pair<int, std::string>> Session::check_value(const Value& v, std::int64_t lo, std::int64_t hi,
                                                              const char* what, const std::set<std::string>& known) const {
    std::vector<std::pair<int, std::string>> out;
    if (v.expression) {  // each name a symbol loaded before this line, or a register or flag
        for (const debug::Expr::Name& n : v.names)
            if (!known.count(n.name) && (n.symbol_only || !n.machine))
                out.emplace_back(v.col + n.col - 1,
                                 fmt::format("unknown symbol '{}' (no source loaded before this line defines it)", n.name));
        return out;
    }
    if (v.number < lo || v.number > hi) out.emplace_back(v.col, fmt::format("{} {} is out of range ({}..{})", what, v.text, lo, hi));
    return out;
}

std::string Session::check_pin(const std::string& pin) const { return debug::SignalRecorder::check_selection(*machine_, {pin}); }

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
    auto value_in = [&](const Command& c, const Value& v, std::int64_t lo, std::int64_t hi, const char* what) {
        for (auto& [col, why] : check_value(v, lo, hi, what, known)) err(c, col, std::move(why));
    };
    for (const Command& c : commands) {
        switch (c.op) {
            case Op::Load: {
                const int col = col_of(c, c.text);
                if (std::string why = check_program(c.text, c.address.has_value()); !why.empty()) {
                    err(c, col, std::move(why));
                    break;
                }
                if (c.address) value_in(c, *c.address, 0, 0xFFFF, "address");
                if (std::string why = check_image(c.text, c.address, known); !why.empty()) err(c, col, std::move(why));
                break;
            }
            case Op::Restore:
                if (saved.count(resolve_output(c.text).string())) break;
                if (const std::string why = input_problem(resolve_output(c.text)); !why.empty())
                    err(c, col_of(c, c.text), fmt::format("snapshot: {}", why));
                break;
            case Op::Save: saved.insert(resolve_output(c.text).string()); break;
            case Op::Monitor:
                if (std::string why = check_monitor(known); !why.empty()) err(c, c.where.col, std::move(why));
                break;
            case Op::Firmware:
                if (std::string why = check_firmware(c.text, known); !why.empty()) err(c, col_of(c, c.text), std::move(why));
                break;
            case Op::Record:
                if (!c.signals) {
                    recorded = true;
                    break;
                }
                for (const Value& v : c.pins)
                    if (std::string why = check_pin(v.text); !why.empty()) err(c, v.col, std::move(why));
                break;
            case Op::Plot:
                if (!recorded) err(c, c.where.col, "nothing recorded to plot: a 'record FILE.csv' must come first");
                break;
            case Op::RunUntil:
            case Op::Break:
            case Op::Delete: value_in(c, *c.address, 0, 0xFFFF, "address"); break;
            case Op::ExpectMem:
            case Op::SetMem:
                value_in(c, *c.address, 0, 0xFFFF, "address");
                for (const Value& v : c.values) value_in(c, v, -128, 255, "byte");
                break;
            case Op::ExpectWord:
                value_in(c, *c.address, 0, 0xFFFF, "address");
                value_in(c, c.values[0], -32768, 0xFFFF, "word");
                break;
            case Op::ExpectReg:
            case Op::SetReg:
                value_in(c, c.values[0], -(std::int64_t{1} << (c.reg->width - 1)), c.reg->mask(), "value");
                break;
            case Op::ExpectPort: value_in(c, c.values[0], 0, 0xFF, "value"); break;
            case Op::Press:
            case Op::Type:
            case Op::KeyDown:
            case Op::KeyUp:
                for (const KeyRef& k : c.keys)
                    if (std::string why = check_key(k); !why.empty()) err(c, col_of(c, k.name), std::move(why));
                break;
            case Op::ExpectSymbol:
                if (!known.count(c.name)) err(c, col_of(c, c.name), fmt::format("unknown symbol '{}'", c.name));
                value_in(c, c.values[0], -32768, 0xFFFF, "value");
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

// ---- the typed API: each call does its work; a script line reaches it through execute() -------

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
    if (!b.rom.empty())
        if (Outcome o = load_rom(b.rom); o.status != Status::Ok) return o;
    std::optional<std::uint16_t> start;  // where a board without the monitor starts
    for (const std::string& f : b.firmware) {
        if (Outcome o = load_firmware(f); o.status != Status::Ok) return o;
        if (const auto fw = firmware::find(f); fw && !fw->segments.empty()) start = fw->segments.front().address;
    }
    for (const Boot::Image& i : b.images) {
        if (Outcome o = load_image(i.path, i.address, b.defines); o.status != Status::Ok) return o;
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

Session::Outcome Session::load_monitor() {
    const Changed changed{debugger_};
    if (!options_.monitor_rom) return fail("this alp85 was built without the monitor ROM");
    const firmware::Firmware rom = options_.monitor_rom();
    machine_->load(rom.segments);
    debugger_.program().add_table(rom.symbols);
    placed(rom.segments);
    return {};
}

namespace {
// The board's ROM at 0000H (its monitor's), where --rom goes.
RomSpec rom_spec(const board::Board& b) {
    const board::MemoryRegion* r = board::rom_at_reset(b);
    return r ? RomSpec{r->base, r->size} : RomSpec{};
}
}  // namespace

std::string Session::check_rom(const std::filesystem::path& path) const {
    try {
        read_rom_image(resolve(path.string()), rom_spec(machine_->board()));
    } catch (const LoadError& e) {
        return e.what();
    }
    return {};
}

Session::Outcome Session::load_rom(const std::filesystem::path& path) {
    const Changed changed{debugger_};
    const RomSpec spec = rom_spec(machine_->board());
    try {
        const RomImage image = read_rom_image(resolve(path.string()), spec);
        const std::vector<ImageSegment> segments{{spec.base, image.bytes}};
        machine_->load(segments);
        if (image.assembly) debugger_.program().add_assembly(*image.assembly);
        placed(segments);
    } catch (const LoadError& e) {
        return fail(e.what());
    }
    return {};
}

Session::Outcome Session::load_firmware(const std::string& name) {
    const Changed changed{debugger_};
    const auto fw = firmware::find(name);
    if (!fw) return fail(fmt::format("no firmware '{}' in this alp85", name));
    if (fw->expansion_eprom) machine_->set_expansion_eprom(true);  // the EPROM it is in goes in with it
    machine_->load(fw->segments);
    debugger_.program().add_table(fw->symbols);
    placed(fw->segments);
    return {};
}

Session::Outcome Session::load_image(const std::filesystem::path& file, std::optional<std::uint16_t> address) {
    return load_image(file, address, {});
}

Session::Outcome Session::load_image(const std::filesystem::path& file, std::optional<std::uint16_t> address,
                                     const std::vector<std::pair<std::string, std::string>>& defines) {
    const Changed changed{debugger_};
    const auto path = resolve(file.string());
    try {
        LoadOptions lo;
        lo.address = address;
        lo.assembler.defines = defines;
        const auto cached = assembled_.find(path.string());
        LoadedImage img = cached != assembled_.end() && !lo.address && defines.empty() ? cached->second : read_image(path, lo);
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
        return fail(e.what());
    } catch (const std::out_of_range& e) {
        return fail(fmt::format("{}: {}", path.string(), e.what()));
    }
    return {};
}

Session::Outcome Session::reset() {
    const Changed changed{debugger_};
    machine_->reset();
    time_origin_ = machine_->now();
    return {};
}

Session::Outcome Session::save(const std::filesystem::path& file) {
    const auto path = resolve_output(file.string());
    if (const std::string why = output_problem(path, "save"); !why.empty()) return fail(why);
    try {
        machine_->save_snapshot(path);
    } catch (const snapshot::SnapshotError& x) {
        return fail(x.what());
    }
    written_.push_back(path.string());
    return {};
}

Session::Outcome Session::restore(const std::filesystem::path& file) {
    const Changed changed{debugger_, true};
    const auto path = resolve_output(file.string());
    try {
        machine_->load_snapshot(path);
    } catch (const snapshot::SnapshotError& x) {
        return fail(x.what());
    }
    add_input(path, "a snapshot the session restored");
    return {};
}

void Session::key(Button button, periph::Key k, bool down, std::optional<std::uint64_t> at) {
    Machine& m = *machine_;
    schedule_key(m, button, k, down, at.value_or(m.now()));
    if (button == Button::Reset && down) time_origin_ = m.now();
}

void Session::attach(periph::Part& part, IoDevice* io, std::uint8_t first, std::uint8_t last) {
    machine_->attach(part, io, first, last);
    debugger_.state_changed(true);  // a part came in: no earlier snapshot has it
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

Session::Outcome Session::key_now(Button button, periph::Key k, bool down) {
    key(button, k, down);
    machine_->run_for(0);  // deliver it now
    return ran({});
}

// A run in slices of pace_slice_ with the pace hook called between them (a window drawing the
// machine at real time); the same instructions run as in one piece.
debug::Stop Session::run_paced(std::uint64_t until, const std::function<bool()>& condition) {
    const debug::Origin o = origin();
    if (!pace_) return debugger_.run_until(until, condition, o);
    for (;;) {
        const std::uint64_t slice_end = std::min(until, machine_->now() + pace_slice_);
        const debug::Stop s = debugger_.run_until(slice_end, condition, o);
        if (s.reason != debug::StopReason::Deadline || machine_->now() >= until) return s;
        pace_(machine_->now());
    }
}

Session::Outcome Session::press(Button button, periph::Key k, std::uint64_t hold, std::uint64_t gap) {
    Machine& m = *machine_;
    if (button == Button::Reset) time_origin_ = m.now();
    run_paced(schedule_press(m, button, k, hold, gap), {});
    return ran({});
}

Session::Outcome Session::type(const std::vector<KeyRef>& keys, std::uint64_t hold, std::uint64_t gap) {
    for (const KeyRef& k : keys)
        if (Outcome o = press(k.kind, k.key, hold, gap); o.status != Status::Ok) return o;
    return {};
}

Session::Outcome Session::run(std::uint64_t tstates) {
    run_paced(machine_->now() + tstates, {});
    return ran({});
}

Session::Outcome Session::run_until(std::uint16_t target, std::uint64_t timeout) {
    if (debugger_.run_to(target, machine_->now() + timeout).reason != debug::StopReason::Target)
        return ran(fail(fmt::format("the PC did not reach {} within {}", hex(target, 4), format_time(timeout))));
    return ran({});
}

Session::Outcome Session::wait_display(const std::string& text, std::uint64_t timeout) {
    Machine& m = *machine_;
    const std::string want = rtrim(text);
    const debug::Stop stop = run_paced(m.now() + timeout, [&] { return rtrim(m.display_text()) == want; });
    if (stop.reason == debug::StopReason::Condition) return ran({});
    if (stop.reason == debug::StopReason::Breakpoint || stop.reason == debug::StopReason::Watchpoint)
        return ran(fail(fmt::format("stopped at {} {} before the display showed \"{}\"", debug::name(stop.reason),
                                    hex(m.cpu().regs().pc, 4), text)));
    if (stop.reason == debug::StopReason::Interrupted) return ran(fail("interrupted"));
    return ran(fail(fmt::format("the display did not show \"{}\" within {}", text, format_time(timeout))));
}

Session::Outcome Session::step(unsigned count) {
    for (unsigned i = 0; i < count; ++i) machine_->step();
    return {};
}

Session::Outcome Session::add_breakpoint(std::uint16_t address) {
    debugger_.add_breakpoint_at(address);
    return {};
}

Session::Outcome Session::delete_breakpoints(std::uint16_t address) {
    debugger_.remove_breakpoints_at(address);
    return {};
}

Session::Outcome Session::delete_all_breakpoints() {
    debugger_.remove_all();
    return {};
}

Session::Outcome Session::set_mem(std::uint16_t address, const std::vector<std::uint8_t>& bytes) {
    const Changed changed{debugger_};
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto addr = static_cast<std::uint16_t>(address + i);
        if (!machine_->poke(addr, bytes[i])) return fail(fmt::format("no memory at {}", hex(addr, 4)));
    }
    return {};
}

Session::Outcome Session::set_reg(const cpu::Register& reg, std::uint16_t value) {
    const Changed changed{debugger_};
    reg.write(machine_->cpu().regs(), static_cast<std::uint16_t>(value & reg.mask()));
    return {};
}

Session::Outcome Session::set_option(std::string_view name, bool fitted) {
    const Changed changed{debugger_};
    if (!machine_->set_option(name, fitted))
        return fail(fmt::format("the {} has no option '{}'", machine_->board().title, name));
    return {};
}

std::string Session::describe_board() const { return machine_->describe_board(); }

std::string Session::check_key(const KeyRef& key) const {
    if (key.kind != Button::Matrix) return {};  // RESET and VECT INTR: every board has them
    const board::Board& b = machine_->board();
    std::string names;
    for (const board::BoardKey& k : b.keys) {
        if (k.wire == board::KeyWire::Matrix && k.key == key.key) return {};
        names += (names.empty() ? "" : " ") + std::string(k.name);
    }
    return fmt::format("the {} has no key '{}' (its keys: {})", b.title, key.name, names);
}

Session::Outcome Session::print(const std::string& text) {
    output(text);
    return {};
}

Session::Outcome Session::print_display(bool as_text) {
    if (as_text) {
        output('"' + machine_->display_text() + '"');
    } else {
        std::string art;
        for (const std::string& line : machine_->display_art()) art += (art.empty() ? "" : "\n") + line;
        output(art);
    }
    return {};
}

// ---- expectations -------------------------------------------------------------------------------

Session::Outcome Session::expect_display(const std::string& text) {
    const std::string actual = machine_->display_text();
    if (rtrim(actual) != rtrim(text)) return fail_expect(fmt::format("\"{}\"", text), fmt::format("\"{}\"", actual));
    return {};
}

Session::Outcome Session::expect_mem(std::uint16_t address, const std::vector<std::uint8_t>& bytes) {
    std::string exp, act;
    bool same = true;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const std::uint8_t got = machine_->peek(static_cast<std::uint16_t>(address + i));
        same = same && bytes[i] == got;
        exp += (i ? " " : "") + hex(bytes[i], 2);
        act += (i ? " " : "") + hex(got, 2);
    }
    if (!same) return fail_expect(fmt::format("{} at {}", exp, hex(address, 4)), act);
    return {};
}

Session::Outcome Session::expect_word(std::uint16_t address, std::uint16_t value) {
    const Machine& m = *machine_;
    const std::uint16_t got = static_cast<std::uint16_t>(m.peek(address) | m.peek(static_cast<std::uint16_t>(address + 1)) << 8);
    if (got != value) return fail_expect(hex(value, 4), hex(got, 4));
    return {};
}

Session::Outcome Session::expect_reg(const cpu::Register& reg, std::uint16_t value) {
    const int digits = reg.width > 8 ? 4 : 2;
    const std::uint16_t want = static_cast<std::uint16_t>(value & reg.mask());
    const std::uint16_t got = reg.read(machine_->cpu().regs());
    if (want != got) return fail_expect(fmt::format("{} = {}", reg.name, hex(want, digits)), hex(got, digits));
    return {};
}

Session::Outcome Session::expect_flag(const cpu::Flag& flag, bool set, const std::string& name) {
    const bool got = (cpu::description().flag_register()->read(machine_->cpu().regs()) & flag.bit) != 0;
    if (set != got) return fail_expect(fmt::format("{} = {}", name, set ? 1 : 0), got ? "1" : "0");
    return {};
}

Session::Outcome Session::expect_port(char port, std::uint8_t value) {
    const auto& latch = machine_->rio().state().latch;
    const std::uint8_t got = latch[static_cast<std::size_t>(port - 'A')];
    if (got != value) return fail_expect(fmt::format("port {} latch = {}", port, hex(value, 2)), hex(got, 2));
    return {};
}

Session::Outcome Session::expect_symbol(const std::string& name, std::uint16_t value) {
    const auto actual = debugger_.program().value_of(name);
    if (!actual) return fail(fmt::format("unknown symbol '{}'", name));
    if (*actual != value) return fail_expect(hex(value, 4), hex(*actual, 4));
    return {};
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
// As a comparison reads before its value: "< ", "" for equality.
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
// expect time's operator: "=" for equality.
const char* compare_symbol(Compare op) {
    switch (op) {
        case Compare::Lt: return "<";
        case Compare::Le: return "<=";
        case Compare::Eq: return "=";
        case Compare::Ge: return ">=";
        case Compare::Gt: return ">";
    }
    return "";
}
periph::MachineTool::Axis tool_axis(std::uint8_t axis) { return static_cast<periph::MachineTool::Axis>(axis); }
char axis_name(std::uint8_t axis) { return "XYZ"[axis % 3]; }
// The table's position as whole steps: the nearest step (a settled physical rotor rests within a
// fraction of a step of it).
std::int64_t whole_steps(const periph::MachineTool& tool, periph::MachineTool::Axis a) {
    return std::llround(tool.table_steps(a));
}
}  // namespace

Session::Outcome Session::expect_time(Compare op, std::uint64_t tstates) {
    const std::uint64_t t = elapsed();
    if (!compare(t, op, tstates)) return fail_expect(fmt::format("time {} {}", compare_symbol(op), format_time(tstates)), format_time(t));
    return {};
}

Session::Outcome Session::expect_halted(bool halted) {
    if (machine_->cpu().halted() == halted) return {};
    return halted ? fail_expect("the CPU halted", "running") : fail_expect("the CPU running", "halted");
}

// ---- the machine tool ---------------------------------------------------------------------------

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

// The tool caught up with the machine's time before it is read or changed.
periph::MachineTool& Session::tool_now() {
    periph::MachineTool& tool = machine_->tool();
    tool.advance(machine_->now());
    return tool;
}

Session::Outcome Session::set_motor(periph::MachineTool::MotorModel model) {
    const Changed changed{debugger_};
    tool_now().set_model(model);
    return {};
}

Session::Outcome Session::set_feedback(periph::MachineTool::Feedback feedback) {
    const Changed changed{debugger_};
    tool_now().set_feedback(feedback);
    return {};
}

Session::Outcome Session::new_workpiece() {
    const Changed changed{debugger_};
    tool_now().set_up_workpiece(machine_->now());
    return {};
}

Session::Outcome Session::print_axes() {
    tool_now();
    output(axes_text());
    return {};
}

Session::Outcome Session::print_time() {
    tool_now();
    const std::uint64_t now = machine_->now();
    output(mark_ ? fmt::format("time: {} since the mark, {} since the last reset", format_time(now - *mark_),
                               format_time(elapsed()))
                 : fmt::format("time: {} since the last reset", format_time(elapsed())));
    return {};
}

Session::Outcome Session::mark() {
    tool_now();
    mark_ = machine_->now();
    return {};
}

Session::Outcome Session::expect_axis_steps(std::uint8_t axis, Compare op, std::int64_t steps) {
    const periph::MachineTool& tool = tool_now();
    const std::int64_t now = whole_steps(tool, tool_axis(axis));
    if (!compare(now, op, steps))
        return fail_expect(fmt::format("axis {} at {}{} steps", axis_name(axis), compare_text(op), steps),
                           fmt::format("{} steps ({:.3f})", now, tool.table_steps(tool_axis(axis))));
    return {};
}

Session::Outcome Session::expect_axis_mm(std::uint8_t axis, Compare op, double want, double within) {
    const double mm = tool_now().table_mm(tool_axis(axis));
    const bool ok = op == Compare::Eq ? std::abs(mm - want) <= within : compare(mm, op, want);
    if (!ok)
        return fail_expect(fmt::format("axis {} at {}{:.4f} mm{}", axis_name(axis), compare_text(op), want,
                                       op == Compare::Eq ? fmt::format(" within {} mm", within) : ""),
                           fmt::format("{:.4f} mm", mm));
    return {};
}

Session::Outcome Session::expect_count(std::uint8_t axis, Compare op, std::int64_t count) {
    const std::int64_t v = tool_now().transducer_count(tool_axis(axis));
    if (!compare(v, op, count))
        return fail_expect(fmt::format("count {} {}{}", axis_name(axis), compare_text(op), count), std::to_string(v));
    return {};
}

Session::Outcome Session::expect_lost(std::uint8_t axis, Compare op, std::int64_t lost) {
    const std::int64_t v = tool_now().lost_steps(tool_axis(axis));
    if (!compare(v, op, lost))
        return fail_expect(fmt::format("lost steps {} {}{}", axis_name(axis), compare_text(op), lost), std::to_string(v));
    return {};
}

Session::Outcome Session::run_until_axis(std::uint8_t axis, Compare op, std::int64_t steps, std::uint64_t timeout) {
    const periph::MachineTool& tool = tool_now();
    const auto a = tool_axis(axis);
    const debug::Stop stop = run_paced(machine_->now() + timeout, [&] { return compare(whole_steps(tool, a), op, steps); });
    if (stop.reason == debug::StopReason::Condition) return ran({});
    if (stop.reason == debug::StopReason::Breakpoint)
        return ran(fail(fmt::format("stopped at breakpoint {} before axis {} reached {}{} steps", hex(stop.pc, 4),
                                    axis_name(axis), compare_text(op), steps)));
    return ran(fail(fmt::format("axis {} did not reach {}{} steps within {} (it is at {} steps)", axis_name(axis),
                                compare_text(op), steps, format_time(timeout), whole_steps(tool, a))));
}

Session::Outcome Session::record(const std::filesystem::path& csv, std::uint64_t period) {
    tool_now();
    if (recorder_.recording()) {
        if (Outcome o = write_recording(); o.status != Status::Ok) return o;
    }
    const auto path = resolve_output(csv.string());
    if (const std::string why = output_problem(path, "record"); !why.empty()) return fail(why);
    record_path_ = path;
    record_line_ = line_ ? std::optional<Command>(*line_) : std::nullopt;
    recorder_.start(*machine_, period);
    return {};
}

Session::Outcome Session::record_signals(const std::filesystem::path& vcd, const std::vector<std::string>& pins,
                                         std::uint64_t period) {
    tool_now();
    if (signals_.recording()) {
        if (Outcome o = write_signals(); o.status != Status::Ok) return o;
    }
    const auto path = resolve_output(vcd.string());
    if (const std::string why = output_problem(path, "record"); !why.empty()) return fail(why);
    try {
        signals_.start(*machine_, path, pins, period);
    } catch (const std::exception& x) {
        return fail(x.what());
    }
    signals_line_ = line_ ? std::optional<Command>(*line_) : std::nullopt;
    return {};
}

Session::Outcome Session::trace_signals(const std::vector<std::string>& pins, std::uint64_t span) {
    try {
        pane_trace_.start(*machine_, pins, span);
    } catch (const std::exception& x) {
        return {Status::Failed, x.what()};
    }
    return {};
}

Session::Outcome Session::record_stop() {
    tool_now();
    // Ends every recording running: the tool's CSV and the pins' VCD.
    if (!recorder_.recording() && !signals_.recording())
        return fail("no recording to stop (record FILE.csv or record signals FILE.vcd starts one)");
    return stop_recordings();
}

Session::Outcome Session::write_recording() {
    const Command* line = record_line_ ? &*record_line_ : nullptr;
    recorder_.stop();
    if (const std::string why = output_problem(record_path_, "record"); !why.empty()) return fail_at(line, why);
    try {
        AtomicOutput file(record_path_);
        recorder_.write_csv(file.stream());
        file.commit();
    } catch (const std::exception& x) {
        return fail_at(line, x.what());
    }
    if (recorder_.full())
        return fail_at(line, fmt::format("the recording reached its cap of {} samples: '{}' holds the first {} (record with a "
                                         "longer period, e.g. every 1ms)",
                                         debug::ToolRecorder::kMaxSamples, record_path_.string(), debug::ToolRecorder::kMaxSamples));
    return {};
}

Session::Outcome Session::write_signals() {
    const Command* line = signals_line_ ? &*signals_line_ : nullptr;
    if (const std::string why = output_problem(signals_.path(), "record"); !why.empty()) {
        signals_.abandon();
        return fail_at(line, why);
    }
    try {
        signals_.stop();
    } catch (const std::exception& x) {
        return fail_at(line, x.what());
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

// The recorded samples, the present moment included (the last sample may be up to one period old).
Session::Outcome Session::plot_time(const std::filesystem::path& out) {
    tool_now();
    const auto& samples = recorder_.samples();
    if (samples.size() < 2) return fail("nothing recorded to plot (record FILE.csv first, then run)");
    const auto path = resolve_output(out.string());
    if (const std::string why = output_problem(path, "plot"); !why.empty()) return fail(why);
    std::vector<plot::Series> series;
    for (int a = 0; a < 3; ++a) {
        plot::Series axis{std::string(1, "XYZ"[a]), {}};
        for (const auto& smp : samples)
            axis.points.push_back({static_cast<double>(smp.t - samples.front().t) / board::kCpuHz,
                                   smp.axes[static_cast<std::size_t>(a)].mm});
        series.push_back(std::move(axis));
    }
    try {
        plot::write_time_series(path.string(), "Table position against time", series, "position (mm)");
    } catch (const plot::PlotError& x) {
        return fail(x.what());
    }
    return {};
}

Session::Outcome Session::plot_toolpath(const std::filesystem::path& out, const std::optional<std::array<double, 4>>& ideal) {
    tool_now();
    const auto& samples = recorder_.samples();
    if (samples.size() < 2) return fail("nothing recorded to plot (record FILE.csv first, then run)");
    const auto path = resolve_output(out.string());
    if (const std::string why = output_problem(path, "plot"); !why.empty()) return fail(why);
    plot::Series table{"table (X, Y)", {}};
    for (const auto& smp : samples) table.points.push_back({smp.axes[0].mm, smp.axes[1].mm});
    const plot::Point a = ideal ? plot::Point{(*ideal)[0], (*ideal)[1]} : table.points.front();
    const plot::Point b = ideal ? plot::Point{(*ideal)[2], (*ideal)[3]} : table.points.back();
    try {
        plot::write_toolpath(path.string(), "Toolpath", {table}, std::make_pair(a, b));
    } catch (const plot::PlotError& x) {
        return fail(x.what());
    }
    return {};
}

// ---- the command language: a parsed line to its typed call --------------------------------------

Session::Outcome Session::connect_serial(const periph::UartFormat& format, std::uint64_t gap) {
    if (serial_) return {Status::Failed, fmt::format("a serial terminal is already connected ({})", serial_->format().text())};
    serial_ = std::make_unique<periph::SerialTerminal>(board::kCpuHz, format, gap);
    machine_->connect_serial(*serial_);
    debugger_.state_changed(true);  // a part came in: no earlier snapshot has it
    return {};
}

void Session::serial_type(std::string_view text) {
    Machine& m = *machine_;
    for (const char ch : text) m.serial_at(static_cast<std::uint8_t>(ch), m.now());
}

Session::Outcome Session::execute(const Command& c) {
    struct Running {  // the line failures name, for the length of this call
        const Command*& line;
        const Command* outer;
        ~Running() { line = outer; }
    } running{line_, line_};
    line_ = &c;
    if (options_.verbose) output(fmt::format("[{}] {}:{}: {}", format_time(elapsed()), c.where.file, c.where.line, rtrim(c.line)));
    return run_command(c);
}

Session::Outcome Session::run_command(const Command& c) {
    std::string e;
    // The command's values, resolved against the symbols of now (nullopt: `e` says why).
    auto address = [&]() -> std::optional<std::uint16_t> {
        const auto a = resolve(*c.address, e);
        return a ? std::optional<std::uint16_t>(static_cast<std::uint16_t>(*a)) : std::nullopt;
    };
    auto bytes = [&]() -> std::optional<std::vector<std::uint8_t>> {
        std::vector<std::uint8_t> out;
        for (const Value& v : c.values) {
            const auto b = resolve(v, e);
            if (!b) return std::nullopt;
            out.push_back(static_cast<std::uint8_t>(*b));
        }
        return out;
    };
    // `call` with the command's first value, or why it has none.
    auto with_value = [&](const auto& call) -> Outcome {
        const auto v = resolve(c.values[0], e);
        return v ? call(*v) : fail(e);
    };
    // `call` with the command's address and bytes, or why they have none.
    auto with_bytes = [&](const auto& call) -> Outcome {
        const auto a = address();
        const auto b = a ? bytes() : std::nullopt;
        return b ? call(*a, *b) : fail(e);
    };
    using Bytes = std::vector<std::uint8_t>;
    switch (c.op) {
        case Op::Load: {
            std::optional<std::uint16_t> at;
            if (c.address && !(at = address())) return fail(e);
            return load_image(c.text, at);
        }
        case Op::Monitor: return load_monitor();
        case Op::Firmware: return load_firmware(c.text);
        case Op::Reset: return reset();
        case Op::Press: return press(c.keys[0].kind, c.keys[0].key, c.time, c.gap);
        case Op::Type: return type(c.keys, c.time, c.gap);
        case Op::KeyDown:
        case Op::KeyUp: return key_now(c.keys[0].kind, c.keys[0].key, c.op == Op::KeyDown);
        case Op::Run: return run(c.time);
        case Op::RunUntil: {
            const auto a = address();
            return a ? run_until(*a, c.time) : fail(e);
        }
        case Op::WaitDisplay: return wait_display(c.text, c.time);
        case Op::Step: return step(c.count);
        case Op::Break:
        case Op::Delete: {
            const auto a = address();
            if (!a) return fail(e);
            return c.op == Op::Break ? add_breakpoint(*a) : delete_breakpoints(*a);
        }
        case Op::DeleteAll: return delete_all_breakpoints();
        case Op::SetMem: return with_bytes([&](std::uint16_t a, const Bytes& b) { return set_mem(a, b); });
        case Op::SetReg: return with_value([&](std::int64_t v) { return set_reg(*c.reg, static_cast<std::uint16_t>(v)); });
        case Op::Save: return save(c.text);
        case Op::Restore: return restore(c.text);
        case Op::Option: return set_option(c.name, c.real == 1);
        case Op::PrintBoard: {
            std::string text = describe_board();
            if (!text.empty() && text.back() == '\n') text.pop_back();
            return print(text);
        }
        case Op::Board:
            if (c.name == machine_->board().name) return {};
            return fail(fmt::format("board {} comes too late: the machine is already a {} (board must be the script's first command)",
                                    c.name, machine_->board().title));
        case Op::Motor:
            return set_motor(c.real == 0 ? periph::MachineTool::MotorModel::Ideal : periph::MachineTool::MotorModel::Physical);
        case Op::Feedback:
            return set_feedback(c.real == 0 ? periph::MachineTool::Feedback::Scale : periph::MachineTool::Feedback::Commanded);
        case Op::NewWorkpiece: return new_workpiece();
        case Op::PrintAxes: return print_axes();
        case Op::PrintTime: return print_time();
        case Op::Mark: return mark();
        case Op::ExpectAxis:
            return c.in_mm ? expect_axis_mm(c.axis, c.compare, c.real, c.within) : expect_axis_steps(c.axis, c.compare, c.integer);
        case Op::ExpectCount: return expect_count(c.axis, c.compare, c.integer);
        case Op::ExpectLost: return expect_lost(c.axis, c.compare, c.integer);
        case Op::RunUntilAxis: return run_until_axis(c.axis, c.compare, c.integer, c.time);
        case Op::Record: {
            if (!c.signals) return record(c.text, c.period);
            std::vector<std::string> pins;
            for (const Value& v : c.pins) pins.push_back(v.text);
            return record_signals(c.text, pins, c.period);
        }
        case Op::RecordStop: return record_stop();
        case Op::Plot: return c.name == "TOOLPATH" ? plot_toolpath(c.text, c.ideal_line) : plot_time(c.text);
        case Op::PrintDisplay: return print_display(c.text == "text");
        case Op::Print: return print(c.text);
        case Op::ExpectDisplay: return expect_display(c.text);
        case Op::ExpectMem: return with_bytes([&](std::uint16_t a, const Bytes& b) { return expect_mem(a, b); });
        case Op::ExpectWord: {
            const auto a = address();
            const auto v = resolve(c.values[0], e);
            return a && v ? expect_word(*a, static_cast<std::uint16_t>(*v)) : fail(e);
        }
        case Op::ExpectReg: return with_value([&](std::int64_t v) { return expect_reg(*c.reg, static_cast<std::uint16_t>(v)); });
        case Op::ExpectFlag: {  // the flag of the parsed bit, named as written
            const auto& flags = cpu::description().flags;
            const auto f = std::find_if(flags.begin(), flags.end(), [&](const cpu::Flag& x) { return x.bit == c.flag; });
            if (f == flags.end()) return fail(fmt::format("no flag of bit {:02X}H", c.flag));
            return expect_flag(*f, c.values[0].number != 0, c.flag_name);
        }
        case Op::ExpectPort: return with_value([&](std::int64_t v) { return expect_port(c.port, static_cast<std::uint8_t>(v)); });
        case Op::ExpectSymbol: return with_value([&](std::int64_t v) { return expect_symbol(c.name, static_cast<std::uint16_t>(v)); });
        case Op::ExpectTime: return expect_time(c.compare, c.time);
        case Op::ExpectHalted: return expect_halted(true);
        case Op::ExpectRunning: return expect_halted(false);
    }
    return {};
}

}  // namespace alp85::script
