#include "emu/board/machine.h"

#include <algorithm>
#include <bitset>
#include <stdexcept>

#include <fmt/format.h>

#include "emu/board/snapshot_file.h"
#include "peripherals/seven_segment.h"

namespace alp85 {

using periph::I8155;

// The debugger's view of a run (its RunObserver), run_to's target and a trace, on the CPU's
// debug path; installed on the CPU only while one of them is set, so a plain run pays nothing.
class Machine::Hooks final : public DebugHooks {
public:
    // A run starts by executing the instruction at the PC (run_to's target is ahead).
    bool skip_armed = false;
    std::uint16_t skip_pc = 0;
    bool stopped = false;
    RunEnd reason = RunEnd::Deadline;
    std::function<void(const I8085&)> trace;
    bool run_to = false;  // run_to(): only run_to_pc stops the run
    std::uint16_t run_to_pc = 0;
    RunObserver* observer = nullptr;
    bool observer_accesses = false;

    bool before_instruction(I8085& cpu) override {
        if (observer && !run_to && observer->before_instruction(cpu)) {
            stopped = true;
            reason = RunEnd::Observer;
            return false;
        }
        const std::uint16_t pc = cpu.regs().pc;
        if (run_to && pc == run_to_pc && !(skip_armed && pc == skip_pc)) {
            skip_armed = false;
            stopped = true;
            reason = RunEnd::Target;
            return false;
        }
        skip_armed = false;
        if (trace) trace(cpu);
        return true;
    }
    void on_read(I8085& cpu, std::uint16_t addr, std::uint8_t v) override {
        if (observer_accesses && observer->on_read(addr, v)) stop_observer(cpu);
    }
    void on_write(I8085& cpu, std::uint16_t addr, std::uint8_t v) override {
        if (observer_accesses && observer->on_write(addr, v)) stop_observer(cpu);
    }
    void on_io(I8085& cpu, std::uint8_t port, std::uint8_t value, bool is_out) override {
        if (observer_accesses && observer->on_io(port, value, is_out)) stop_observer(cpu);
    }

private:
    void stop_observer(I8085& cpu) {
        stopped = true;
        reason = RunEnd::Observer;
        cpu.request_stop();
    }
};

// A chip on the I/O bus as board::kIoMap declares it: the chip sees the register offset, and a
// write may move the chip's next event, so the batch ends there and the scheduler looks again.
// `after_write` lets the board follow pins a write may change (the 8155's port A drives the tool).
template <class Chip>
class ChipPorts final : public IoDevice {
public:
    ChipPorts(Chip& chip, I8085& cpu, const board::IoRegion& region, std::function<void(std::uint64_t)> after_write = {})
        : chip_(chip), cpu_(cpu), region_(region), after_write_(std::move(after_write)) {}
    std::uint8_t in(std::uint8_t port, std::uint64_t t) override { return chip_.read(region_.offset(port), t); }
    void out(std::uint8_t port, std::uint8_t value, std::uint64_t t) override {
        chip_.write(region_.offset(port), value, t);
        if (after_write_) after_write_(t);
        cpu_.stop_at(t);
    }

private:
    Chip& chip_;
    I8085& cpu_;
    const board::IoRegion& region_;
    std::function<void(std::uint64_t)> after_write_;
};

Machine::Machine() : Machine(Options{}) {}

Machine::Machine(Options options)
    : options_(options),
      cpu_(bus_, options.cpu),
      tool_(board::kCpuHz),
      hooks_(std::make_unique<Hooks>()) {
    // Erased EPROMs read FFH (every cell charged); RAM powers up as zeros here (the real parts
    // are unpredictable, and a deterministic machine needs some fixed value).
    monitor_.fill(0xFF);
    user_.fill(0xFF);
    expansion_.fill(0xFF);
    map_.assign(board::kMemoryMap.begin(), board::kMemoryMap.end());
    wire();
    set_expansion_eprom(options.expansion_eprom);
    reset();
}

Machine::~Machine() = default;

void Machine::wire() {
    // Memory, from the one map.
    for (const auto& r : board::kMemoryMap) {
        std::span<std::uint8_t> s = storage(r.id);
        if (r.kind == board::MemoryKind::Rom)
            bus_.map_rom(r.base, r.size, s.data());
        else
            bus_.map_ram(r.base, r.size, s.data());
    }
    // The parts, in the order they are advanced, reset and saved.
    parts_ = {&rio_, &kdc_, &keypad_};
    if (options_.machine_tool) parts_.push_back(&tool_);
    tool_.set_model(options_.motor);
    for (const auto& r : board::kIoMap) {
        switch (r.device) {
            case board::Device::Kdc8279: chip_ports_.push_back(std::make_unique<ChipPorts<periph::I8279>>(kdc_, cpu_, r)); break;
            case board::Device::Rio8155:
                chip_ports_.push_back(
                    std::make_unique<ChipPorts<periph::I8155>>(rio_, cpu_, r, [this](std::uint64_t t) {
                        drive_tool(t);
                        probe_look(t);
                    }));
                break;
        }
        bus_.map_io(r.first, r.last, *chip_ports_.back());
    }
    // Interrupt wiring, from board::kInterruptWiring (the keys are applied in apply()).
    for (const board::Wire& w : board::kInterruptWiring) {
        const board::CpuPin pin = w.pin;
        switch (w.source) {
            case board::Source::Irq8279: kdc_.on_irq([this, pin](bool level, std::uint64_t t) { drive(pin, level, t); }); break;
            case board::Source::TimerOut8155:
                rio_.on_timer_out([this, pin](bool level, std::uint64_t t) { drive(pin, level, t); });
                break;
            case board::Source::VectIntrKey:
            case board::Source::ResetKey: break;
        }
    }
    // SHIFT and CNTL/STB are grounded on the ALP 85 (docs/peripherals.md): key codes carry 0 there.
    kdc_.set_shift(false, 0);
    kdc_.set_cntl_stb(false, 0);
    kdc_.set_return_lines_source([this](std::uint8_t sl) { return keypad_.return_lines(sl); });
    rio_.set_input_callback([this](I8155::Port port, std::uint64_t now) -> std::uint8_t {
        if (port == I8155::Port::B) return sense_tool(now);
        return port == I8155::Port::C ? board::kUndrivenPortC : board::kUndrivenPortAB;
    });
}

namespace {
constexpr I8155::Port port_of(std::uint8_t port) {
    return board::io_region(board::Device::Rio8155).offset(port) == I8155::kPortA ? I8155::Port::A : I8155::Port::B;
}
static_assert(port_of(board::kToolOutPort) == I8155::Port::A && port_of(board::kToolInPort) == I8155::Port::B,
              "the machine tool sits on the 8155's ports A (out) and B (in)");
}  // namespace

namespace {
// The wiring table is in the order of the tool's axes: row a is axis a.
constexpr bool wiring_in_axis_order() {
    for (std::size_t a = 0; a < board::kToolWiring.size(); ++a)
        if (static_cast<std::size_t>(board::kToolWiring[a].axis) != a) return false;
    return true;
}
static_assert(wiring_in_axis_order(), "board::kToolWiring lists X, Y, Z in order");

constexpr std::uint8_t bit_mask(const board::ToolBit& b) { return static_cast<std::uint8_t>(1u << b.bit); }
}  // namespace

void Machine::drive_tool(std::uint64_t t) {
    if (!options_.machine_tool) return;
    // Pins programmed as inputs are not driven: the sequencers' inputs are pulled high.
    const std::uint8_t mask = rio_.port_output_mask(I8155::Port::A);
    const std::uint8_t pins = static_cast<std::uint8_t>((rio_.port_output(I8155::Port::A) & mask) | ~mask);
    // Only axes whose inputs change are told (most 8155 writes leave them alone); what each
    // sequencer last saw is its own state, so snapshots need nothing here.
    const auto& axes = tool_.state().axes;
    for (std::size_t a = 0; a < 3; ++a) {
        const board::AxisWiring& w = board::kToolWiring[a];
        const bool pulse = pins & bit_mask(w.pulse), direction = pins & bit_mask(w.direction);
        if (pulse != axes[a].sequencer.pulse || direction != axes[a].sequencer.direction)
            tool_.set_drive(static_cast<board::ToolAxis>(a), pulse, direction, t);
    }
}

std::uint8_t Machine::sense_tool(std::uint64_t t) {
    std::uint8_t pins = board::kUndrivenPortAB;  // bits the tool does not drive are pulled high
    if (!options_.machine_tool) return pins;
    for (const board::AxisWiring& w : board::kToolWiring) {
        const periph::MachineTool::Sense s = tool_.sense(w.axis, t);
        for (const auto& [b, level] : {std::pair{w.count, s.count}, {w.count_direction, s.direction}})
            pins = static_cast<std::uint8_t>(level ? pins | bit_mask(b) : pins & ~bit_mask(b));
    }
    return pins;
}

void Machine::set_sampler(std::uint64_t period, std::function<void(std::uint64_t)> fn) {
    sample_period_ = fn ? period : 0;
    sampler_ = std::move(fn);
    next_sample_ = sample_period_ ? (now() / sample_period_ + 1) * sample_period_ : periph::Part::kNever;
}

void Machine::sample(std::uint64_t t) {
    while (next_sample_ <= t) {
        const std::uint64_t at = next_sample_;
        next_sample_ += sample_period_;
        for (periph::Part* p : parts_) p->advance(std::max(at, p->now()));
        if (!sampler_paused_) sampler_(at);
    }
}

void Machine::drive(board::CpuPin pin, bool level, std::uint64_t t) {
    switch (pin) {
        case board::CpuPin::Rst55: cpu_.set_rst55(level); break;
        case board::CpuPin::Trap: cpu_.set_trap(level); break;
        case board::CpuPin::Rst75: cpu_.set_rst75(level); break;
        case board::CpuPin::ResetIn:
            if (level) reset();
            break;
    }
    probe_look(t);
}

void Machine::add_probe(PinProbe* probe) {
    if (!probe || has_probe(probe)) return;
    probes_.push_back(probe);
    update_sod();
}

void Machine::remove_probe(PinProbe* probe) {
    std::erase(probes_, probe);
    update_sod();
}

bool Machine::has_probe(const PinProbe* probe) const {
    return std::find(probes_.begin(), probes_.end(), probe) != probes_.end();
}

void Machine::update_sod() {
    // SIM changes SOD inside an instruction: seen at that instruction's first T-state.
    if (!probes_.empty() || serial_)
        cpu_.on_sod = [this](bool level) {
            const std::uint64_t t = cpu_.tstates();
            if (serial_) serial_->sod(level, t);
            probe_look(t);
        };
    else
        cpu_.on_sod = nullptr;
}

void Machine::connect_serial(periph::SerialTerminal& terminal) {
    if (serial_) throw std::logic_error("a serial terminal is already connected");
    attach(terminal);
    serial_ = &terminal;
    terminal.set_sod_level(cpu_.sod());
    terminal.on_txd([this](bool level, std::uint64_t t) {
        cpu_.set_sid(level);
        probe_look(t);
    });
    cpu_.set_sid(terminal.txd());
    update_sod();
}

void Machine::serial_at(std::uint8_t value, std::uint64_t at) { inputs_.schedule(at, InputKind::Serial, value, true); }

// Each probe's own clock (a sample period, a part's next pin change) up to t: the parts are
// advanced to the earliest time a probe asks for, and every probe due then looks.
void Machine::probe_clock(std::uint64_t t) {
    while (!probes_.empty()) {
        std::uint64_t at = periph::Part::kNever;
        for (const PinProbe* p : probes_) at = std::min(at, p->next());
        if (at > t) return;
        for (periph::Part* p : parts_) p->advance(std::max(at, p->now()));
        if (sampler_paused_) return;  // a debugger re-running the past: looked at the first time
        for (PinProbe* p : probes_)
            if (p->next() <= at) p->look(at);
        for (const PinProbe* p : probes_)
            if (p->next() <= at) return;  // a probe must move on; never spin here
    }
}

void Machine::cpu_pins(periph::Pins& p) const {
    p.scope("8085");
    p.logic("SOD", cpu_.sod());
    p.logic("SID", cpu_.sid());
    p.logic("TRAP", cpu_.trap_pin());
    p.logic("RST7_5", cpu_.rst75_pin());
    p.logic("RST6_5", cpu_.rst65_pin());
    p.logic("RST5_5", cpu_.rst55_pin());
    p.logic("INTR", cpu_.intr_pin());
    p.logic("INTA", true);
    p.logic("HLT", cpu_.halted(), false);
}

void Machine::attach(periph::Part& part, IoDevice* io, std::uint8_t first, std::uint8_t last) {
    for (const periph::Part* p : parts_) {
        if (p->tag() == part.tag())
            throw std::invalid_argument(fmt::format("a part tagged '{}' is already on the board", part.tag()));
    }
    part.advance(now());
    parts_.push_back(&part);
    if (io) bus_.map_io(first, last, *io);
}

periph::Part* Machine::find_part(std::string_view name) const {
    for (periph::Part* p : parts_)
        if (p->name() == name) return p;
    return nullptr;
}

std::span<std::uint8_t> Machine::storage(board::Memory id) {
    switch (id) {
        case board::Memory::MonitorEprom: return monitor_;
        case board::Memory::UserEprom: return user_;
        case board::Memory::Ram: return ram_;
        case board::Memory::Ram8155: return rio_.ram();
        case board::Memory::ExpansionEprom: return expansion_;
    }
    return {};
}

void Machine::set_expansion_eprom(bool fitted) {
    const board::MemoryRegion& r = board::kExpansionEprom;
    options_.expansion_eprom = fitted;
    std::erase_if(map_, [](const board::MemoryRegion& m) { return m.id == board::Memory::ExpansionEprom; });
    if (fitted) {
        map_.push_back(r);
        bus_.map_rom(r.base, r.size, expansion_.data());
    } else {
        bus_.unmap(r.base, r.size);
    }
}

namespace {
void check_on_board(const std::vector<board::MemoryRegion>& map, std::uint16_t address, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t a = address + static_cast<std::uint32_t>(i);
        const bool mapped = a <= 0xFFFF && std::any_of(map.begin(), map.end(),
                                                       [a](const board::MemoryRegion& r) {
                                                           return a >= r.base && a < r.base + r.size;
                                                       });
        if (!mapped)
            throw std::out_of_range(fmt::format("address {:04X}H is not on the ALP 85 (no memory there)", a));
    }
}
}  // namespace

