#include "emu/cpm/cpm.h"

#include <limits>
#include <stdexcept>

#include "emu/program/ihex.h"

namespace alp85 {

CpmMachine::CpmMachine(Variant variant) : ram_(0x10000, 0), cpu_(bus_, variant) {
    bus_.map_ram(0, 0x10000, ram_.data());
    const std::string err = load_intel_hex(kBdosHex, [this](std::uint16_t a, std::uint8_t v) { ram_[a] = v; });
    if (!err.empty()) throw std::logic_error("built-in BDOS image: " + err);
    io_.on_out = [this](std::uint8_t port, std::uint8_t value, std::uint64_t) {
        if (port == kConsolePort) {
            if (console_) console_(static_cast<char>(value));
        } else if (port == kBadFunctionPort) {
            bad_function_ = value;
        }
    };
    bus_.map_io(kConsolePort, kBadFunctionPort, io_);
    cpu_.on_halt = [this] { cpu_.request_stop(); };
    cpu_.regs().pc = kTpa;
    cpu_.regs().sp = bdos_entry();
}

void CpmMachine::set_trace(std::function<void(const I8085&)> trace) {
    trace_hooks_.trace = std::move(trace);
    cpu_.set_debug_hooks(trace_hooks_.trace ? &trace_hooks_ : nullptr);
}

std::string CpmMachine::load_program(std::span<const std::uint8_t> image) {
    const std::size_t room = bdos_entry() - kTpa;
    if (image.empty()) return "program is empty";
    if (image.size() > room)
        return "program is " + std::to_string(image.size()) + " bytes; the TPA holds " + std::to_string(room);
    std::copy(image.begin(), image.end(), ram_.begin() + kTpa);
    return {};
}

CpmMachine::Result CpmMachine::run(std::uint64_t max_tstates, const std::function<void(char)>& console) {
    console_ = console;
    bad_function_ = -1;
    const std::uint64_t deadline = max_tstates == 0 ? std::numeric_limits<std::uint64_t>::max() : max_tstates;
    // A CALL 0005H pushes its return address onto the stack the program set up; the warm-boot HLT
    // stops the run through on_halt.
    bool stopped = false;
    while (!cpu_.halted() && cpu_.tstates() < deadline && !stopped)
        stopped = cpu_.run(deadline) == 0;  // nothing ran: a debug hook refused the next instruction

    Result r;
    r.instructions = cpu_.instructions();
    r.tstates = cpu_.tstates();
    char buf[96];
    if (cpu_.halted() && bad_function_ >= 0) {
        r.end = End::BadFunction;
        r.exit_status = 3;
        std::snprintf(buf, sizeof buf, "undefined BDOS function %d (C=%02XH)", bad_function_, bad_function_);
        r.message = buf;
    } else if (cpu_.halted() && cpu_.regs().pc == 0x0001) {
        r.end = End::WarmBoot;
        r.exit_status = 0;
    } else if (cpu_.halted()) {
        r.end = End::Halt;
        r.exit_status = 2;
        std::snprintf(buf, sizeof buf, "HLT at %04XH", static_cast<unsigned>((cpu_.regs().pc - 1) & 0xFFFF));
        r.message = buf;
    } else if (stopped) {
        r.end = End::Stopped;
        r.exit_status = 5;
        std::snprintf(buf, sizeof buf, "stopped by a debug hook before %04XH", static_cast<unsigned>(cpu_.regs().pc));
        r.message = buf;
    } else {
        r.end = End::CycleLimit;
        r.exit_status = 4;
        std::snprintf(buf, sizeof buf, "cycle limit reached: %llu T-states (PC=%04XH)",
                      static_cast<unsigned long long>(cpu_.tstates()), static_cast<unsigned>(cpu_.regs().pc));
        r.message = buf;
    }
    console_ = nullptr;
    return r;
}

}  // namespace alp85
