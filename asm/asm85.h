// asm85: the two-pass (repeated until stable) Intel 8080/8085 macro assembler of ALP85.
//
// It accepts the common form of three period dialects: Intel's ASM80 (ISIS), Digital Research's
// ASM/MAC (CP/M) and Microsoft's M80. See docs/asm85.md for the language.
//
// Use:
//     alp85::asm85::Options opt;            // cpu, defines, include dirs
//     auto r = alp85::asm85::assemble_file("prog.asm", opt);
//     for (auto& d : r.diagnostics) std::cerr << format_diagnostic(d);
//     if (r.ok()) write(write_intel_hex(r.image));
//
// Nothing here throws for bad input: every problem is a Diagnostic.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace alp85::asm85 {

enum class Cpu : std::uint8_t {
    i8080,   // rejects RIM, SIM and the undocumented 8085 instructions
    i8085,   // the documented 8085 set (default)
    i8085u,  // 8085 plus its ten undocumented instructions (DSUB, ARHL, ... JK/JX5)
};

// Parses "8080", "8085", "8085u" (case-insensitive).
std::optional<Cpu> parse_cpu(std::string_view text);

struct Options {
    Cpu cpu = Cpu::i8085;
    // NAME=VALUE pairs, defined before the first line as EQU symbols. VALUE is an expression;
    // an empty VALUE means 1.
    std::vector<std::pair<std::string, std::string>> defines;
    // Searched, in order, after the including file's own directory, for INCLUDE/MACLIB files.
    std::vector<std::filesystem::path> include_dirs;
    // Reads a file's text; nullopt when it cannot. Defaults to reading regular files from disk.
    std::function<std::optional<std::string>(const std::filesystem::path&)> read_file;
    bool warn_unused_macros = true;
    // Significant characters of a symbol name; 0 = all. Intel's ASM80 and M80 kept six, so a
    // source may define RESTART and use RESTAR: assemble such a source with 6.
    int name_length = 0;
    // A pass ends with an error after this many lines (expansions of macros and REPT counted) or
    // 32 MB of text: a runaway REPT or macro recursion stops instead of running for hours.
    std::size_t max_lines_per_pass = 1'000'000;
};

enum class Severity : std::uint8_t { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Error;
    std::string file;  // as named on the command line / in INCLUDE; empty when no source applies
    int line = 0;      // 1-based; 0 = no line
    int col = 0;       // 1-based character column; 0 = whole line
    std::string message;
    std::string source_line;  // the text of the line (macro expansion lines: as expanded)
};

// `file:line:col: error: message`, then the source line and a caret under the column.
std::string format_diagnostic(const Diagnostic& d);

// One contiguous run of emitted bytes.
struct Segment {
    std::uint16_t start = 0;
    std::vector<std::uint8_t> bytes;
    std::uint32_t end() const { return start + static_cast<std::uint32_t>(bytes.size()); }  // exclusive
};

// The sparse 64 KiB memory image an assembly produces.
class Image {
public:
    Image();
    // Stores a byte; returns false when the address already held one (an overlap).
    bool write(std::uint16_t address, std::uint8_t value);
    std::optional<std::uint8_t> read(std::uint16_t address) const;
    bool empty() const { return count_ == 0; }
    std::size_t size() const { return count_; }  // number of written bytes
    std::uint16_t lowest() const;                 // only when !empty()
    std::uint16_t highest() const;
    std::vector<Segment> segments() const;  // ascending, maximal runs
    std::optional<std::uint16_t> start_address;  // from END expr

private:
    std::vector<std::uint8_t> bytes_;  // 64 KiB once anything is written
    std::vector<bool> used_;
    std::size_t count_ = 0;
    std::uint16_t lo_ = 0, hi_ = 0;
};

enum class SymbolKind : std::uint8_t { Label, Equ, Set, Define };
std::string_view kind_name(SymbolKind k);  // "label", "equ", "set", "define"

struct Symbol {
    std::string name;  // upper case
    std::uint16_t value = 0;
    SymbolKind kind = SymbolKind::Label;
    int file = -1;  // index into Result::files; -1 for command-line defines
    int line = 0;
};

// `length` bytes from `address` came from source `file:line` (for macro expansions, the line of
// the outermost invocation in a real source file).
struct LineSpan {
    std::uint16_t address = 0;
    std::uint16_t length = 0;
    int file = 0;
    int line = 0;
};

// One line of the listing as assembled (source lines and macro expansion lines).
struct ListingLine {
    int file = 0;
    int line = 0;
    int expansion_depth = 0;  // 0: a source line; n: a line of a macro/REPT expansion, nesting n
    int include_depth = 0;
    std::string text;
    std::optional<std::uint16_t> address;  // LOC column
    std::optional<std::uint16_t> value;    // EQU/SET value shown instead of LOC
    std::vector<std::uint8_t> bytes;       // OBJ column
    bool skipped = false;                  // inside a false IF
};

struct Result {
    Image image;
    std::vector<Symbol> symbols;  // sorted by name
    std::vector<LineSpan> line_map;  // in emission order
    std::vector<Diagnostic> diagnostics;
    std::vector<std::string> files;  // index 0: the main source
    std::vector<ListingLine> listing;
    std::string title;  // from TITLE, when given
    int passes = 0;

    bool ok() const { return error_count() == 0; }
    int error_count() const;
    int warning_count() const;
    const Symbol* find_symbol(std::string_view name) const;  // case-insensitive
    const LineSpan* origin(std::uint16_t address) const;      // source of the byte at address
};

Result assemble_file(const std::filesystem::path& path, const Options& options = {});
Result assemble_string(std::string_view source, const Options& options = {},
                       std::string_view name = "<string>");

// Writers. Intel HEX: data records of `per_record` bytes at most, one run per segment, a type 03
// start-address record (CS=0, IP=start) when END named one, then the :00000001FF EOF record.
std::string write_intel_hex(const Image& image, int per_record = 16);
// Bytes [first, last] with gaps filled by `fill`.
std::vector<std::uint8_t> write_binary(const Image& image, std::uint16_t first, std::uint16_t last,
                                       std::uint8_t fill = 0xFF);
// How addresses count in the listing and the map: the 8085's bytes, or the words of another
// machine stored as `unit_bytes` bytes each in Result::image (the Pisa interpolator's 22-bit ROM
// words: three bytes at 3 x address; asm/pisa_asm.h). Listing LOC and map addresses are in units.
struct OutputFormat {
    std::string_view title = "asm85 8080/8085 MACRO ASSEMBLER";
    int unit_bytes = 1;         // bytes per addressed unit
    int obj_bytes = 4;          // OBJ column: bytes on the statement's line, the rest continue
    std::string_view unit;      // map: "unit" (empty: not written, bytes)
};
// The classic Intel listing: LOC OBJ LINE SOURCE STATEMENT, '+' on expansion lines, symbols after.
std::string write_listing(const Result& result, const OutputFormat& format = {});
// {"files":[...], "symbols":[{"name","value","kind","file","line"}], "lines":[{"address",
//  "length","file","line"}], "start":n|null} - the map the debugger reads.
std::string write_json_map(const Result& result, const OutputFormat& format = {});

}  // namespace alp85::asm85
