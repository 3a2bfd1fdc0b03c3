#include "emu/board/machine.h"

#include <algorithm>
#include <bitset>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

// A chip as its board's description decodes it, in I/O or memory space: the chip sees as its
// register the address lines the description selects, and a write may move the chip's next event,
// so the batch ends there and the scheduler looks again.
class Machine::Decoder : public IoDevice, public MemoryDevice {
public:
    explicit Decoder(const board::DeviceRegion& region) : region(region) {}
    const board::DeviceRegion& region;
};

namespace {
// `after_write` lets the board follow pins a write may change (the 8155's port A drives the tool).
template <class Chip, class Base>
class ChipDecoder final : public Base {
public:
    ChipDecoder(Chip& chip, I8085& cpu, const board::DeviceRegion& region, std::function<void(std::uint64_t)> after_write = {})
        : Base(region), chip_(chip), cpu_(cpu), after_write_(std::move(after_write)) {}
    std::uint8_t in(std::uint8_t port, std::uint64_t t) override { return chip_.read(this->region.offset(port), t); }
    void out(std::uint8_t port, std::uint8_t value, std::uint64_t t) override { write(port, value, t); }
    std::uint8_t read(std::uint16_t addr, std::uint64_t t) override { return chip_.read(this->region.offset(addr), t); }
    void write(std::uint16_t addr, std::uint8_t value, std::uint64_t t) override {
        chip_.write(this->region.offset(addr), value, t);
        if (after_write_) after_write_(t);
        cpu_.stop_at(t);
    }

private:
    Chip& chip_;
    I8085& cpu_;
    std::function<void(std::uint64_t)> after_write_;
};

constexpr bool chip_ram(board::Memory id) {  // memory inside a chip (chip_ram: the name older than the 8355)
    return id == board::Memory::Ram8155 || id == board::Memory::Ram8155Expansion || id == board::Memory::Rom8355;
}
}  // namespace

Machine::Machine() : Machine(Options{}) {}

Machine::Machine(Options options)
    : options_(options),
      cpu_(bus_, options.cpu),
      tool_(board::kCpuHz),
      hooks_(std::make_unique<Hooks>()) {
    const board::Board& b = *options_.board;
    if (b.clock.cpu_hz() != board::kCpuHz)
        throw std::invalid_argument(fmt::format("board {}: the 8085 must run at {} Hz", b.name, board::kCpuHz));
    options_.machine_tool = options_.machine_tool && !b.tool.empty();
    // Erased EPROMs read FFH (every cell charged); RAM powers up as zeros here (the real parts
    // are unpredictable, and a deterministic machine needs some fixed value).
    stores_.resize(b.memory.size());
    for (std::size_t i = 0; i < b.memory.size(); ++i) {
        const board::MemoryRegion& r = b.memory[i];
        if (!chip_ram(r.id)) stores_[i].assign(r.size, r.kind == board::MemoryKind::Rom ? 0xFF : 0x00);
    }
    wire();
    if (options.expansion_eprom) set_option("expansion", true);
    options_.expansion_eprom = option("expansion");
    reset();
}

Machine::~Machine() = default;