void Machine::load(std::uint16_t address, std::span<const std::uint8_t> bytes) {
    load(std::vector<ImageSegment>{{address, {bytes.begin(), bytes.end()}}});
}

void Machine::load(const std::vector<ImageSegment>& image) {
    // Check the whole image first, so a failed load changes nothing.
    for (const ImageSegment& s : image) check_on_board(map_, s.address, s.bytes.size());
    for (const ImageSegment& s : image)
        for (std::size_t i = 0; i < s.bytes.size(); ++i) poke(static_cast<std::uint16_t>(s.address + i), s.bytes[i]);
}

bool Machine::poke(std::uint16_t address, std::uint8_t value) {
    for (const auto& r : map_) {
        if (address >= r.base && address < r.base + r.size) {
            storage(r.id)[address - r.base] = value;
            return true;
        }
    }
    return false;
}

void Machine::reset() {
    const std::uint64_t t = now();
    const bool sod = cpu_.sod();
    cpu_.reset();
    if (sod != cpu_.sod() && cpu_.on_sod) cpu_.on_sod(cpu_.sod());  // RESET puts SOD low: a listener sees it fall
    for (periph::Part* p : parts_) {
        p->advance(t);
        p->reset(t);
    }
}

void Machine::apply(const InputEvent& e) {
    switch (e.kind) {
        case InputKind::Key: {
            // The 8279 sees the matrix change at the event's time (or at its own time, if the CPU's
            // last instruction already brought it past that).
            const std::uint64_t t = std::max(e.at, kdc_.state().now);
            kdc_.advance(t);
            keypad_.set(static_cast<periph::Key>(e.code), e.level);
            kdc_.inputs_changed(t);
            break;
        }
        case InputKind::VectIntr: drive(board::pin_of(board::Source::VectIntrKey), e.level, std::max(e.at, now())); break;
        case InputKind::Reset: drive(board::pin_of(board::Source::ResetKey), e.level, std::max(e.at, now())); break;
        case InputKind::Serial:
            if (serial_) serial_->type(static_cast<std::uint8_t>(e.code), std::max(e.at, now()));
            break;
    }
}

