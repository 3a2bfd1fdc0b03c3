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