void Machine::wire() {
    const board::Board& b = *options_.board;
    // A second 8155, where the board has a place for one: a part like the others, decoded while fitted.
    for (const board::DeviceRegion& d : b.devices) {
        if (d.device == board::Device::Rio8155 && d.unit == 1 && !rio2_) rio2_ = std::make_unique<I8155>("8155b", "RIO2");
        if (d.device == board::Device::Rom8355 && !rom8355_) rom8355_ = std::make_unique<periph::I8355>();
    }
    // The parts, in the order they are advanced, reset and saved.
    parts_ = {&rio_, &kdc_, &keypad_};
    if (rio2_) parts_.push_back(rio2_.get());
    if (rom8355_) parts_.push_back(rom8355_.get());
    if (options_.machine_tool) parts_.push_back(&tool_);
    tool_.set_model(options_.motor);
    for (const board::DeviceRegion& r : b.devices) {
        const auto make = [&]<class Chip>(Chip& chip, std::function<void(std::uint64_t)> after = {}) {
            decoders_.push_back(std::make_unique<ChipDecoder<Chip, Decoder>>(chip, cpu_, r, std::move(after)));
        };
        switch (r.device) {
            case board::Device::Kdc8279: make(kdc_); break;
            case board::Device::Rio8155:
                if (r.unit == 0)
                    make(rio_, [this](std::uint64_t t) {
                        drive_tool(t);
                        probe_look(t);
                    });
                else
                    make(*rio2_);
                break;
            case board::Device::Rom8355: make(*rom8355_); break;
        }
    }
    fit({}, true);  // everything that is not an option
    // Interrupt wiring, from the description (the keys are applied in apply()).
    for (const board::Wire& w : b.wiring) {
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
    // SHIFT and CNTL/STB: grounded on the ALP 85 (docs/peripherals.md), so key codes carry 0 there.
    kdc_.set_shift(b.shift_cntl_high, 0);
    kdc_.set_cntl_stb(b.shift_cntl_high, 0);
    keypad_.clear_places();
    for (const board::BoardKey& k : b.keys)
        if (k.wire == board::KeyWire::Matrix) keypad_.place(k.key, k.scan, k.ret);
    kdc_.set_return_lines_source([this](std::uint8_t sl) { return keypad_.return_lines(sl); });
    const auto undriven = [ab = b.undriven_port_ab, c = b.undriven_port_c](I8155::Port port) {
        return port == I8155::Port::C ? c : ab;
    };
    rio_.set_input_callback([this, undriven](I8155::Port port, std::uint64_t now) -> std::uint8_t {
        if (port == I8155::Port::B && options_.machine_tool) return sense_tool(now);
        return undriven(port);
    });
    if (rio2_) rio2_->set_input_callback([undriven](I8155::Port port, std::uint64_t) { return undriven(port); });
    // Nothing on the board drives the 8355's port lines: pulled up, they read 1.
    if (rom8355_) rom8355_->set_input_callback([ab = b.undriven_port_ab](periph::I8355::Port, std::uint64_t) { return ab; });
}

// Maps (or takes off the bus) every region and chip of one option; option {} is the board as built.
void Machine::fit(std::string_view option, bool fitted) {
    const board::Board& b = *options_.board;
    for (std::size_t i = 0; i < b.memory.size(); ++i) {
        const board::MemoryRegion& r = b.memory[i];
        if (r.option != option) continue;
        std::erase_if(map_, [&](const board::MemoryRegion& m) { return m.id == r.id; });
        if (!fitted) {
            bus_.unmap(r.base, r.span());
            continue;
        }
        map_.push_back(r);
        std::uint8_t* data = storage(r.id).data();
        for (std::uint32_t at = r.base; at < r.base + r.span(); at += r.size) {  // the decoder's mirrors
            if (r.kind == board::MemoryKind::Rom)
                bus_.map_rom(at, r.size, data);
            else
                bus_.map_ram(at, r.size, data);
        }
    }
    for (const auto& d : decoders_) {
        const board::DeviceRegion& r = d->region;
        if (r.option != option) continue;
        if (r.space == board::Space::Io) {
            const auto first = static_cast<std::uint8_t>(r.first), last = static_cast<std::uint8_t>(r.last);
            if (fitted)
                bus_.map_io(first, last, *d);
            else
                bus_.unmap_io(first, last);
        } else if (fitted) {
            bus_.map_device(r.first, r.last - r.first + 1u, *d);
        } else {
            bus_.unmap(r.first, r.last - r.first + 1u);
        }
    }
}

bool Machine::set_option(std::string_view name, bool fitted) {
    if (!board::has_option(*options_.board, name)) return false;
    std::erase(fitted_, name);
    if (fitted) fitted_.push_back(name);
    fit(name, fitted);
    if (name == "expansion") options_.expansion_eprom = fitted;
    return true;
}

bool Machine::option(std::string_view name) const { return std::find(fitted_.begin(), fitted_.end(), name) != fitted_.end(); }

std::string Machine::describe_board() const {
    const board::Board& b = *options_.board;
    std::string out = fmt::format("board {}: {}, 8085 at {} Hz (crystal {} Hz)\n", b.name, b.title, b.clock.cpu_hz(),
                                  b.clock.crystal_hz);
    out += "memory:\n";
    for (const board::MemoryRegion& r : map_) {
        out += fmt::format("  {:04X}H-{:04X}H  {} {:<10} {}", r.base, r.base + r.size - 1,
                           r.kind == board::MemoryKind::Rom ? "ROM" : "RAM", r.name, r.part);
        if (r.span() != r.size) out += fmt::format(" (mirrored through {:04X}H)", r.base + r.span() - 1);
        out += '\n';
    }
    out += "devices:\n";
    for (const board::DeviceRegion& d : device_map())
        out += fmt::format("  {} {:0{}X}H-{:0{}X}H  {:<6} {}\n", d.space == board::Space::Io ? "I/O   " : "memory", d.first,
                           d.space == board::Space::Io ? 2 : 4, d.last, d.space == board::Space::Io ? 2 : 4, d.name,
                           d.registers);
    out += "wiring:\n";
    static constexpr std::array<std::string_view, 4> kSources{"8279 IRQ", "8155 TIMER OUT", "VECT INTR key", "RESET key"};
    static constexpr std::array<std::string_view, 4> kPins{"RST 5.5", "TRAP", "RST 7.5", "RESET IN"};
    for (const board::Wire& w : b.wiring)
        out += fmt::format("  {} -> {}: {}\n", kSources[static_cast<std::size_t>(w.source)], kPins[static_cast<std::size_t>(w.pin)],
                           w.why);
    out += "keys:\n";
    for (const board::BoardKey& k : b.keys) {
        std::string cap(k.cap);
        std::replace(cap.begin(), cap.end(), '\n', ' ');
        if (k.wire == board::KeyWire::Matrix)
            out += fmt::format("  {:<12} {:<5} SL{} RL{}\n", cap, k.name, k.scan, k.ret);
        else
            out += fmt::format("  {:<12} {:<5} {}\n", cap, k.name, k.wire == board::KeyWire::ResetIn ? "RESET IN" : "RST 7.5");
    }
    out += fmt::format("display: {} digits, segments a-g,dp on display RAM bits {}, lit at {}\n", b.display.digits,
                       fmt::join(b.display.segment_bit, ","), b.display.active_low ? 0 : 1);
    for (const board::BoardOption& o : b.options)
        out += fmt::format("option {} ({}): {}\n", o.name, option(o.name) ? "on" : "off", o.what);
    return out;
}

std::vector<board::DeviceRegion> Machine::device_map() const {
    std::vector<board::DeviceRegion> out;
    for (const board::DeviceRegion& r : options_.board->devices)
        if (r.option.empty() || option(r.option)) out.push_back(r);
    return out;
}

namespace {
constexpr I8155::Port port_of(std::uint8_t port) {
    return board::alp85::kDevices[1].offset(port) == I8155::kPortA ? I8155::Port::A : I8155::Port::B;
}
static_assert(board::alp85::kDevices[1].device == board::Device::Rio8155 &&
                  port_of(board::alp85::kToolOutPort) == I8155::Port::A && port_of(board::alp85::kToolInPort) == I8155::Port::B,
              "the machine tool sits on the 8155's ports A (out) and B (in)");

// The wiring table is in the order of the tool's axes: row a is axis a.
constexpr bool wiring_in_axis_order(std::span<const board::AxisWiring> wiring) {
    for (std::size_t a = 0; a < wiring.size(); ++a)
        if (static_cast<std::size_t>(wiring[a].axis) != a) return false;
    return wiring.size() == 3;
}
static_assert(wiring_in_axis_order(board::alp85::kToolWiring), "the tool's wiring lists X, Y, Z in order");

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
        const board::AxisWiring& w = options_.board->tool[a];
        const bool pulse = pins & bit_mask(w.pulse), direction = pins & bit_mask(w.direction);
        if (pulse != axes[a].sequencer.pulse || direction != axes[a].sequencer.direction)
            tool_.set_drive(static_cast<board::ToolAxis>(a), pulse, direction, t);
    }
}