void Machine::deliver_inputs(std::uint64_t t) {
    while (inputs_.due(t)) {
        const InputEvent e = inputs_.pop();
        input_log_.push_back(e);
        apply(e);
    }
}

void Machine::replay(const std::vector<InputEvent>& events) {
    for (const InputEvent& e : events) inputs_.schedule(e.at, e.kind, e.code, e.level);
}

Machine::RunEnd Machine::run_until(std::uint64_t until, const std::function<bool()>& condition) {
    Hooks& h = *hooks_;
    h.stopped = false;
    h.skip_armed = true;
    h.skip_pc = cpu_.regs().pc;
    for (;;) {
        const std::uint64_t t = now();
        deliver_inputs(t);
        if (next_sample_ <= t) sample(t);
        if (!probes_.empty()) probe_clock(t);
        sync_parts(t);
        if (condition && condition()) return RunEnd::Condition;
        if (t >= until) return RunEnd::Deadline;
        std::uint64_t next = std::min({until, inputs_.next_time(), next_part_event()});
        if (next <= t) next = t + 1;
        cpu_.run(next);
        if (cpu_.fence_stopped()) {  // the observer's fetch fence: it decides, the CPU goes on
            if (h.observer->at_fence(cpu_)) {
                sync_parts(now());
                return RunEnd::Observer;
            }
            cpu_.pass_fence();
            continue;
        }
        if (h.stopped) {
            sync_parts(now());
            return h.reason;
        }
    }
}

