// A 64 KiB CP/M-like machine for running CP/M .COM programs (the period CPU diagnostics): all RAM,
// the program at 0100H, and a small BDOS (firmware/cpm/bdos.asm, assembled at build time) that the
// emulated CPU executes. The host only watches the BDOS's output ports and the HALT state.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "emu/core/bus.h"
#include "emu/core/i8085.h"

namespace alp85 {

// The image of firmware/cpm/bdos.asm as Intel HEX (generated at build time).
extern const char kBdosHex[];

class CpmMachine {
public:
    static constexpr std::uint16_t kTpa = 0x0100;
    static constexpr std::uint8_t kConsolePort = 0x01;   // must match bdos.asm CONOUT
    static constexpr std::uint8_t kBadFunctionPort = 0x02;  // must match bdos.asm BADFN

    enum class End { WarmBoot, Halt, BadFunction, CycleLimit, Stopped };  // Stopped: a debug hook said so
    struct Result {
        End end = End::Halt;
        int exit_status = 1;
        std::string message;  // empty after a warm boot
        std::uint64_t instructions = 0;
        std::uint64_t tstates = 0;
    };

    explicit CpmMachine(Variant variant);

    // Loads a .COM image at 0100H; returns an error message if it does not fit below the BDOS.
    std::string load_program(std::span<const std::uint8_t> image);
    // Runs until warm boot, HLT elsewhere, an undefined BDOS function, max_tstates (0 = no
    // limit), or a debug hook's before_instruction returning false. Console output goes to
    // `console`, a character at a time.
    Result run(std::uint64_t max_tstates, const std::function<void(char)>& console);

    // Calls `trace` before every instruction, through the core's debug hooks (none while empty,
    // so an untraced run keeps the plain loop). Registers are those before the instruction.
    void set_trace(std::function<void(const I8085&)> trace);

    I8085& cpu() { return cpu_; }
    Bus& bus() { return bus_; }
    std::uint16_t bdos_entry() const { return static_cast<std::uint16_t>(ram_[6] | ram_[7] << 8); }

private:
    struct TraceHooks final : DebugHooks {
        std::function<void(const I8085&)> trace;
        bool before_instruction(I8085& cpu) override {
            trace(cpu);
            return true;
        }
    };
    TraceHooks trace_hooks_;
    std::vector<std::uint8_t> ram_;
    Bus bus_;
    I8085 cpu_;
    IoFunctions io_;
    std::function<void(char)> console_;
    int bad_function_ = -1;
};

}  // namespace alp85
