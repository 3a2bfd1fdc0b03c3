#include "emu/gui/debug_panes.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "emu/gui/controls.h"
#include "emu/gui/layout.h"

namespace alp85::gui {

namespace {
ImU32 rgb(Rgb c) { return IM_COL32(c.r, c.g, c.b, 255); }
constexpr ImGuiWindowFlags kPane = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings;
void begin_pane(const char* title, const Rect& r) {
    ImGui::SetNextWindowPos({r.x, r.y});
    ImGui::SetNextWindowSize({r.w, r.h});
    ImGui::Begin(title, nullptr, kPane);
}
// A pane the user can resize (by its edges and corners): placed in its rect the first time only.
void begin_resizable_pane(const char* title, const Rect& r, ImGuiWindowFlags extra = 0) {
    ImGui::SetNextWindowPos({r.x, r.y}, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize({r.w, r.h}, ImGuiCond_FirstUseEver);
    ImGui::Begin(title, nullptr, (kPane & ~ImGuiWindowFlags_NoResize) | extra);
}
// The words of a line: the command (without a /FMT) and its first argument.
std::pair<std::string_view, std::string_view> first_words(std::string_view line) {
    const auto word = [&line] {
        const auto b = line.find_first_not_of(" \t");
        if (b == std::string_view::npos) return std::string_view{};
        line.remove_prefix(b);
        const auto e = std::min(line.find_first_of(" \t"), line.size());
        const std::string_view w = line.substr(0, e);
        line.remove_prefix(e);
        return w;
    };
    std::string_view cmd = word();
    cmd = cmd.substr(0, cmd.find('/'));
    return {cmd, word()};
}
bool prefix_of(std::string_view word, std::string_view full, std::size_t least) {
    return word.size() >= least && full.starts_with(word);
}
// The last item's place, for the test hooks' clicks (click:NAME).
void remember_item(const std::string& name) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    drawn_buttons()[name] = {a.x, a.y, b.x, b.y};
}
}  // namespace

bool runs_while_running(std::string_view line) {
    const auto [cmd, arg] = first_words(line);
    // list only reads the source: it runs too, and the source pane follows it.
    for (std::string_view w : {"break", "b", "br", "brea", "tbreak", "tb", "watch", "wa", "rwatch", "rw", "awatch", "aw", "display", "disp",
                               "list", "l"})
        if (cmd == w) return true;
    if (cmd == "info" || cmd == "i")
        return prefix_of(arg, "breakpoints", 1) || prefix_of(arg, "watchpoints", 2) || prefix_of(arg, "displays", 4);
    return false;
}

Typed run_typed(DebugPanes& p, script::DebugShell& shell, const std::string& line, bool running) {
    p.add_log("(alp85) " + line);
    Typed t;
    if (running && !runs_while_running(line)) {
        t.out = "The machine is running: pause first (Pause), then the command runs as typed.\n";
    } else {
        t.out = shell.execute(line);
        t.ran = true;
        if (const auto l = list_target(p, shell, line)) p.show_chosen(*l);
    }
    p.add_log(t.out);
    p.last_t = ~0ull;  // refresh the panes
    return t;
}

void DebugPanes::add_log(const std::string& text) {
    std::size_t start = 0;
    while (start < text.size()) {
        const auto nl = text.find('\n', start);
        log.push_back(text.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
        if (nl == std::string::npos) break;
        start = nl + 1;
    }
    while (log.size() > 400) log.pop_front();
}

void DebugPanes::show_chosen(const SourceLine& l) {
    file = l.file;
    first = std::max(1, l.line - kSourceRows / 2);
    pinned = true;
}

std::optional<SourceLine> list_target(const DebugPanes& p, script::DebugShell& shell, std::string_view line) {
    const auto [cmd, arg_word] = first_words(line);
    if (cmd != "list" && cmd != "l") return std::nullopt;
    const auto b = line.find(arg_word);
    std::string_view arg = arg_word.empty() ? arg_word : line.substr(b);
    arg = arg.substr(0, arg.find(','));  // a range: its first line
    while (!arg.empty() && (arg.back() == ' ' || arg.back() == '\t')) arg.remove_suffix(1);
    if (arg.empty()) return std::nullopt;
    const auto number = [](std::string_view t) -> std::optional<int> {
        if (t.empty() || t.size() > 6 || !std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; })) return std::nullopt;
        return std::stoi(std::string(t));
    };
    const SymbolTable& program = shell.debugger().program();
    if (const auto colon = arg.rfind(':'); colon != std::string_view::npos) {  // FILE:LINE
        const auto n = number(arg.substr(colon + 1));
        const std::string_view name = arg.substr(0, colon);
        if (!n) return std::nullopt;
        for (const std::string& f : program.files())
            if (f == name || (f.size() > name.size() && f.ends_with(name) && f[f.size() - name.size() - 1] == '/')) return SourceLine{f, *n};
        return std::nullopt;
    }
    if (const auto n = number(arg)) {  // a line of the file shown
        if (p.file.empty()) return std::nullopt;
        return SourceLine{p.file, *n};
    }
    const auto v = shell.debugger().evaluate(std::string(arg));  // a symbol or an address
    if (!v.error.empty()) return std::nullopt;
    return program.line_of(static_cast<std::uint16_t>(v.value));
}

