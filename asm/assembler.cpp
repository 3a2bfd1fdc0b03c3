// The pass driver: passes until symbol values settle, and line fetching from files and expansions.
#include <algorithm>

#include "asm/assembler.h"

namespace alp85::asm85 {
namespace {

constexpr int kMaxPasses = 10;
constexpr std::size_t kMaxExpandedLine = 4096;
constexpr std::size_t kMaxCharsPerPass = 32u << 20;

}  // namespace

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
    // Name the symbol that still moves, where it is defined (an IF or a DS that depends on a
    // later label, as a rule).
    Diagnostic d{Severity::Error, files_[static_cast<std::size_t>(main_file)].name, 0, 0,
                 "phase error: symbol values still change after " + std::to_string(kMaxPasses) + " passes", ""};
    if (auto it = syms_.find(changed_name_); it != syms_.end() && it->second.file >= 0) {
        const SourceFile& f = files_[static_cast<std::size_t>(it->second.file)];
        d.file = f.name;
        d.line = it->second.line;
        d.col = it->second.col;
        if (d.line >= 1 && static_cast<std::size_t>(d.line) <= f.lines.size()) d.source_line = f.lines[static_cast<std::size_t>(d.line - 1)];
        d.message = "phase error: the value of '" + changed_name_ + "' still changes after " + std::to_string(kMaxPasses) +
                    " passes (does an IF, DS or ORG before it depend on a later symbol?)";
    }
    diags_.push_back(std::move(d));
    return finish();
}

void Assembler::pass(int number, int main_file) {
    pass_ = number;
    changed_ = false;
    changed_name_.clear();
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
        if (n.empty() || !is_name_start(n[0]) || !std::all_of(n.begin(), n.end(), is_name_char)) {
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
    if (pass_ > 1 && !limit_reported_) report_circles();
    if (collect_.kind != Collect::None) {
        const SourceFile& f = files_[static_cast<std::size_t>(collect_.file)];
        diags_.push_back({Severity::Error, f.name, collect_.line, collect_.col, "missing ENDM for this block",
                          f.lines[static_cast<std::size_t>(collect_.line - 1)]});
    }
    for (auto& c : cond_)
        diags_.push_back({Severity::Error, files_[static_cast<std::size_t>(c.file)].name, c.line, c.col,
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
        if (++lines_this_pass_ > opt_.max_lines_per_pass || chars_this_pass_ > kMaxCharsPerPass) {
            if (!limit_reported_) {
                cur_line_ = &out;
                error(0, "more than " + std::to_string(opt_.max_lines_per_pass) +
                             " lines or 32 MB of text in one pass (runaway REPT or macro recursion?)");
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
    if (f.kind != FrameKind::File && f.cond_scope && cond_.size() > f.cond_depth) {
        // At the IF in the body that is still open, with the invocation as a note.
        const Cond& c = cond_[f.cond_depth];
        Line at;
        at.file = c.file;
        at.line = c.line;
        at.depth = 1;
        at.site_file = f.site_file;
        at.site_line = f.site_line;
        const SourceFile& src = files_[static_cast<std::size_t>(c.file)];
        if (c.line >= 1 && static_cast<std::size_t>(c.line) <= src.lines.size()) at.text = src.lines[static_cast<std::size_t>(c.line - 1)];
        const Line* saved = cur_line_;
        cur_line_ = &at;
        error(c.col - 1, "IF without ENDIF in the expansion of " + f.name);
        cur_line_ = saved;
        cond_.resize(f.cond_depth);
    }
    frames_.pop_back();
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
