// The pass driver: line fetching from files and expansions, symbols, values and emission.
#include "asm/assembler.h"
#include "asm/instructions.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace alp85::asm85 {
namespace {

constexpr int kMaxPasses = 10;
constexpr int kMaxErrors = 1000;
constexpr std::size_t kMaxExpandedLine = 4096;
constexpr std::size_t kMaxCharsPerPass = 32u << 20;
constexpr std::size_t kMaxLinesPerPass = 1'000'000;  // bounds REPT/macro bombs
constexpr std::uintmax_t kMaxFileSize = 16u << 20;

std::optional<std::string> read_disk_file(const std::filesystem::path& p) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) return std::nullopt;
    auto size = std::filesystem::file_size(p, ec);
    if (ec || size > kMaxFileSize) return std::nullopt;
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::vector<std::string> split_lines(std::string_view text) {
    std::vector<std::string> lines;
    auto eof = text.find('\x1a');  // CP/M pads text files with ^Z after the end
    if (eof != std::string_view::npos) text = text.substr(0, eof);
    std::size_t start = 0;
    while (start < text.size()) {
        auto nl = text.find('\n', start);
        auto end = nl == std::string_view::npos ? text.size() : nl;
        std::string l(text.substr(start, end - start));
        if (!l.empty() && l.back() == '\r') l.pop_back();
        lines.push_back(std::move(l));
        if (nl == std::string_view::npos) break;
        start = nl + 1;
    }
    return lines;
}

}  // namespace

bool is_register_name(const std::string& n, int* value) {
    static const std::unordered_map<std::string, int> kRegs{
        {"B", 0}, {"C", 1}, {"D", 2}, {"E", 3}, {"H", 4}, {"L", 5},
        {"M", 6}, {"A", 7}, {"SP", 6}, {"PSW", 6}};
    auto it = kRegs.find(n);
    if (it == kRegs.end()) return false;
    if (value) *value = it->second;
    return true;
}

Assembler::Assembler(const Options& options) : opt_(options) {
    if (!opt_.read_file) opt_.read_file = read_disk_file;
}

int Assembler::load_file(const std::filesystem::path& path, const std::string& shown) {
    std::error_code ec;
    auto canon = std::filesystem::weakly_canonical(path, ec);
    std::string key = ec ? path.string() : canon.string();
    if (auto it = file_index_.find(key); it != file_index_.end()) return it->second;
    auto text = opt_.read_file(path);
    if (!text) return -1;
    files_.push_back({shown, path, split_lines(*text)});
    int idx = static_cast<int>(files_.size() - 1);
    file_index_[key] = idx;
    return idx;
}