std::uint8_t Machine::sense_tool(std::uint64_t t) {
    std::uint8_t pins = options_.board->undriven_port_ab;  // bits the tool does not drive are pulled high
    if (!options_.machine_tool) return pins;
    for (const board::AxisWiring& w : options_.board->tool) {
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
            if (serial_) serial_->sod(level != options_.board->sod_inverted, t);
            probe_look(t);
        };
    else
        cpu_.on_sod = nullptr;
}

void Machine::connect_serial(periph::SerialTerminal& terminal) {
    if (serial_) throw std::logic_error("a serial terminal is already connected");
    attach(terminal);
    serial_ = &terminal;
    terminal.set_sod_level(cpu_.sod() != options_.board->sod_inverted);
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
    const board::Board& b = *options_.board;
    for (std::size_t i = 0; i < b.memory.size(); ++i) {
        if (b.memory[i].id != id) continue;
        if (id == board::Memory::Ram8155) return rio_.ram();
        if (id == board::Memory::Ram8155Expansion) return rio2_ ? rio2_->ram() : std::span<std::uint8_t>{};
        if (id == board::Memory::Rom8355) return rom8355_ ? rom8355_->rom() : std::span<std::uint8_t>{};
        return stores_[i];
    }
    return {};
}

namespace {
void check_on_board(const board::Board& board, const std::vector<board::MemoryRegion>& map, std::uint16_t address, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t a = address + static_cast<std::uint32_t>(i);
        const bool mapped = a <= 0xFFFF && std::any_of(map.begin(), map.end(),
                                                       [a](const board::MemoryRegion& r) {
                                                           return a >= r.base && a < r.base + r.size;
                                                       });
        if (!mapped)
            throw std::out_of_range(fmt::format("address {:04X}H is not on the {} (no memory there)", a, board.title));
    }
}
}  // namespace

