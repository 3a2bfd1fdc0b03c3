#include "emu/debug/signal_record.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "emu/util/text.h"

namespace alp85::debug {

namespace {

constexpr std::uint64_t kNever = periph::Part::kNever;

// T-state -> ns from power-on, rounded to the nearest (no overflow for any T-state count).
std::uint64_t ns_of(std::uint64_t t) {
    constexpr std::uint64_t hz = board::kCpuHz;
    return t / hz * 1'000'000'000ull + (t % hz * 1'000'000'000ull + hz / 2) / hz;
}

// VCD identifiers: printable characters '!'..'~', shortest first.
std::string vcd_id(std::size_t n) {
    std::string id;
    do {
        id += static_cast<char>('!' + n % 94);
        n /= 94;
    } while (n-- > 0);
    return id;
}

bool selects(const std::string& word, const std::string& scope, const std::string& name) {
    const std::string w = to_upper(word), s = to_upper(scope), n = to_upper(name);
    return w == n || w == s || w == s + "." + n;
}

}  // namespace

namespace {
template <class Fn>
void for_each_source(const Machine& m, Fn fn) {
    fn(static_cast<periph::Part*>(nullptr));
    for (periph::Part* p : m.parts()) fn(p);
}
void read_pins(const Machine& m, periph::Part* part, periph::Pins& pins, std::uint64_t t) {
    if (part)
        part->pins(pins, t);
    else
        m.cpu_pins(pins);
}
}  // namespace

std::vector<SignalRecorder::PinName> SignalRecorder::pin_names(const Machine& machine) {
    std::vector<PinName> out;
    for_each_source(machine, [&](periph::Part* part) {
        periph::Pins pins;
        read_pins(machine, part, pins, machine.now());
        for (const auto& p : pins.list()) out.push_back({p.scope, p.name, p.kind == periph::Pins::Kind::Real, p.exact});
    });
    return out;
}

std::string SignalRecorder::check_selection(const Machine& machine, const std::vector<std::string>& selection) {
    const std::vector<PinName> all = pin_names(machine);
    for (const std::string& w : selection) {
        if (std::none_of(all.begin(), all.end(), [&](const PinName& p) { return selects(w, p.scope, p.name); })) {
            std::vector<std::string> seen;
            std::string scopes;
            for (const PinName& p : all) {
                if (std::find(seen.begin(), seen.end(), p.scope) != seen.end()) continue;
                seen.push_back(p.scope);
                scopes += (scopes.empty() ? "" : ", ") + p.scope;
            }
            return fmt::format("no pin '{}' on the board (a pin such as PA0, 8155.PA0 or X.PULSE, or a whole part: {}; "
                               "docs/signals.md lists them)",
                               w, scopes);
        }
    }
    return {};
}

SignalRecorder::~SignalRecorder() { detach(); }

void SignalRecorder::detach() {
    if (machine_ && machine_->probe() == this) machine_->set_probe(nullptr);
    machine_ = nullptr;
}