std::optional<SourceLine> DebugPanes::line_in_row(int row) const {
    if (file.empty() || row < 0 || row >= kSourceRows) return std::nullopt;
    return SourceLine{file, first + row};
}

void DebugPanes::show(const SourceLine& l) {
    if (l.file != file || l.line < first + 2 || l.line >= first + kSourceRows - 2) {
        file = l.file;
        first = std::max(1, l.line - kSourceRows / 2);
    }
}

void toggle_breakpoint(DebugPanes& p, script::DebugShell& shell, int row) {
    const auto l = p.line_in_row(row);
    if (!l) return;
    debug::Debugger& d = shell.debugger();
    // A line with a breakpoint: delete it; otherwise set one (a line without code binds to the next).
    for (const auto& b : d.breakpoints()) {
        if (b.line && b.line->file == l->file && b.line->line == l->line) {
            d.remove(b.number);
            p.add_log(fmt::format("Deleted breakpoint {}", b.number));
            p.last_t = ~0ull;
            return;
        }
    }
    const auto loc = d.locate_line(l->file, l->line);
    if (!loc.error.empty()) {
        p.add_log(loc.error);
        return;
    }
    for (const std::uint16_t a : loc.addresses) {
        const auto added = d.add_breakpoint_at(a);
        const int line = loc.bound ? loc.bound->line : l->line;
        p.add_log(fmt::format("Breakpoint {} at {:04X}H: file {}, line {}.", added.number, a,
                              std::filesystem::path(l->file).filename().string(), line));
    }
    p.last_t = ~0ull;
}

void draw_part_lines(const DebugPanes::PartPane& part) {
    for (const std::string& l : part.lines) ImGui::TextWrapped("%s", l.c_str());  // wrapped, not cut at the edge
}

std::vector<DebugPanes::PartPane> part_panes(script::DebugShell& shell) {
    std::vector<DebugPanes::PartPane> out;
    for (const periph::Part* part : shell.debugger().parts()) {
        if (shell.debugger().describe(*part).empty()) continue;
        DebugPanes::PartPane pane{std::string(part->name()), {}};
        const std::string text = shell.console().info(part->name());
        for (std::size_t start = 0; start < text.size();) {
            const auto nl = std::min(text.find('\n', start), text.size());
            pane.lines.push_back(text.substr(start, nl - start));
            start = nl + 1;
        }
        out.push_back(std::move(pane));
    }
    return out;
}

std::string registers_text(const debug::Debugger& d) {
    const cpu::Description& desc = cpu::description();
    auto shown = [&](const cpu::Register& x) { return fmt::format("{} {}", x.name, x.hex(d.reg(x))); };
    std::vector<std::string> left, right;
    for (const cpu::Register& x : desc.registers)
        if (x.kind == cpu::Register::Kind::Pair) left.push_back(shown(*desc.find(x.high)) + "  " + shown(*desc.find(x.low)));
    for (const cpu::Register& x : desc.registers)
        if (desc.standalone(x)) right.push_back(shown(x));
    for (const cpu::Register& x : desc.registers)
        if (x.kind == cpu::Register::Kind::Memory)
            if (const cpu::Register* at = desc.find(x.high)) right.push_back(fmt::format("[{}] {:02X}H", at->name, d.peek(d.reg(*at))));
    const debug::CpuStatus status = d.cpu_status();
    right.push_back(status.halted ? "HALTED" : "");
    std::string out;
    const std::size_t left_width = left.empty() ? 0 : left.front().size();
    for (std::size_t i = 0; i < std::max(left.size(), right.size()); ++i)
        out += fmt::format("{:<{}}   {}\n", i < left.size() ? left[i] : "", left_width, i < right.size() ? right[i] : "");
    const auto f = d.reg(*desc.flag_register());
    std::string flags;
    for (const cpu::Flag& flag : desc.flags) flags += fmt::format("{}{}={}", flags.empty() ? "" : " ", flag.name, (f & flag.bit) ? 1 : 0);
    const std::uint8_t rim = status.rim;
    out += fmt::format("{}\nIE={} M7.5={} M6.5={} M5.5={} I7.5={}\nT {} ({:.3f} ms)", flags, status.interrupts_enabled ? 1 : 0,
                       (rim >> 2) & 1, (rim >> 1) & 1, rim & 1, (rim >> 6) & 1, d.now(), board::ms_from_tstates(d.now()));
    return out;
}

