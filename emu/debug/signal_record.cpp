#include "emu/debug/signal_record.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace alp85::debug {

namespace {

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

}  // namespace

SignalRecorder::~SignalRecorder() { detach(); }

void SignalRecorder::detach() {
    if (machine_) machine_->remove_probe(this);
    machine_ = nullptr;
    tap_.detach();
}

void SignalRecorder::start(Machine& machine, const std::filesystem::path& path, const std::vector<std::string>& selection,
                           std::uint64_t period) {
    if (recording()) throw std::runtime_error("a signal recording is already running");
    PinTap tap;
    tap.attach(machine, selection, period);
    changes_ = 0;
    const std::uint64_t t = machine.now();
    std::vector<std::string> ids;
    for (std::size_t k = 0; k < tap.channels().size(); ++k) ids.push_back(vcd_id(k));

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
      << fmt::format("  Sampled every {} T-states: the 8085's HLT, the transducers' COUNT and CDIR, the\n", tap.period())
      << "  winding currents (A) and rotor angles (degrees).\n"
      << "$end\n";
    o << "$timescale 1 ns $end\n";
    o << "$scope module alp85 $end\n";
    std::string open_scope;
    for (std::size_t k = 0; k < tap.channels().size(); ++k) {
        const PinName& p = tap.channels()[k].pin;
        if (p.scope != open_scope) {
            if (!open_scope.empty()) o << "$upscope $end\n";
            // A scope named by a number ("8155") reads as one in GTKWave; the part's name is kept.
            o << "$scope module " << (p.scope[0] >= '0' && p.scope[0] <= '9' ? "i" : "") << p.scope << " $end\n";
            open_scope = p.scope;
        }
        o << "$var " << (p.real ? "real 64 " : "wire 1 ") << ids[k] << ' ' << p.name << " $end\n";
    }
    if (!open_scope.empty()) o << "$upscope $end\n";
    o << "$upscope $end\n$enddefinitions $end\n";
    o << '#' << ns_of(t) << "\n$dumpvars\n";
    for (std::size_t k = 0; k < tap.channels().size(); ++k) {
        const PinTap::Channel& c = tap.channels()[k];
        if (c.pin.real)
            o << fmt::format("r{:.9g} {}\n", c.value, ids[k]);
        else
            o << c.level << ids[k] << '\n';
    }
    o << "$end\n";

    file_ = std::move(file);
    path_ = path;
    tap_ = std::move(tap);
    ids_ = std::move(ids);
    machine_ = &machine;
    start_t_ = last_t_ = written_t_ = t;
    machine.add_probe(this);
}

void SignalRecorder::write_time(std::uint64_t t) {
    if (t == written_t_) return;
    written_t_ = t;
    file_->stream() << '#' << ns_of(t) << '\n';
}

void SignalRecorder::look(std::uint64_t t) {
    if (!machine_) return;
    // The file never goes back in time: a debugger that took the machine back re-runs what was
    // recorded the first time (and a new timeline from there shows from where the first ended).
    if (t < last_t_) return;
    last_t_ = t;
    std::ostream& o = file_->stream();
    for (const std::size_t k : tap_.read(t)) {
        const PinTap::Channel& c = tap_.channels()[k];
        write_time(t);
        if (c.pin.real)
            o << fmt::format("r{:.9g} {}\n", c.value, ids_[k]);
        else
            o << c.level << ids_[k] << '\n';
        ++changes_;
    }
}

std::uint64_t SignalRecorder::next() const { return tap_.next(last_t_); }

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