std::optional<std::filesystem::path> Assembler::find_include(const std::string& name) const {
    std::vector<std::filesystem::path> dirs;
    if (cur_line_ && cur_line_->file >= 0 && cur_line_->file < static_cast<int>(files_.size()))
        dirs.push_back(files_[static_cast<std::size_t>(cur_line_->file)].path.parent_path());
    for (auto& d : opt_.include_dirs) dirs.push_back(d);
    dirs.emplace_back(".");
    std::filesystem::path p(name);
    if (p.is_absolute()) return p;
    for (auto& d : dirs) {
        auto cand = d / p;
        if (opt_.read_file(cand)) return cand;
        // Period sources name files in upper case on case-sensitive disks: try the other case.
        auto lower = d / std::filesystem::path(to_upper(name));
        if (opt_.read_file(lower)) return lower;
        std::string low = name;
        std::transform(low.begin(), low.end(), low.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (opt_.read_file(d / low)) return d / low;
    }
    return std::nullopt;
}

Result Assembler::run_file(const std::filesystem::path& path) {
    int idx = load_file(path, path.string());
    if (idx < 0) {
        Result r;
        r.diagnostics.push_back({Severity::Error, path.string(), 0, 0, "cannot read source file", ""});
        return r;
    }
    return run(idx);
}

Result Assembler::run_string(std::string_view text, std::string_view name) {
    files_.push_back({std::string(name), std::filesystem::path(), split_lines(text)});
    return run(0);
}

Result Assembler::run(int main_file) {
    for (int n = 1; n <= kMaxPasses; ++n) {
        pass(n, main_file);
        if (limit_reported_) return finish();  // runaway expansion: another pass won't help
        if (n >= 2 && !changed_) return finish();
    }
    diags_.push_back({Severity::Error, files_[static_cast<std::size_t>(main_file)].name, 0, 0,
                      "phase error: symbol values still change after " + std::to_string(kMaxPasses) + " passes", ""});
    return finish();
}

void Assembler::pass(int number, int main_file) {
    pass_ = number;
    changed_ = false;
    cpu_ = opt_.cpu;
    radix_ = 10;
    pc_ = 0;
    phase_ = 0;
    pc_overflow_reported_ = overlap_reported_ = ended_ = limit_reported_ = false;
    image_ = Image();
    line_map_.clear();
    diags_.clear();
    listing_.clear();
    title_.clear();
    macros_.clear();
    frames_.clear();
    cond_.clear();
    collect_ = Collect{};
    local_counter_ = 0;
    lines_this_pass_ = 0;
    chars_this_pass_ = 0;
    errors_this_pass_ = 0;
    comment_delim_.clear();
    cur_line_ = nullptr;

    Line cmdline;
    cmdline.file = -1;
    cur_line_ = &cmdline;
    for (auto& [name, value] : opt_.defines) {
        std::string n = to_upper(name);
        Value v{1, true};
        if (!value.empty()) {
            LexError le;
            auto toks = tokenize(value, le);
            if (!le.message.empty()) {
                error(0, "-D " + name + ": " + le.message);
                continue;
            }
            std::size_t p = 0;
            if (!expr(toks, p, v)) continue;
        }
        if (n.empty() || !is_name_start(n[0])) {
            error(0, "-D: '" + name + "' is not a valid name");
            continue;
        }
        define(n, 0, v.v, SymbolKind::Define);
    }

    Frame f;
    f.kind = FrameKind::File;
    f.file = main_file;
    frames_.push_back(std::move(f));
    Line line;
    while (!ended_ && fetch(line)) {
        cur_line_ = &line;
        process_line(line);
    }
    cur_line_ = nullptr;
    if (collect_.kind != Collect::None) {
        diags_.push_back({Severity::Error, files_[static_cast<std::size_t>(collect_.file)].name, collect_.line, 0,
                          "missing ENDM for this block", ""});
    }
    for (auto& c : cond_)
        diags_.push_back({Severity::Error, files_[static_cast<std::size_t>(c.file)].name, c.line, 0,
                          "IF without ENDIF", files_[static_cast<std::size_t>(c.file)].lines[static_cast<std::size_t>(c.line - 1)]});
    if (opt_.warn_unused_macros) {
        std::vector<const MacroDef*> unused;
        for (auto& [k, m] : macros_)
            if (!m.used) unused.push_back(&m);
        std::sort(unused.begin(), unused.end(), [](auto* a, auto* b) { return std::tie(a->file, a->line) < std::tie(b->file, b->line); });
        for (auto* m : unused)
            diags_.push_back({Severity::Warning, files_[static_cast<std::size_t>(m->file)].name, m->line, 0,
                              "macro '" + m->name + "' is defined but never used", ""});
    }
}

bool Assembler::fetch(Line& out) {
    while (!frames_.empty()) {
        Frame& f = frames_.back();
        if (f.kind == FrameKind::File) {
            auto& lines = files_[static_cast<std::size_t>(f.file)].lines;
            if (f.next >= lines.size()) {
                end_frame();
                continue;
            }
            out.text = lines[f.next];
            out.file = f.file;
            out.line = static_cast<int>(++f.next);
            out.depth = 0;
            out.site_file = out.file;
            out.site_line = out.line;
        } else {
            if (f.next >= f.body->size()) {
                f.next = 0;
                f.locals.clear();
                if (++f.iteration >= f.count || f.body->empty()) {
                    end_frame();
                    continue;
                }
            }
            if (f.body->empty()) {
                end_frame();
                continue;
            }
            const BodyLine& b = (*f.body)[f.next++];
            out.text = substitute(f, b.text);
            bool too_long = out.text.size() > kMaxExpandedLine;  // arguments that double per level
            if (too_long) out.text.resize(kMaxExpandedLine);
            out.file = b.file;
            out.line = b.line;
            out.depth = 0;
            for (auto& fr : frames_)
                if (fr.kind != FrameKind::File) ++out.depth;
            out.site_file = f.site_file;
            out.site_line = f.site_line;
            if (too_long) {
                cur_line_ = &out;
                error(0, "macro expansion line longer than " + std::to_string(kMaxExpandedLine) + " characters");
                out.text.clear();
            }
        }
        chars_this_pass_ += out.text.size();
        if (++lines_this_pass_ > kMaxLinesPerPass || chars_this_pass_ > kMaxCharsPerPass) {
            if (!limit_reported_) {
                cur_line_ = &out;
                error(0, "more than 1000000 lines or 32 MB of text in one pass (runaway REPT or macro recursion?)");
                limit_reported_ = true;
            }
            ended_ = true;
            return false;
        }
        return true;
    }
    return false;
}

void Assembler::end_frame() {
    Frame& f = frames_.back();
    if (f.kind != FrameKind::File && cond_.size() > f.cond_depth) {
        diags_.push_back({Severity::Error, files_[static_cast<std::size_t>(f.site_file)].name, f.site_line, 0,
                          "IF without ENDIF in the expansion of " + f.name, ""});
        cond_.resize(f.cond_depth);
    }
    frames_.pop_back();
}

void Assembler::diag(Severity s, int col, const std::string& msg) {
    if (limit_reported_) return;
    if (s == Severity::Error && ++errors_this_pass_ > kMaxErrors) {
        diags_.push_back({Severity::Error, "", 0, 0, "too many errors; assembly stopped", ""});
        limit_reported_ = true;
        ended_ = true;
        return;
    }
    Diagnostic d;
    d.severity = s;
    d.message = msg;
    if (cur_line_ && cur_line_->file >= 0) {
        d.file = files_[static_cast<std::size_t>(cur_line_->file)].name;
        d.line = cur_line_->line;
        d.col = col + 1;
        d.source_line = cur_line_->text;
    }
    diags_.push_back(std::move(d));
    if (cur_line_ && cur_line_->depth > 0 && cur_line_->site_file >= 0) {
        const SourceFile& sf = files_[static_cast<std::size_t>(cur_line_->site_file)];
        Diagnostic n;
        n.severity = Severity::Note;
        n.file = sf.name;
        n.line = cur_line_->site_line;
        n.message = "in the expansion invoked here";
        if (cur_line_->site_line >= 1 && static_cast<std::size_t>(cur_line_->site_line) <= sf.lines.size())
            n.source_line = sf.lines[static_cast<std::size_t>(cur_line_->site_line - 1)];
        diags_.push_back(std::move(n));
    }
}

Value Assembler::lookup(const Token& t, bool registers) {
    // As in ASM80 and DR ASM, register names are predefined symbols (B=0 ... A=7, SP=PSW=6) in
    // every expression: `UR EQU B` then `MOV UR,A` is period practice.
    (void)registers;
    int rv = 0;
    if (is_register_name(t.text, &rv)) return {static_cast<std::uint16_t>(rv), true};
    auto it = syms_.find(key(t.text));
    if (it != syms_.end() && it->second.pass >= pass_ - 1) return {it->second.value, true};
    if (pass_ > 1) {
        error(t.col, "undefined symbol '" + t.text + "'");
    }
    return {0, false};
}

bool Assembler::expr(const std::vector<Token>& toks, std::size_t& pos, Value& out, bool registers) {
    ExprContext ctx;
    ctx.pc = loc();
    ctx.lookup = [this, registers](const Token& t) { return lookup(t, registers); };
    ctx.error = [this](int col, const std::string& m) { error(col, m); };
    ctx.is_mnemonic = [this](const std::string& w) { return find_mnemonic(w) != nullptr && syms_.count(w) == 0; };
    ctx.instruction = [this, &toks](std::size_t first, std::size_t last) { return instruction_value(toks, first, last); };
    return eval_expr(toks, pos, ctx, out);
}

bool Assembler::expr_all(const std::vector<Token>& toks, std::size_t pos, Value& out) {
    if (!expr(toks, pos, out)) return false;
    if (toks[pos].kind != Tok::End) {
        error(toks[pos].col, "unexpected ',' after expression");
        return false;
    }
    return true;
}

void Assembler::define(const std::string& full_name, int col, std::uint16_t value, SymbolKind kind) {
    const std::string name = key(full_name);
    if (is_operator_word(name)) {
        error(col, "'" + name + "' is an operator and can't be a symbol");
        return;
    }
    if (is_register_name(name)) {
        error(col, "'" + name + "' is a register name and can't be a symbol");
        return;
    }
    auto [it, inserted] = syms_.try_emplace(name);
    SymEntry& e = it->second;
    int file = cur_line_ ? cur_line_->file : -1;
    int line = cur_line_ ? cur_line_->line : 0;
    if (!inserted && e.pass == pass_) {
        if (e.kind == SymbolKind::Define && kind != SymbolKind::Define) {
            if (e.value != value)
                warning(col, fmt::format("'{}' is set on the command line to {:04X}H; this definition ({:04X}H) is ignored", name, e.value, value));
            return;
        }
        if (kind == SymbolKind::Equ && e.kind == SymbolKind::Equ && e.value == value) return;  // ASM80 allows
        if (kind == SymbolKind::Set && e.kind == SymbolKind::Set) {
            e.value = value;
            e.file = file;
            e.line = line;
            return;
        }
        std::string where = e.file >= 0 ? fmt::format(" (first defined at {}:{})", files_[static_cast<std::size_t>(e.file)].name, e.line) : "";
        error(col, "'" + name + "' is already defined" + where);
        return;
    }
    if (inserted || e.pass < pass_ - 1) {
        if (pass_ > 1) changed_ = true;
    } else if (kind != SymbolKind::Set && e.value != value) {
        changed_ = true;
    }
    e = {value, kind, pass_, file, line};
}

std::uint8_t Assembler::byte_of(const Value& v, int col) {
    if (v.known && (v.v & 0xFF00) != 0 && (v.v & 0xFF00) != 0xFF00)
        warning(col, fmt::format("value {:04X}H truncated to byte {:02X}H", v.v, v.v & 0xFF));
    return static_cast<std::uint8_t>(v.v & 0xFF);
}

void Assembler::emit(std::uint8_t b) {
    if (pc_ > 0xFFFF) {
        if (!pc_overflow_reported_) error(op_col_, "code beyond address 0FFFFH");
        pc_overflow_reported_ = true;
        ++pc_;
        return;
    }
    auto addr = static_cast<std::uint16_t>(pc_);
    if (!image_.write(addr, b) && !overlap_reported_) {
        warning(op_col_, fmt::format("overlapping ORG regions: address {:04X}H is written twice", addr));
        overlap_reported_ = true;
    }
    if (!listing_.empty()) {
        auto& ll = listing_.back();
        if (ll.bytes.empty() && !ll.address) ll.address = loc();  // the run address under .PHASE
        ll.bytes.push_back(b);
    }
    if (cur_line_) {
        if (!line_map_.empty()) {
            LineSpan& s = line_map_.back();
            if (s.file == cur_line_->site_file && s.line == cur_line_->site_line && s.address + s.length == addr &&
                s.length < 0xFFFF) {
                ++s.length;
                ++pc_;
                return;
            }
        }
        line_map_.push_back({addr, 1, cur_line_->site_file, cur_line_->site_line});
    }
    ++pc_;
}

void Assembler::emit_word(std::uint16_t w) {
    emit(static_cast<std::uint8_t>(w & 0xFF));
    emit(static_cast<std::uint8_t>(w >> 8));
}

Result Assembler::finish() {
    Result r;
    r.image = std::move(image_);
    r.line_map = std::move(line_map_);
    r.diagnostics = std::move(diags_);
    r.listing = std::move(listing_);
    r.title = title_;
    r.passes = pass_;
    for (auto& f : files_) r.files.push_back(f.name);
    for (auto& [name, e] : syms_)
        if (e.pass == pass_) r.symbols.push_back({name, e.value, e.kind, e.file, e.line});
    std::sort(r.symbols.begin(), r.symbols.end(), [](const Symbol& a, const Symbol& b) { return a.name < b.name; });
    return r;
}

Result assemble_file(const std::filesystem::path& path, const Options& options) {
    Assembler a(options);
    return a.run_file(path);
}

Result assemble_string(std::string_view source, const Options& options, std::string_view name) {
    Assembler a(options);
    return a.run_string(source, name);
}

}  // namespace alp85::asm85