Machine::RunEnd Machine::run_to(std::uint16_t pc, std::uint64_t until) {
    Hooks& h = *hooks_;
    h.run_to = true;
    h.run_to_pc = pc;
    cpu_.set_debug_hooks(hooks_.get());
    const RunEnd end = run_until(until);
    h.run_to = false;
    update_hooks();
    return end;
}

void Machine::step() {
    Hooks& h = *hooks_;
    h.stopped = false;
    h.skip_armed = true;
    h.skip_pc = cpu_.regs().pc;
    deliver_inputs(now());
    sync_parts(now());
    cpu_.pass_fence();  // one instruction, whatever the fence says
    cpu_.step();
    deliver_inputs(now());
    sync_parts(now());
}

bool Machine::can_wake() const {
    return cpu_.interrupts_enabled() || rio_.state().running || !inputs_.empty();
}

void Machine::key_at(periph::Key key, bool down, std::uint64_t at) {
    inputs_.schedule(at, InputKind::Key, static_cast<std::uint16_t>(key), down);
}
void Machine::vect_intr_at(bool down, std::uint64_t at) { inputs_.schedule(at, InputKind::VectIntr, 0, down); }
void Machine::reset_key_at(bool down, std::uint64_t at) { inputs_.schedule(at, InputKind::Reset, 0, down); }


