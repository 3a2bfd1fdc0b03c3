// The console's frame commands, as gdb has them: frame N, up, down (a frame of the backtrace
// selected for looking), jump, and info symbol.
#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "emu/debug/console.h"
#include "emu/util/text.h"

namespace alp85::debug {

std::string Console::show_frame(std::size_t n) {
    const auto frames = d_.backtrace();
    if (n >= frames.size()) return error(1, "no such frame");
    const Frame& f = frames[n];
    frame_line_ = f.line;  // list shows the selected frame's source, as gdb's
    next_list_.reset();
    std::string out = fmt::format("#{:<2} {} in {}", n, hex4h(f.pc), f.routine ? *f.routine : "??");
    if (f.line) out += fmt::format(" at {}:{}", std::filesystem::path(f.line->file).filename().string(), f.line->line);
    out += '\n';
    const auto src = f.line ? source_line(*f.line) : std::nullopt;
    if (src)
        out += fmt::format("{}\t{}\n", f.line->line, *src);
    else
        out += fmt::format("{}\t{}\n", hex4h(f.pc), disassemble(d_.machine().bus(), f.pc, d_.machine().cpu().variant(), &d_.program()).text);
    return out;
}

std::string Console::cmd_frame(std::string_view a, int col) {
    if (!a.empty()) {
        const auto n = parse_int(trim_blanks(a));
        if (!n || *n < 0) return error(col, fmt::format("bad frame number '{}'", a));
        const auto frames = d_.backtrace();
        if (static_cast<std::size_t>(*n) >= frames.size())
            return error(col, fmt::format("no frame {}: the backtrace has {} (0-{})", *n, frames.size(), frames.size() - 1));
        selected_frame_ = static_cast<std::size_t>(*n);
    }
    return show_frame(selected_frame_);
}

// up N / down N: how many frames (default 1), or an error already formatted.
std::optional<std::size_t> Console::frame_count(std::string_view a, int col, std::string& err) {
    if (a.empty()) return 1;
    const auto v = number_arg(a, col, err);
    if (!v) return std::nullopt;
    return static_cast<std::size_t>(*v);
}

std::string Console::cmd_up(std::string_view a, int col) {
    std::string err;
    const auto n = frame_count(a, col, err);
    if (!n) return err;
    const auto frames = d_.backtrace();
    if (selected_frame_ + 1 >= frames.size()) return error(col, "Initial frame selected; you cannot go up.");
    selected_frame_ = std::min(selected_frame_ + *n, frames.size() - 1);
    return show_frame(selected_frame_);
}

std::string Console::cmd_down(std::string_view a, int col) {
    std::string err;
    const auto n = frame_count(a, col, err);
    if (!n) return err;
    if (selected_frame_ == 0) return error(col, "Bottom (innermost) frame selected; you cannot go down.");
    selected_frame_ = selected_frame_ > *n ? selected_frame_ - *n : 0;
    return show_frame(selected_frame_);
}

std::string Console::cmd_jump(std::string_view a, int col) {
    if (a.empty()) return error(col, "expected a location: jump LOCATION");
    const auto loc = d_.locate(a);
    if (!loc.error.empty()) return error(col + std::max(loc.col, 1) - 1, loc.error);
    const std::uint16_t to = loc.addresses.front();
    d_.machine().cpu().regs().pc = to;
    d_.state_changed();  // the timeline changes here: history after now is another run's
    const auto name = d_.program().routine_at(to);
    return fmt::format("Continuing at {}{}.\n", hex4h(to), name ? fmt::format(" ({})", *name) : "") + report(d_.cont());
}

// info symbol ADDR: the name that holds ADDR, as gdb says it ("ANWEIN + 3").
std::string Console::info_symbol(std::string_view a, int col) {
    if (a.empty()) return error(col, "expected an address: info symbol ADDR");
    std::int64_t v = 0;
    if (std::string e = address(a, col, v); !e.empty()) return e;
    const auto addr = static_cast<std::uint16_t>(v);
    std::optional<std::string> name = d_.program().routine_at(addr);
    if (!name) name = d_.program().data_name_near(addr);  // YAC + 1: the high byte of the word YAC
    if (!name) return fmt::format("No symbol matches {}.\n", a);
    if (const auto plus = name->find('+'); plus != std::string::npos) name->replace(plus, 1, " + ");
    const auto line = d_.program().line_of(addr);
    return fmt::format("{}{}\n", *name,
                       line ? fmt::format(" at {}:{}", std::filesystem::path(line->file).filename().string(), line->line) : "");
}

}  // namespace alp85::debug
