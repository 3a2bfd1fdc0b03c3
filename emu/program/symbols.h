// The one table of what is known about the loaded programs: their symbols and the source line of
// every byte, from asm85's result or its JSON map ("alp85-asm-map", version 1), for the
// disassembler, the script language and the debugger; and disassembly of emulated memory with
// those symbols. The disassembler itself is asm85's
// (asm/disasm.h, over the shared opcode table); this is the thin layer that feeds it names.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "asm/asm85.h"

#include "asm/disasm.h"
#include "emu/core/bus.h"
#include "emu/core/i8085.h"

namespace alp85 {

// Where a byte came from: a source file and a 1-based line.
struct SourceLine {
    std::string file;
    int line = 0;
    friend bool operator==(const SourceLine&, const SourceLine&) = default;
};

class SymbolTable {
public:
    // Adds the symbols and source lines of an assembly, or of another table (a later definition
    // of a name wins).
    void add_assembly(const asm85::Result& result);
    void add_table(const SymbolTable& other);
    // Adds the symbols of one map (several maps may be loaded). Returns "" or an error message.
    std::string load_map_text(std::string_view json);
    std::string load_map_file(const std::string& path);
    // One symbol; kind is asm85's: "label", "equ" or "set" name addresses, others only values.
    void add(std::string_view name, std::uint16_t value, std::string_view kind);

    // The name for an address: a label if one is defined there, otherwise an EQU/SET name with
    // that value; the first defined wins among equals. nullopt if none.
    std::optional<std::string> name_at(std::uint16_t addr) const;
    // The name for a 16-bit immediate (LXI): a label, or an EQU/SET name only for values above
    // 00FFH, since small EQUs are usually 8-bit constants (KMODE EQU 0 would name LXI H,0).
    std::optional<std::string> data_name_at(std::uint16_t value) const;
    // The datum `value` is in, as gdb's info symbol names it: data_name_at's name, or "NAME+N"
    // from the nearest such name below (N < 256; sizes are not known, the next name ends it).
    std::optional<std::string> data_name_near(std::uint16_t value) const;
    // A label defined exactly here (for "LOOP:" lines in a listing).
    std::optional<std::string> label_at(std::uint16_t addr) const;
    // The name of code at `addr`: a label, or an entry point named by EQU/SET (a value above 00FFH
    // where a loaded line of code starts: ANWEIN EQU 0701H names the monitor's routine there,
    // while KMODE EQU 0 is a constant). nullopt if none.
    std::optional<std::string> code_name_at(std::uint16_t addr) const;
    // The routine `addr` is in, as a debugger names a location: "NAME" at a code name, "NAME+N"
    // when `addr` lies in the run of instructions that follows NAME (consecutive source lines of
    // at most 3 bytes each, no other name between), nullopt otherwise: an address in a data
    // table, a DS fill, or code without source lines gets no name rather than a far one.
    std::optional<std::string> routine_at(std::uint16_t addr) const;
    std::optional<std::uint16_t> value_of(std::string_view name) const;  // case-insensitive
    std::size_t size() const { return by_name_.size(); }
    bool empty() const { return by_name_.empty(); }
    const std::unordered_map<std::string, std::uint16_t>& names() const { return by_name_; }  // upper case

    // ---- source lines ----------------------------------------------------------------------------
    void add_line(std::uint16_t address, std::uint16_t length, const std::string& file, int line);
    // The source line of the byte at `addr` (the last loaded program wins where two overlap).
    std::optional<SourceLine> line_of(std::uint16_t addr) const;
    // The first address of every span that `file:line` produced; `file` matches a loaded file's
    // full name or its last component(s) ("thesis.asm" finds "/x/firmware/thesis/thesis.asm").
    std::vector<std::uint16_t> addresses_of(std::string_view file, int line) const;
    // The next line of `file` at or after `line` that produced code (a breakpoint on a comment
    // binds there), or nullopt.
    std::optional<SourceLine> next_line_with_code(std::string_view file, int line) const;
    // Every source file lines were added from, in load order (full names as loaded).
    const std::vector<std::string>& files() const { return files_; }

private:
    struct Span {
        std::uint16_t address, length;
        int file, line;
    };
    int file_index(const std::string& file);
    bool file_matches(int index, std::string_view file) const;

    std::map<std::uint16_t, std::string> labels_, equates_;
    std::unordered_map<std::string, std::uint16_t> by_name_;
    std::vector<std::string> files_;
    std::vector<Span> spans_;  // in load order
    // Address -> 1 + the index in spans_ of the last-loaded span covering it (0: none), so that
    // line_of answers at once: a debugger asks it at every stop and for every frame of a backtrace.
    std::vector<std::uint32_t> span_at_;
    std::map<std::uint16_t, std::uint16_t> starts_;  // the first address of each line -> its length (last load wins)
};

// One instruction at `addr`, as the given variant decodes it, with a16/d16 operands named from
// `symbols` (may be null). Reads memory with Bus::peek (no device side effects).
asm85::Disassembly disassemble(const Bus& bus, std::uint16_t addr, Variant variant,
                               const SymbolTable* symbols = nullptr);

}  // namespace alp85