std::array<std::uint8_t, 8> Machine::display() const { return periph::seven_segment::read_digits(kdc_); }
std::string Machine::display_text() const {
    const auto d = display();
    return periph::seven_segment::to_text(d);
}
std::array<std::string, 7> Machine::display_art() const {
    const auto d = display();
    return periph::seven_segment::to_art(d);
}

void Machine::update_hooks() {
    Hooks& h = *hooks_;
    h.observer_accesses = h.observer && h.observer->wants_accesses();
    // An observer content with a fetch fence leaves the CPU on its plain path (I8085::set_fetch_fence).
    const std::bitset<0x10000>* fence = h.observer && !h.observer_accesses ? h.observer->fetch_fence() : nullptr;
    const bool hooks = h.trace || (h.observer && !fence);
    cpu_.set_debug_hooks(hooks ? hooks_.get() : nullptr);
    cpu_.set_fetch_fence(hooks ? nullptr : fence);
}

void Machine::set_observer(RunObserver* observer) {
    hooks_->observer = observer;
    update_hooks();
}
RunObserver* Machine::observer() const { return hooks_->observer; }

void Machine::rewind_inputs(std::size_t log_size, const std::vector<InputEvent>& pending, std::uint64_t next_seq) {
    if (log_size < input_log_.size()) input_log_.resize(log_size);
    inputs_.restore(pending, next_seq);
}

void Machine::set_trace(std::function<void(const I8085&)> trace) {
    hooks_->trace = std::move(trace);
    update_hooks();
}
}  // namespace alp85
