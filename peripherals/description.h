// What a part shows a debugger: its registers, their bit fields and what they mean, as one small
// tree of named values (in the manner of MAME's device state: the part owns the list, front ends
// render it). The console's `info PART`, the GUI's chip pane, DAP's scopes and `watch PART NAME`
// all read it, so a part with registers needs no front-end code of its own.
//
//   void describe(Description& d) const override {
//       d.title = "8155 (RAM-I/O-timer)";
//       Field& cmd = d.add(Field::hex("command", s_.command, 8));
//       cmd.add(Field::bits("port C", s_.command, 2, 2, "ALT3 (port A strobed)"));
//       cmd.text = summary(cmd.fields);          // "port A out, port B in, port C ALT3 (...)"
//   }
//
// Building one reads the part's state only: describing never changes a device.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace alp85::periph {

struct Field {
    enum class Shown : std::uint8_t {
        Hex,      // 0DH (width bits: 2 digits up to 8, 4 up to 16)
        Bits,     // 01 (width binary digits): a bit field
        Decimal,  // 12; width 0: a signed quantity (steps, lost steps), else an unsigned count
        Text,     // no number: `text` is the value ("physical", "4 steps, 0.200 mm")
    };

    std::string name;        // "command", "port C", "FIFO count", "3"
    std::int64_t value = 0;  // the raw number (what a watchpoint compares)
    int width = 8;           // bits
    int lsb = -1;            // a bit field: its lowest bit in the parent register; -1: not one
    Shown shown = Shown::Hex;
    std::string text;        // what the value means: "ALT3 (port A strobed)", "FIFO 1 entry"
    std::string watch;       // its name for `watch PART NAME` ("porta"); empty: not watchable
    std::vector<Field> fields;  // bit fields, entries (FIFO, display RAM) or quantities (an axis)

    static Field hex(std::string name, std::int64_t value, int width, std::string text = {});
    // Bits lsb+width-1..lsb of `reg`.
    static Field bits(std::string name, std::int64_t reg, int lsb, int width, std::string text = {});
    static Field flag(std::string name, bool set, int bit, std::string text_when_set = {});
    static Field decimal(std::string name, std::int64_t value, int width = 0, std::string text = {});
    static Field note(std::string name, std::string text);

    Field& add(Field f) {
        fields.push_back(std::move(f));
        return fields.back();
    }
    Field& watched_as(std::string w) {
        watch = std::move(w);
        return *this;
    }
    // The number as shown: "0DH", "01", "-100"; empty for Shown::Text.
    std::string number() const;
    // For a bit field: "bit 4", "bits 3-2"; empty otherwise.
    std::string bit_range() const;
    // The value as every front end shows it: "0DH: port A out, port B in", "bits 3-2 = 01: ALT3
    // (port A strobed, PC3-5 output)", "-100", "physical".
    std::string shown_value() const;
    // Hex digits a watch message shows its old and new values with (0: a signed decimal).
    int digits() const { return shown == Shown::Decimal && width == 0 ? 0 : width <= 8 ? 2 : 4; }
};

struct Description {
    std::uint64_t now = 0;      // the T-state looked at (the machine's: a part may lag behind it)
    std::string title;          // one line about the part: "8279 (keyboard/display)"
    std::vector<Field> fields;  // its registers and quantities, in the order shown

    Field& add(Field f) {
        fields.push_back(std::move(f));
        return fields.back();
    }
    // The field `watch PART NAME` names (case-insensitive), searched through the whole tree.
    const Field* find_watch(std::string_view watch) const;
    // Every watchable name, in order (for messages).
    std::vector<std::string> watch_names() const;
    bool empty() const { return title.empty() && fields.empty(); }
};

// "name text, name text" of the fields that have a text: a register's meaning from its fields'.
std::string summary(const std::vector<Field>& fields);

}  // namespace alp85::periph

namespace alp85::periph {

// What a part shows a logic analyzer: the levels on its pins and the quantities an oscilloscope
// would measure (Part::pins). The names and their order are the part's and never change, so a
// recorder reads the names once (naming()) and afterwards only the values, with no allocation:
// levels() is called with the same names in the same order every time.
class Pins {
public:
    enum class Kind : std::uint8_t {
        Logic,  // a digital pin: '0', '1' or 'z' (not driven: an input, or a port line set as input)
        Real,   // a quantity: a winding current in A, a rotor angle in degrees
    };
    struct Pin {
        std::string scope;  // the part: "8155", "X" (an axis of the machine tool)
        std::string name;   // "PA0", "TIMER_OUT", "PULSE" (no spaces: a VCD identifier)
        Kind kind = Kind::Logic;
        bool exact = true;  // its changes are seen at their T-state; false: at the sample clock
    };

    // The first call of a part's pins() lists the names; later ones only give values.
    bool naming() const { return naming_; }
    void set_naming(bool on) {
        naming_ = on;
        at_ = 0;
    }
    void scope(std::string_view s) { scope_ = s; }
    void logic(std::string_view name, bool level, bool exact = true) { put(name, Kind::Logic, level ? '1' : '0', 0, exact); }
    void undriven(std::string_view name, bool exact = true) { put(name, Kind::Logic, 'z', 0, exact); }
    void real(std::string_view name, double value, bool exact = false) { put(name, Kind::Real, 0, value, exact); }

    const std::vector<Pin>& list() const { return pins_; }
    const std::vector<char>& levels() const { return levels_; }  // per pin: '0', '1', 'z' (Real: unused)
    const std::vector<double>& reals() const { return reals_; }  // per pin (Logic: unused)
    std::size_t size() const { return pins_.size(); }

private:
    void put(std::string_view name, Kind kind, char level, double value, bool exact) {
        if (naming_) {
            pins_.push_back({std::string(scope_), std::string(name), kind, exact});
            levels_.push_back(level);
            reals_.push_back(value);
            return;
        }
        levels_[at_] = level;
        reals_[at_] = value;
        ++at_;
    }

    bool naming_ = true;
    std::size_t at_ = 0;
    std::string_view scope_;
    std::vector<Pin> pins_;
    std::vector<char> levels_;
    std::vector<double> reals_;
};

}  // namespace alp85::periph
