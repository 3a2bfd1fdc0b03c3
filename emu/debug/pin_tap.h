// The probes of a logic analyzer on the ALP 85: a selection of the pins the parts and the 8085 show
// (Part::pins, Machine::cpu_pins), read at a T-state, each with the level it had when last read.
// The VCD recorder (signal_record.h) and the window's Signals pane (signal_trace.h) both read the
// board through it: one model of the pins, one way of naming them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "emu/board/machine.h"

namespace alp85::debug {

class PinTap {
public:
    struct PinName {
        std::string scope, name;
        bool real = false, exact = true;
    };
    // Every pin of `machine`, in the order a recording lists them (the 8085, then each part).
    static std::vector<PinName> pin_names(const Machine& machine);
    // "" when every word of `selection` names a pin ("PA0", "8155.PA0"), every pin of that name
    // ("PULSE": X, Y and Z's) or a scope ("8155", "X"), case-insensitive; else why not.
    static std::string check_selection(const Machine& machine, const std::vector<std::string>& selection);
    // Whether `word` (a word of a selection) chooses `pin`.
    static bool selects(const std::string& word, const PinName& pin);

    struct Channel {
        PinName pin;
        char level = '0';   // a logic pin: '0', '1' or 'z'
        double value = 0;   // a real one
    };

    // Chooses the pins `selection` names (every pin when empty) and reads them at the machine's
    // present T-state, every part advanced to it first. `period`: the sample clock of the pins
    // that are not exact. Throws std::runtime_error (why) when a word names no pin.
    void attach(Machine& machine, const std::vector<std::string>& selection, std::uint64_t period);
    void detach() { machine_ = nullptr; }
    bool attached() const { return machine_ != nullptr; }
    Machine* machine() const { return machine_; }

    // Reads every chosen pin at T-state t; returns the channels whose level or value changed
    // since the last read (their new ones are in channels()). Moves the sample clock past t.
    const std::vector<std::size_t>& read(std::uint64_t t);
    // The machine went back to T-state t (a snapshot, reverse execution): the sample clock
    // starts again from there.
    void rewind(std::uint64_t t);
    // The next T-state the tap must look at by itself, `last` being its last look: the sample
    // clock when a sampled pin is chosen, a chosen part's next pin change (kNever: none).
    std::uint64_t next(std::uint64_t last) const;

    const std::vector<Channel>& channels() const { return channels_; }
    std::uint64_t period() const { return period_; }
    bool sampled() const { return sampled_; }  // a chosen pin needs the sample clock

private:
    // One reader of pins: the 8085 (part == nullptr) or a part.
    struct Source {
        periph::Part* part = nullptr;
        periph::Pins pins;
        std::vector<std::size_t> selected;  // indices into pins, one per channel
        std::size_t first = 0;              // its first channel
        bool self_timed = false;            // a chosen exact pin may change by itself (next_pin_change)
    };

    Machine* machine_ = nullptr;
    std::vector<Source> sources_;
    std::vector<Channel> channels_;
    std::vector<std::size_t> changed_;
    std::uint64_t period_ = 1;
    bool sampled_ = false;
    std::uint64_t next_sample_ = 0;
};

}  // namespace alp85::debug
