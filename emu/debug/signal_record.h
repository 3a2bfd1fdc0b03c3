// A logic analyzer on the ALP 85: the pins the parts and the 8085 show (periph::Pins, through
// Part::pins and Machine::cpu_pins), recorded as a Value Change Dump for GTKWave, PulseView and
// sigrok-cli. For `record signals FILE.vcd [PIN...]` and `alp85 run --vcd FILE` (docs/signals.md).
//
// Time: one VCD unit is 1 ns; a change at T-state T (counted from power-on) is written at
// #round(T * 1e9 / kCpuHz), so round(ns * kCpuHz / 1e9) gives T back exactly (the header says so,
// with the T-states the recording starts and ends at; sigrok 0.5 stops reading at a vector, so
// there is no T-state variable). Pins that change at a write,
// a timer or an interrupt line, SID (a serial terminal's bit edges) and the 8279's scan, are
// recorded at their T-state; the 8085's HLT and the machine tool's physics (transducer outputs, currents, rotor angle) on a sample
// clock of `period` T-states.
//
// The file goes to a temporary beside its target and takes its name only at stop(): a recording
// is complete or absent.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "emu/board/machine.h"
#include "emu/debug/pin_tap.h"
#include "asm/files/atomic_file.h"

namespace alp85::debug {

class SignalRecorder final : public PinProbe {
public:
    static constexpr std::uint64_t kDefaultPeriod = 96;  // 31.25 us: four samples of the 125 us motor grid

    using PinName = PinTap::PinName;
    // Every pin of `machine`, in the file's order.
    static std::vector<PinName> pin_names(const Machine& machine) { return PinTap::pin_names(machine); }
    // "" when every word of `selection` names a pin ("PA0", "8155.PA0"), every pin of that name
    // ("PULSE": X, Y and Z's) or a scope ("8155", "X"), case-insensitive; else why not.
    static std::string check_selection(const Machine& machine, const std::vector<std::string>& selection) {
        return PinTap::check_selection(machine, selection);
    }

    SignalRecorder() = default;
    SignalRecorder(const SignalRecorder&) = delete;
    SignalRecorder& operator=(const SignalRecorder&) = delete;
    ~SignalRecorder() override;

    // Starts recording the selected pins (all when empty) of `machine` into `path`, from now on.
    // Throws std::runtime_error (a file that cannot be made, a selection that names no pin).
    void start(Machine& machine, const std::filesystem::path& path, const std::vector<std::string>& selection,
               std::uint64_t period = kDefaultPeriod);
    // Ends the recording at the machine's present T-state and gives the file its name. Throws
    // std::runtime_error naming the path (the temporary is then gone).
    void stop();
    // Ends the recording without a file: the temporary is removed, the target left as it was.
    void abandon();
    bool recording() const { return machine_ != nullptr; }
    const std::filesystem::path& path() const { return path_; }
    std::uint64_t changes() const { return changes_; }  // value changes written

    // PinProbe
    void look(std::uint64_t t) override;
    std::uint64_t next() const override;

private:
    void write_time(std::uint64_t t);
    void detach();

    Machine* machine_ = nullptr;
    std::filesystem::path path_;
    std::unique_ptr<AtomicOutput> file_;
    PinTap tap_;
    std::vector<std::string> ids_;  // per channel of the tap: its VCD identifier
    std::uint64_t last_t_ = 0;   // the latest T-state looked at (the file never goes back)
    std::uint64_t written_t_ = ~std::uint64_t{0};  // the time of the last `#` line
    std::uint64_t start_t_ = 0;
    std::uint64_t changes_ = 0;
};

}  // namespace alp85::debug
