#include "emu/board/machine.h"

#include <algorithm>
#include <bitset>
#include <stdexcept>

#include <fmt/format.h>

#include "emu/board/snapshot_file.h"
#include "peripherals/seven_segment.h"

namespace alp85 {

using periph::I8155;

// The debugger's view of a run: breakpoints before an instruction, watchpoints on data accesses.
// Installed on the CPU only while some are set, so a plain run pays nothing for them.
class Machine::Hooks final : public DebugHooks {
public:
    std::bitset<0x10000> breakpoint;
    std::bitset<0x10000> watch;
    bool any_watch = false;
    // A run that starts on a breakpoint executes that instruction (as a debugger's "continue").
    bool skip_armed = false;
    std::uint16_t skip_pc = 0;
    bool stopped = false;
    Stop reason = Stop::Deadline;
    std::uint16_t hit_address = 0;
    std::function<void(const I8085&)> trace;
    bool run_to = false;  // run_to(): only run_to_pc stops the run
    std::uint16_t run_to_pc = 0;

    bool before_instruction(I8085& cpu) override {
        const std::uint16_t pc = cpu.regs().pc;
        const bool stop_here = run_to ? pc == run_to_pc : static_cast<bool>(breakpoint[pc]);
        if (stop_here && !(skip_armed && pc == skip_pc)) {
            skip_armed = false;
            stopped = true;
            reason = Stop::Breakpoint;
            return false;
        }
        skip_armed = false;
        if (trace) trace(cpu);
        return true;
    }
    void on_read(I8085& cpu, std::uint16_t addr, std::uint8_t) override { check(cpu, addr); }
    void on_write(I8085& cpu, std::uint16_t addr, std::uint8_t) override { check(cpu, addr); }

private:
    void check(I8085& cpu, std::uint16_t addr) {
        if (any_watch && watch[addr]) {
            stopped = true;
            reason = Stop::Watchpoint;
            hit_address = addr;
            cpu.request_stop();
        }
    }
};

// The 8279 on ports E0H-E1H: A0 selects data (0) or command/status (1).
class Machine::Port8279 final : public IoDevice {
public:
    explicit Port8279(Machine& m) : m_(m) {}
    std::uint8_t in(std::uint8_t port, std::uint64_t t) override { return m_.kdc_.read(port & 1, t); }
    void out(std::uint8_t port, std::uint8_t value, std::uint64_t t) override {
        m_.kdc_.write(port & 1, value, t);
        m_.cpu_.stop_at(t);  // the chip's next event may have moved: let the scheduler look again
    }

private:
    Machine& m_;
};

// The 8155 on ports F8H-FDH: AD0-AD2 = port - F8H.
class Machine::Port8155 final : public IoDevice {
public:
    explicit Port8155(Machine& m) : m_(m) {}
    std::uint8_t in(std::uint8_t port, std::uint64_t t) override {
        return m_.rio_.read(static_cast<std::uint8_t>(port - kBase), t);
    }
    void out(std::uint8_t port, std::uint8_t value, std::uint64_t t) override {
        m_.rio_.write(static_cast<std::uint8_t>(port - kBase), value, t);
        m_.cpu_.stop_at(t);
    }

private:
    static constexpr std::uint8_t kBase = [] {
        for (const auto& r : board::kIoMap)
            if (r.device == board::Device::Rio8155) return r.first;
        return std::uint8_t{0};
    }();
    Machine& m_;
};

Machine::Machine() : Machine(Options{}) {}

Machine::Machine(Options options)
    : options_(options),
      cpu_(bus_, options.cpu),
      port8279_(std::make_unique<Port8279>(*this)),
      port8155_(std::make_unique<Port8155>(*this)),
      hooks_(std::make_unique<Hooks>()) {
    // Erased EPROMs read FFH (every cell charged); RAM powers up as zeros here (the real parts
    // are unpredictable, and a deterministic machine needs some fixed value).
    monitor_.fill(0xFF);
    user_.fill(0xFF);
    wire();
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
    for (const auto& r : board::kIoMap) {
        IoDevice& dev = r.device == board::Device::Kdc8279 ? static_cast<IoDevice&>(*port8279_)
                                                             : static_cast<IoDevice&>(*port8155_);
        bus_.map_io(r.first, r.last, dev);
    }
    // Interrupt wiring (board::kInterruptWiring).
    // SHIFT and CNTL/STB are grounded on the ALP 85 (docs/peripherals.md): key codes carry 0 there.
    kdc_.set_shift(false, 0);
    kdc_.set_cntl_stb(false, 0);
    rio_.on_timer_out([this](bool level, std::uint64_t) { cpu_.set_trap(level); });
    kdc_.on_irq([this](bool level, std::uint64_t) { cpu_.set_rst55(level); });
    kdc_.set_return_lines_source([this](std::uint8_t sl) { return keypad_.return_lines(sl); });
    rio_.set_input_callback([this](I8155::Port port, std::uint64_t now) -> std::uint8_t {
        if (port == I8155::Port::B && port_b_source_) return port_b_source_(now);
        return port == I8155::Port::C ? 0x3F : 0xFF;  // unconnected inputs are pulled high
    });
}

std::span<std::uint8_t> Machine::storage(board::Memory id) {
    switch (id) {
        case board::Memory::MonitorEprom: return monitor_;
        case board::Memory::UserEprom: return user_;
        case board::Memory::Ram: return ram_;
        case board::Memory::Ram8155: return rio_.ram();
    }
    return {};
}

namespace {
void check_on_board(std::uint16_t address, std::size_t size) {
    for (std::size_t i = 0; i < size; ++i) {
        const std::uint32_t a = address + static_cast<std::uint32_t>(i);
        const bool mapped = a <= 0xFFFF && std::any_of(board::kMemoryMap.begin(), board::kMemoryMap.end(),
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
    for (const ImageSegment& s : image) check_on_board(s.address, s.bytes.size());
    for (const ImageSegment& s : image)
        for (std::size_t i = 0; i < s.bytes.size(); ++i) poke(static_cast<std::uint16_t>(s.address + i), s.bytes[i]);
}

bool Machine::poke(std::uint16_t address, std::uint8_t value) {
    for (const auto& r : board::kMemoryMap) {
        if (address >= r.base && address < r.base + r.size) {
            storage(r.id)[address - r.base] = value;
            return true;
        }
    }
    return false;
}

void Machine::reset() {
    const std::uint64_t t = now();
    cpu_.reset();
    rio_.reset(t);
    kdc_.reset(t);
}

void Machine::sync_chips(std::uint64_t t) {
    rio_.advance(t);
    kdc_.advance(t);
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
        case InputKind::VectIntr: cpu_.set_rst75(e.level); break;
        case InputKind::Reset:
            if (e.level) reset();
            break;
    }
}

void Machine::deliver_inputs(std::uint64_t t) {
    while (inputs_.due(t)) apply(inputs_.pop());
}

Machine::Stop Machine::run_until(std::uint64_t until, const std::function<bool()>& condition) {
    Hooks& h = *hooks_;
    h.stopped = false;
    h.skip_armed = true;
    h.skip_pc = cpu_.regs().pc;
    for (;;) {
        const std::uint64_t t = now();
        deliver_inputs(t);
        sync_chips(t);
        if (condition && condition()) return Stop::Condition;
        if (t >= until) return Stop::Deadline;
        std::uint64_t next = std::min({until, inputs_.next_time(), rio_.next_event(), kdc_.next_event()});
        if (next <= t) next = t + 1;
        cpu_.run(next);
        if (h.stopped) {
            sync_chips(now());
            if (h.reason == Stop::Watchpoint) watch_hit_ = h.hit_address;
            return h.reason;
        }
    }
}

Machine::Stop Machine::run_to(std::uint16_t pc, std::uint64_t until) {
    Hooks& h = *hooks_;
    h.run_to = true;
    h.run_to_pc = pc;
    cpu_.set_debug_hooks(hooks_.get());
    const Stop stop = run_until(until);
    h.run_to = false;
    update_hooks();
    return stop;
}

void Machine::step() {
    Hooks& h = *hooks_;
    h.stopped = false;
    h.skip_armed = true;
    h.skip_pc = cpu_.regs().pc;
    deliver_inputs(now());
    sync_chips(now());
    cpu_.step();
    deliver_inputs(now());
    sync_chips(now());
}

void Machine::key_at(periph::Key key, bool down, std::uint64_t at) {
    inputs_.schedule(at, InputKind::Key, static_cast<std::uint16_t>(key), down);
}
void Machine::vect_intr_at(bool down, std::uint64_t at) { inputs_.schedule(at, InputKind::VectIntr, 0, down); }
void Machine::reset_key_at(bool down, std::uint64_t at) { inputs_.schedule(at, InputKind::Reset, 0, down); }

void Machine::set_port_b_source(std::function<std::uint8_t(std::uint64_t)> source) {
    port_b_source_ = std::move(source);
}

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
    h.any_watch = h.watch.any();
    cpu_.set_debug_hooks(h.breakpoint.any() || h.any_watch || h.trace ? hooks_.get() : nullptr);
}

void Machine::add_breakpoint(std::uint16_t pc) {
    if (!hooks_->breakpoint[pc]) breakpoints_.push_back(pc);
    hooks_->breakpoint[pc] = true;
    update_hooks();
}
void Machine::remove_breakpoint(std::uint16_t pc) {
    hooks_->breakpoint[pc] = false;
    std::erase(breakpoints_, pc);
    update_hooks();
}
void Machine::clear_breakpoints() {
    hooks_->breakpoint.reset();
    breakpoints_.clear();
    update_hooks();
}
void Machine::set_trace(std::function<void(const I8085&)> trace) {
    hooks_->trace = std::move(trace);
    update_hooks();
}
void Machine::add_watchpoint(std::uint16_t address) {
    hooks_->watch[address] = true;
    watchpoints_.push_back(address);
    update_hooks();
}
void Machine::clear_watchpoints() {
    hooks_->watch.reset();
    watchpoints_.clear();
    update_hooks();
}

}  // namespace alp85
