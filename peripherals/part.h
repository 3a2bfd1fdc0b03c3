// A part of the board beside the CPU: a chip, the keypad, the machine tool. The Machine keeps
// its parts in one list; its scheduler, RESET and snapshots loop over that list, so a new part
// is added in one place (emu/board/machine.cpp, Machine::Machine) plus its wiring. The debugger's
// front ends show a part through its describe() alone.
//
// Time is the CPU's T-state count. A part catches up lazily when advance(now) is called (the
// machine calls it before every access, after every batch of instructions and before a snapshot)
// and tells the scheduler, through next_event(), the earliest T-state at which it would change
// something the CPU sees without being asked (an interrupt line, a pin the CPU does not poll).
// A part knows nothing of the board it sits on: the machine wires its pins.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "peripherals/state_io.h"
#include "peripherals/description.h"

namespace alp85::periph {

class Part {
public:
    static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();

    virtual ~Part() = default;

    // For the debugger and messages: "8155", "8279", "keypad", "machine tool".
    virtual std::string_view name() const = 0;
    // Its registers, fields and their meanings for every debugger front end (description.h);
    // a part without registers leaves it empty. Never changes the part.
    virtual void describe(Description& d) const { (void)d; }
    // Its pins' levels at `now` (not before now(): a lazy part computes what it can, the others
    // show their state at now()) for a logic analyzer (description.h, Pins); a part without pins
    // of interest gives none. Never changes the part.
    virtual void pins(Pins& p, std::uint64_t now) const { (void)p, (void)now; }
    // The next T-state after `now` at which a pin changes by itself without the CPU or a callback
    // telling the board (the 8279's scan lines): a recorder wakes there. kNever: none.
    virtual std::uint64_t next_pin_change(std::uint64_t now) const { (void)now; return kNever; }
    // The snapshot section that holds this part's state: exactly four characters, and the
    // version of that state's layout (bump it when the field list changes).
    virtual std::string_view tag() const = 0;
    virtual std::uint8_t state_version() const = 0;

    // RESET OUT of the CPU (power-on and the RESET key). Parts without a reset input ignore it.
    virtual void reset(std::uint64_t now) = 0;
    // Catches up to `now` (non-decreasing).
    virtual void advance(std::uint64_t now) = 0;
    virtual std::uint64_t next_event() const { return kNever; }
    // The T-state the part has caught up to (a snapshot requires it to equal the CPU's).
    virtual std::uint64_t now() const = 0;

    // The part's state, listed once (StateWriter / StateReader, peripherals/state_io.h). load_state
    // reads the whole record into a scratch state, checks r.expect_end() and the state's
    // invariants, and only then commits: on SnapshotError the part is unchanged.
    virtual void save_state(StateWriter& w) const = 0;
    virtual void load_state(StateReader& r) = 0;

    // The record as the machine's snapshot stores it: a header (the tag's first two characters
    // and the version, ByteWriter::header) and the fields.
    void save(std::vector<std::uint8_t>& out) const {
        StateWriter w(out);
        w.header(tag()[0], tag()[1], state_version());
        save_state(w);
    }
    void load(std::span<const std::uint8_t> in) {
        StateReader r(in, std::string(name()));
        r.expect_header(tag()[0], tag()[1], state_version());
        load_state(r);
    }
};

}  // namespace alp85::periph