void SignalRecorder::start(Machine& machine, const std::filesystem::path& path, const std::vector<std::string>& selection,
                           std::uint64_t period) {
    if (recording()) throw std::runtime_error("a signal recording is already running");
    if (const std::string why = check_selection(machine, selection); !why.empty()) throw std::runtime_error(why);
    if (machine.probe()) throw std::runtime_error("another logic analyzer is on the board");
    sources_.clear();
    period_ = std::max<std::uint64_t>(period, 1);
    sampled_ = false;
    changes_ = 0;
    const std::uint64_t t = machine.now();
    // Parts catch up first: what is recorded at `t` is what the board shows at t.
    for (periph::Part* p : machine.parts()) p->advance(std::max(t, p->now()));

    std::size_t next_id = 0;
    for_each_source(machine, [&](periph::Part* part) {
        Source s;
        s.part = part;
        read_pins(machine, part, s.pins, t);
        s.pins.set_naming(false);
        for (std::size_t i = 0; i < s.pins.size(); ++i) {
            const auto& p = s.pins.list()[i];
            const bool chosen = selection.empty() || std::any_of(selection.begin(), selection.end(), [&](const std::string& w) {
                                    return selects(w, p.scope, p.name);
                                });
            if (!chosen) continue;
            s.selected.push_back(i);
            s.ids.push_back(vcd_id(next_id++));
            s.level.push_back(s.pins.levels()[i]);
            s.real.push_back(s.pins.reals()[i]);
            if (!p.exact) sampled_ = true;
            if (p.exact && part) s.self_timed = true;
        }
        if (!s.selected.empty()) sources_.push_back(std::move(s));
    });

    auto file = std::make_unique<AtomicOutput>(path);
    std::ostream& o = file->stream();
    o << "$version ALP85 (alp85 record signals) $end\n";
    o << "$comment\n"
      << fmt::format("  ALP 85 pins. The 8085's clock is {} Hz: one T-state is 1e9/{} ns = {:.6f} ns.\n", board::kCpuHz,
                     board::kCpuHz, 1e9 / board::kCpuHz)
      << fmt::format("  A change at T-state T (counted from power-on) is at #round(T * 1e9 / {}); T = round(# * {} / 1e9)\n",
                     board::kCpuHz, board::kCpuHz)
      << "  gives it back exactly (a T-state is 325 ns, far more than the rounding).\n"
      << fmt::format("  Recording started at T-state {}.\n", t)
      << "  Exact to the T-state: the 8155's ports and TIMER OUT, the 8279, the 8085's interrupt lines, SOD and\n"
      << "  SID (a port write at the first T-state of the OUT's I/O write cycle, SOD at the SIM's first T-state,\n"
      << "  SID at a serial terminal's bit edges), the sequencers' inputs and phase drives.\n"
      << fmt::format("  Sampled every {} T-states: the 8085's HLT, the transducers' COUNT and CDIR, the\n", period_)
      << "  winding currents (A) and rotor angles (degrees).\n"
      << "$end\n";
    o << "$timescale 1 ns $end\n";
    o << "$scope module alp85 $end\n";
    std::string open_scope;
    for (const Source& s : sources_) {
        for (std::size_t k = 0; k < s.selected.size(); ++k) {
            const auto& p = s.pins.list()[s.selected[k]];
            if (p.scope != open_scope) {
                if (!open_scope.empty()) o << "$upscope $end\n";
                // A scope named by a number ("8155") reads as one in GTKWave; the part's name is kept.
                o << "$scope module " << (p.scope[0] >= '0' && p.scope[0] <= '9' ? "i" : "") << p.scope << " $end\n";
                open_scope = p.scope;
            }
            o << "$var " << (p.kind == periph::Pins::Kind::Real ? "real 64 " : "wire 1 ") << s.ids[k] << ' ' << p.name
              << " $end\n";
        }
    }
    if (!open_scope.empty()) o << "$upscope $end\n";
    o << "$upscope $end\n$enddefinitions $end\n";
    o << '#' << ns_of(t) << "\n$dumpvars\n";
    for (const Source& s : sources_)
        for (std::size_t k = 0; k < s.selected.size(); ++k) {
            if (s.pins.list()[s.selected[k]].kind == periph::Pins::Kind::Real)
                o << fmt::format("r{:.9g} {}\n", s.real[k], s.ids[k]);
            else
                o << s.level[k] << s.ids[k] << '\n';
        }
    o << "$end\n";

    file_ = std::move(file);
    path_ = path;
    machine_ = &machine;
    start_t_ = last_t_ = written_t_ = t;
    next_sample_ = (t / period_ + 1) * period_;
    machine.set_probe(this);
}

void SignalRecorder::write_time(std::uint64_t t) {
    if (t == written_t_) return;
    written_t_ = t;
    file_->stream() << '#' << ns_of(t) << '\n';
}

void SignalRecorder::read(Source& s, std::uint64_t t) {
    s.pins.set_naming(false);
    read_pins(*machine_, s.part, s.pins, t);
    std::ostream& o = file_->stream();
    for (std::size_t k = 0; k < s.selected.size(); ++k) {
        const std::size_t i = s.selected[k];
        if (s.pins.list()[i].kind == periph::Pins::Kind::Real) {
            const double v = s.pins.reals()[i];
            if (v == s.real[k]) continue;
            s.real[k] = v;
            write_time(t);
            o << fmt::format("r{:.9g} {}\n", v, s.ids[k]);
        } else {
            const char v = s.pins.levels()[i];
            if (v == s.level[k]) continue;
            s.level[k] = v;
            write_time(t);
            o << v << s.ids[k] << '\n';
        }
        ++changes_;
    }
}

void SignalRecorder::look(std::uint64_t t) {
    if (!machine_) return;
    // The file never goes back in time: a debugger that took the machine back re-runs what was
    // recorded the first time (and a new timeline from there shows from where the first ended).
    if (t < last_t_) return;
    last_t_ = t;
    for (Source& s : sources_) read(s, t);
    if (sampled_ && t >= next_sample_) next_sample_ = (t / period_ + 1) * period_;
}

std::uint64_t SignalRecorder::next() const {
    std::uint64_t next = sampled_ ? next_sample_ : kNever;
    for (const Source& s : sources_)
        if (s.self_timed) next = std::min(next, std::max(s.part->next_pin_change(last_t_), last_t_ + 1));
    return next;
}

void SignalRecorder::abandon() {
    detach();
    file_.reset();
}

void SignalRecorder::stop() {
    if (!machine_) return;
    const std::uint64_t t = std::max(machine_->now(), last_t_);
    look(t);
    std::unique_ptr<AtomicOutput> file = std::move(file_);
    detach();
    // The last time written, so that a viewer shows the levels up to the end of the recording.
    if (t != written_t_) file->stream() << '#' << ns_of(t) << '\n';
    file->stream() << fmt::format("$comment recording ended at T-state {} ({} T-states recorded) $end\n", t, t - start_t_);
    file->commit();
}

}  // namespace alp85::debug