void draw_debug_panes(DebugPanes& p, script::DebugShell& shell, bool running) {
    debug::Debugger& d = shell.debugger();
    static const cpu::Register& pc_register = *cpu::description().find("PC");
    const std::uint16_t pc = d.reg(pc_register);
    const auto pc_line = d.program().line_of(d.where());  // a halted CPU: its HLT's line
    if (pc != p.last_pc) {
        if (pc_line && !p.pinned) p.show(*pc_line);
        p.last_pc = pc;
    }
    if (d.now() != p.last_t) {
        p.registers = registers_text(d);
        p.parts = part_panes(shell);
        p.frames = d.backtrace();
        if (p.files.size() != d.program().files().size()) p.files = d.program().files();
        p.last_t = d.now();
    }

    // ---- source: the current line, breakpoints, a click sets one ----
    begin_pane(p.file.empty() ? "Source###source" : (std::filesystem::path(p.file).filename().string() + "###source").c_str(), kSourceRect);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    for (int i = 0; i < kSourceRows && !p.file.empty(); ++i) {
        const SourceLine l{p.file, p.first + i};
        const auto text = shell.console().source_line(l);
        if (!text) break;
        const Rect r = source_row(i);
        if (pc_line && *pc_line == l) dl->AddRectFilled({r.x, r.y}, {r.x + r.w, r.y + r.h}, rgb(colour::kCurrentLine));
        for (const auto& b : d.breakpoints())
            if (b.line && *b.line == l)
                dl->AddCircleFilled({r.x + kSourceDotX, r.y + r.h / 2}, 5, rgb(b.enabled ? colour::kBreakpoint : Rgb{120, 60, 60}));
        dl->AddText({r.x + 20, r.y + 1}, IM_COL32(150, 150, 150, 255), fmt::format("{:>5}", l.line).c_str());
        dl->AddText({r.x + kSourceTextX, r.y + 1}, IM_COL32(230, 230, 230, 255), text->c_str());
    }
    if (p.file.empty()) ImGui::TextUnformatted("(no source for the PC)");
    if (ImGui::IsWindowHovered() && ImGui::GetIO().MouseWheel != 0 && !p.file.empty()) {  // the wheel scrolls the file
        p.first = std::max(1, p.first - static_cast<int>(ImGui::GetIO().MouseWheel * 3));
        p.pinned = true;
    }
    ImGui::End();

    // ---- registers and flags ----
    begin_pane("Registers", kRegistersRect);
    ImGui::TextUnformatted(p.registers.c_str());
    ImGui::End();

    // ---- disassembly around the PC ----
    begin_pane("Disassembly", kDisasmRect);
    std::uint16_t a = pc;
    for (int i = 0; i < 12; ++i) {
        const auto dis = d.disassemble(a);
        const auto label = d.program().label_at(a);
        ImGui::TextColored(a == pc ? ImVec4(1, 0.9f, 0.3f, 1) : ImVec4(0.85f, 0.85f, 0.85f, 1), "%s%04XH %-8s %s", a == pc ? "=>" : "  ", a,
                           label ? label->c_str() : "", dis.text.c_str());
        a = static_cast<std::uint16_t>(a + dis.length);
    }
    ImGui::End();

    // ---- memory ----
    begin_pane("Memory", kMemoryRect);
    ImGui::SetNextItemWidth(120);
    ImGui::InputText("address", &p.memory);
    const auto base = d.evaluate(p.memory);
    if (!base.error.empty()) {
        ImGui::TextUnformatted(base.error.c_str());
    } else {
        for (int row = 0; row < 4; ++row) {
            const auto at = static_cast<std::uint16_t>(base.value + row * 16);
            std::string line = fmt::format("{:04X}H ", at);
            for (int k = 0; k < 16; ++k) line += fmt::format(" {:02X}", d.peek(static_cast<std::uint16_t>(at + k)));
            ImGui::TextUnformatted(line.c_str());
        }
    }
    ImGui::End();

    // ---- the parts: a tab each, showing its description ----
    // The scrollbar always there: text wrapped at a width that does not change when one appears.
    begin_resizable_pane("Parts", kChipsRect, ImGuiWindowFlags_AlwaysVerticalScrollbar);
    if (ImGui::BeginTabBar("parts", ImGuiTabBarFlags_FittingPolicyScroll)) {
        for (const DebugPanes::PartPane& part : p.parts) {
            const bool bring = !p.shown_part.empty() && p.shown_part == part.name;
            const bool open = ImGui::BeginTabItem(part.name.c_str(), nullptr, bring ? ImGuiTabItemFlags_SetSelected : 0);
            remember_item("debug.tab:" + part.name);
            if (open) {
                if (bring) p.shown_part.clear();  // it is in front: the user's clicks choose from now on
                draw_part_lines(part);
                ImGui::EndTabItem();
            }
        }
        // The call stack: a click on a frame shows its line in the source pane. At the right end of
        // the tabs, always in view however many parts there are.
        const bool stack_open = ImGui::BeginTabItem("call stack", nullptr, ImGuiTabItemFlags_Trailing);
        remember_item("debug.tab:call stack");
        if (stack_open) {
            for (std::size_t i = 0; i < p.frames.size(); ++i) {
                const debug::Frame& f = p.frames[i];
                const std::string where =
                    f.line ? fmt::format("{}:{}", std::filesystem::path(f.line->file).filename().string(), f.line->line) : std::string("??");
                const std::string text = fmt::format("#{} {:04X}H {} {}", i, f.pc, f.routine.value_or("??"), where);
                if (ImGui::Selectable(text.c_str()) && f.line) p.show_chosen(*f.line);
                remember_item(fmt::format("debug.frame:{}", i));
            }
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::End();

    // ---- watch list ----
    begin_resizable_pane("Watch", kWatchRect);
    int remove = -1;
    for (std::size_t i = 0; i < p.watches.size(); ++i) {
        const auto v = d.evaluate(p.watches[i]);
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::SmallButton("x")) remove = static_cast<int>(i);
        ImGui::PopID();
        ImGui::SameLine();
        if (v.error.empty())
            ImGui::Text("%s = %s (%lld)", p.watches[i].c_str(),
                        v.width == 8 ? fmt::format("{:02X}H", v.value & 0xFF).c_str() : fmt::format("{:04X}H", v.value & 0xFFFF).c_str(),
                        static_cast<long long>(v.value));
        else
            ImGui::Text("%s: %s", p.watches[i].c_str(), v.error.c_str());
    }
    if (remove >= 0) p.watches.erase(p.watches.begin() + remove);
    ImGui::SetNextItemWidth(180);
    if (ImGui::InputText("##newwatch", &p.new_watch, ImGuiInputTextFlags_EnterReturnsTrue) && !p.new_watch.empty()) {
        p.watches.push_back(p.new_watch);
        p.new_watch.clear();
    }
    ImGui::SameLine();
    ImGui::TextUnformatted("add");
    ImGui::End();

    // ---- stepping, forward and back ----
    begin_pane("Run", kStepButtonsRect);
    const ImVec2 b{100, 0};
    using R = DebugPanes::Request;
    struct StepButton {
        const char* id;
        const char* label;
        R request;
    };
    // Two rows of four, forward then back; Continue is Pause while the machine runs.
    const StepButton steps[] = {
        {"debug.continue", running ? "Pause###cont" : "Continue###cont", running ? R::Pause : R::Continue},
        {"debug.step", "Step", R::Step}, {"debug.next", "Next", R::Next}, {"debug.finish", "Finish", R::Finish},
        {"debug.reverse-continue", "Rev continue", R::ReverseContinue}, {"debug.reverse-step", "Rev step", R::ReverseStep},
        {"debug.reverse-next", "Rev next", R::ReverseNext}, {"debug.reverse-finish", "Rev finish", R::ReverseFinish}};
    for (std::size_t i = 0; i < std::size(steps); ++i) {
        if (i % 4 != 0) ImGui::SameLine();
        if (named_button(steps[i].id, steps[i].label, b.x)) p.request = steps[i].request;
    }
    // Every source of the loaded program's map: the source pane shows the one chosen.
    ImGui::SetNextItemWidth(260);
    const std::string shown = p.file.empty() ? std::string("(none)") : std::filesystem::path(p.file).filename().string();
    const bool chooser = ImGui::BeginCombo("source file", shown.c_str());
    remember_item("debug.source-files");
    if (chooser) {
        for (const std::string& f : p.files) {
            const std::string name = std::filesystem::path(f).filename().string();
            if (ImGui::Selectable(name.c_str(), f == p.file)) p.show_chosen({f, 1 + kSourceRows / 2});
            remember_item("debug.source:" + name);
        }
        ImGui::EndCombo();
    }
    ImGui::End();

    // ---- the command line ----
    begin_pane("Command", kCommandRect);
    ImGui::BeginChild("out", {0, kCommandRect.h - 58}, false);
    for (const std::string& l : p.log) ImGui::TextUnformatted(l.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::SetNextItemWidth(kCommandRect.w - 20);
    if (ImGui::InputText("##command", &p.command, ImGuiInputTextFlags_EnterReturnsTrue)) {
        // A line refused while running stays in the box, to be entered again after Pause.
        if (p.command.empty() || run_typed(p, shell, p.command, running).ran) p.command.clear();
        ImGui::SetKeyboardFocusHere(-1);
    }
    ImGui::End();
}

}  // namespace alp85::gui