void Machine::load(std::uint16_t address, std::span<const std::uint8_t> bytes) {
    load(std::vector<ImageSegment>{{address, {bytes.begin(), bytes.end()}}});
}

void Machine::load(const std::vector<ImageSegment>& image) {
    // Check the whole image first, so a failed load changes nothing.
    for (const ImageSegment& s : image) check_on_board(*options_.board, map_, s.address, s.bytes.size());
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
        case InputKind::VectIntr:
        case InputKind::Reset: {
            const board::Source key = e.kind == InputKind::Reset ? board::Source::ResetKey : board::Source::VectIntrKey;
            for (const board::Wire& w : options_.board->wiring)
                if (w.source == key) drive(w.pin, e.level, std::max(e.at, now()));
            break;
        }
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


std::array<std::uint8_t, 8> Machine::display() const {
    // The 8279's display RAM byte of each digit, through the board's segment wiring.
    const board::DisplayWiring& w = options_.board->display;
    const std::array<std::uint8_t, periph::seven_segment::kDigits> raw = periph::seven_segment::read_digits(kdc_);
    std::array<std::uint8_t, 8> out{};
    for (unsigned i = 0; i < w.digits; ++i) {
        if (w.position[i] >= kdc_.display_digits()) continue;  // never scanned: dark
        const auto bits = static_cast<std::uint8_t>(w.active_low ? ~raw[w.position[i]] : raw[w.position[i]]);
        for (unsigned seg = 0; seg < 8; ++seg)
            if (bits >> w.segment_bit[seg] & 1u) out[i] = static_cast<std::uint8_t>(out[i] | 1u << seg);
    }
    return out;
}
std::string Machine::display_text() const {
    const auto d = display();
    return periph::seven_segment::to_text(std::span(d).first(display_digits()));
}
std::array<std::string, 7> Machine::display_art() const {
    const auto d = display();
    return periph::seven_segment::to_art(std::span(d).first(display_digits()));
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
