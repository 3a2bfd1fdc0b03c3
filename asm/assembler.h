// The assembler's internal state and passes. Public entry points are in asm85.h.
//
// Each pass reads the source from the top, expanding macros and conditionals; symbol values of
// the previous pass answer forward references. Passes repeat until no symbol value changes
// (two for ordinary sources), and the last pass alone provides the output and the diagnostics.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "asm/asm85.h"
#include "asm/expr.h"
#include "asm/lexer.h"

namespace alp85::asm85 {

struct SourceFile {
    std::string name;  // as shown in diagnostics
    std::filesystem::path path;
    std::vector<std::string> lines;
};

struct BodyLine {
    std::string text;
    int file = 0;
    int line = 0;
};

struct MacroDef {
    std::string name;
    std::vector<std::string> params;  // upper case
    std::shared_ptr<std::vector<BodyLine>> body;
    int file = 0;
    int line = 0;
    bool used = false;
};

enum class FrameKind : std::uint8_t { File, Macro, Repeat };

// A source of lines: a file, or one macro/REPT/IRP/IRPC expansion.
struct Frame {
    FrameKind kind = FrameKind::File;
    int file = 0;
    std::size_t next = 0;
    std::shared_ptr<std::vector<BodyLine>> body;
    std::vector<std::string> params;
    std::vector<std::vector<std::string>> args;  // per iteration (Macro: one; IRP/IRPC: one per item)
    std::size_t iteration = 0;
    std::size_t count = 0;  // iterations
    std::vector<std::pair<std::string, std::string>> locals;
    std::size_t cond_depth = 0;  // IFs open when the expansion began
    // An IF opened in the expansion must end in it, and ELSE/ENDIF can't reach an IF opened outside
    // (ASM80's rule); not for the rest of a '!' line run after a macro, which is the line's own.
    bool cond_scope = true;
    int site_file = 0;  // outermost invocation in a real file
    int site_line = 0;
    std::string name;
};

// A line as fetched for assembly.
struct Line {
    std::string text;
    int file = 0;
    int line = 0;
    int depth = 0;  // expansion depth
    int site_file = 0;
    int site_line = 0;
};

struct SymEntry {
    std::uint16_t value = 0;
    SymbolKind kind = SymbolKind::Label;
    int pass = 0;  // last pass that defined it
    int file = -1;
    int line = 0;
    int col = 0;   // 1-based, of the name
    // EQU/SET: false while the value rests on a symbol not known yet (a forward reference still
    // settling, an undefined symbol or a circle); deps are the symbols its expression read.
    bool known = true;
    std::vector<std::string> deps;
};

struct Cond {
    bool parent_active = true;
    bool active = true;
    bool taken = false;  // some branch of this IF was taken
    bool in_else = false;
    int file = 0;
    int line = 0;
    int col = 0;  // 1-based, of the IF word
};

// A block being collected: MACRO, REPT, IRP or IRPC up to its ENDM.
struct Collect {
    enum Kind : std::uint8_t { None, Macro, Rept, Irp, Irpc } kind = None;
    MacroDef def;
    int depth = 0;
    std::size_t count = 0;
    std::vector<std::vector<std::string>> args;
    int file = 0, line = 0, col = 0;  // col: 1-based, of the MACRO/REPT/IRP/IRPC word
};

class Assembler {
public:
    explicit Assembler(const Options& options);
    Result run_file(const std::filesystem::path& path);
    Result run_string(std::string_view text, std::string_view name);

private:
    // --- driver (assembler.cpp; files in sources.cpp)
    Result run(int main_file);
    void pass(int number, int main_file);
    bool fetch(Line& out);
    void end_frame();
    int load_file(const std::filesystem::path& path, const std::string& shown);
    std::optional<std::filesystem::path> find_include(const std::string& name) const;
    Result finish();

    // --- statements (statement.cpp)
    void process_line(const Line& line);
    void process_statement(const std::vector<Token>& toks, const Line& line);
    void control_line(const std::string& text);  // '$' in column 1 (ASM80 controls)
    bool is_op_word(const std::string& w) const;
    void collect_line(const Line& line);

    // --- diagnostics and values (values.cpp)
    void diag(Severity s, int col, const std::string& msg);
    void error(int col, const std::string& msg) { diag(Severity::Error, col, msg); }
    void warning(int col, const std::string& msg) { diag(Severity::Warning, col, msg); }
    Value lookup(const Token& t, bool registers);
    bool expr(const std::vector<Token>& toks, std::size_t& pos, Value& out, bool registers = false);
    bool expr_all(const std::vector<Token>& toks, std::size_t pos, Value& out);  // whole operand field
    void define(const std::string& name, int col, std::uint16_t value, SymbolKind kind, bool known = true,
                std::vector<std::string> deps = {});
    void report_circles();  // EQU/SET symbols whose definitions lead back to themselves
    std::uint8_t byte_of(const Value& v, int col);
    void emit(std::uint8_t b);
    void emit_word(std::uint16_t w);

    // --- instructions (instructions.cpp)
    bool try_instruction(const std::string& op, const Token& optok, const std::vector<Token>& toks, std::size_t p);
    bool encode_instruction(const std::string& op, const Token& optok, const std::vector<Token>& toks, std::size_t p,
                            std::vector<std::uint8_t>& out);
    // ASM80: "(JMP X)" in an expression is the instruction's first byte. toks[first] is the mnemonic,
    // toks[last] the closing parenthesis.
    std::string key(const std::string& name) const {
        return opt_.name_length > 0 && name.size() > static_cast<std::size_t>(opt_.name_length)
                   ? name.substr(0, static_cast<std::size_t>(opt_.name_length)) : name;
    }
    Value instruction_value(const std::vector<Token>& toks, std::size_t first, std::size_t last);

    // --- directives (directives.cpp, conditionals.cpp)
    bool try_directive(const std::string& op, const std::vector<Token>& toks, std::size_t p,
                       const std::string& name, int name_col, const Line& line);
    void conditional(const std::string& op, const std::vector<Token>& toks, std::size_t p, const Line& line);
    bool skipping() const { return !cond_.empty() && !cond_.back().active; }
    void do_include(const std::string& name, int col);
    void data_bytes(const std::vector<Token>& toks, std::size_t p, bool high_bit_last);

    // --- macros (macros.cpp)
    void begin_collect(Collect::Kind kind, const std::vector<Token>& toks, std::size_t p,
                       const std::string& name, const Line& line);
    void finish_collect();
    void call_macro(MacroDef& m, const Line& line, int args_col, int args_end);
    std::string substitute(const Frame& f, const std::string& text) const;
    void exitm();
    void add_locals(const std::vector<Token>& toks, std::size_t p);

public:
    // Splits a macro argument list (raw text) at top-level commas; <...> groups, quotes kept.
    static std::vector<std::string> split_args(std::string_view text);

private:
    Options opt_;
    std::vector<SourceFile> files_;
    std::unordered_map<std::string, int> file_index_;

    // pass state
    int pass_ = 0;
    bool changed_ = false;
    std::string changed_name_;  // the first symbol whose value changed this pass (for a phase error)
    std::vector<std::string>* refs_ = nullptr;  // collects the symbols an EQU/SET expression reads
    Cpu cpu_ = Cpu::i8085;
    int radix_ = 10;
    std::uint32_t pc_ = 0;     // where the next byte is stored
    std::int32_t phase_ = 0;   // M80 .PHASE: the address code runs at, minus pc_
    std::uint16_t loc() const { return static_cast<std::uint16_t>((static_cast<std::int64_t>(pc_) + phase_) & 0xFFFF); }
    bool pc_overflow_reported_ = false;
    bool overlap_reported_ = false;
    bool ended_ = false;
    Image image_;
    std::vector<LineSpan> line_map_;
    std::vector<Diagnostic> diags_;
    std::vector<ListingLine> listing_;
    std::string title_;
    std::unordered_map<std::string, SymEntry> syms_;
    std::unordered_map<std::string, MacroDef> macros_;
    std::vector<Frame> frames_;
    std::vector<Cond> cond_;
    Collect collect_;
    int local_counter_ = 0;
    std::size_t lines_this_pass_ = 0;
    std::size_t chars_this_pass_ = 0;
    bool limit_reported_ = false;  // a resource limit stopped this pass (no further passes)
    int errors_this_pass_ = 0;
    std::string comment_delim_;  // inside M80 .COMMENT until this character
    const Line* cur_line_ = nullptr;
    std::string cur_text_;  // the current line as tokenized (for diagnostics)
    int op_col_ = 0;
    int insn_depth_ = 0;  // nesting of "(instruction)" values  // column of the current statement's operation, for emission warnings
};

bool is_register_name(const std::string& upper, int* value = nullptr);
std::vector<std::string> split_lines(std::string_view text);  // CR LF or LF; stops at ^Z
// A regular file's text (up to 16 MB); nullopt when it cannot be read.
std::optional<std::string> read_disk_file(const std::filesystem::path& p);
std::string trim(std::string_view s);        // without leading/trailing blanks
std::string strip_angle(std::string s);      // trimmed, without one enclosing <...>
bool is_directive_word(const std::string& upper);    // ORG, DB, ... (not the IF family)
bool is_conditional_word(const std::string& upper);  // IF, IFDEF, ..., ELSE, ENDIF, ENDC

}  // namespace alp85::asm85
