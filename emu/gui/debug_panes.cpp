#include "emu/gui/debug_panes.h"

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
std::string run(DebugPanes& p, script::DebugShell& shell, const std::string& line) {
    p.add_log("(alp85) " + line);
    std::string out = shell.execute(line);
    p.add_log(out);
    p.last_t = ~0ull;  // refresh the panes
    return out;
}
}  // namespace

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

std::vector<DebugPanes::PartPane> part_panes(script::DebugShell& shell) {
    std::vector<DebugPanes::PartPane> out;
    for (const periph::Part* part : shell.debugger().machine().parts()) {
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

void draw_debug_panes(DebugPanes& p, script::DebugShell& shell, bool running) {
    debug::Debugger& d = shell.debugger();
    Machine& m = d.machine();
    const std::uint16_t pc = m.cpu().regs().pc;
    const auto pc_line = d.program().line_of(d.where());  // a halted CPU: its HLT's line
    if (pc != p.last_pc) {
        if (pc_line) p.show(*pc_line);
        p.last_pc = pc;
    }
    if (m.now() != p.last_t) {
        const Registers& r = m.cpu().regs();
        const std::uint8_t rim = m.cpu().rim_value();
        auto f = [&](std::uint8_t bit) { return (r.f & bit) ? 1 : 0; };
        p.registers = fmt::format(
            "A {:02X}H  F {:02X}H   SP {:04X}H\nB {:02X}H  C {:02X}H   PC {:04X}H\nD {:02X}H  E {:02X}H   [HL] {:02X}H\n"
            "H {:02X}H  L {:02X}H   {}\nS={} Z={} AC={} P={} CY={} V={} K={}\nIE={} M7.5={} M6.5={} M5.5={} I7.5={}\n"
            "T {} ({:.3f} ms)",
            r.a, r.f, r.sp, r.b, r.c, r.pc, r.d, r.e, m.peek(r.hl()), r.h, r.l, m.cpu().halted() ? "HALTED" : "", f(0x80), f(0x40),
            f(0x10), f(0x04), f(0x01), f(0x02), f(0x20), m.cpu().interrupts_enabled() ? 1 : 0, (rim >> 2) & 1, (rim >> 1) & 1, rim & 1,
            (rim >> 6) & 1, m.now(), board::ms_from_tstates(m.now()));
        p.parts = part_panes(shell);
        p.last_t = m.now();
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
    ImGui::End();

    // ---- registers and flags ----
    begin_pane("Registers", kRegistersRect);
    ImGui::TextUnformatted(p.registers.c_str());
    ImGui::End();

    // ---- disassembly around the PC ----
    begin_pane("Disassembly", kDisasmRect);
    std::uint16_t a = pc;
    for (int i = 0; i < 12; ++i) {
        const auto dis = disassemble(m.bus(), a, m.cpu().variant(), &d.program());
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
            for (int k = 0; k < 16; ++k) line += fmt::format(" {:02X}", m.peek(static_cast<std::uint16_t>(at + k)));
            ImGui::TextUnformatted(line.c_str());
        }
    }
    ImGui::End();

    // ---- the parts: a tab each, showing its description ----
    ImGui::SetNextWindowPos({kChipsRect.x, kChipsRect.y});
    ImGui::SetNextWindowSize({kChipsRect.w, kChipsRect.h});
    ImGui::Begin("Parts", nullptr, kPane | ImGuiWindowFlags_HorizontalScrollbar);
    if (ImGui::BeginTabBar("parts", ImGuiTabBarFlags_FittingPolicyScroll)) {
        for (const DebugPanes::PartPane& part : p.parts) {
            const bool bring = !p.shown_part.empty() && p.shown_part == part.name;
            if (ImGui::BeginTabItem(part.name.c_str(), nullptr, bring ? ImGuiTabItemFlags_SetSelected : 0)) {
                if (bring) p.shown_part.clear();  // it is in front: the user's clicks choose from now on
                for (const std::string& l : part.lines) ImGui::TextUnformatted(l.c_str());
                ImGui::EndTabItem();
            }
        }
        ImGui::EndTabBar();
    }
    ImGui::End();

    // ---- watch list ----
    begin_pane("Watch", kWatchRect);
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
    if (named_button("debug.continue", running ? "Pause###cont" : "Continue###cont", b.x)) p.request = running ? R::Pause : R::Continue;
    ImGui::SameLine();
    if (named_button("debug.step", "Step", b.x)) p.request = R::Step;
    ImGui::SameLine();
    if (named_button("debug.next", "Next", b.x)) p.request = R::Next;
    ImGui::SameLine();
    if (named_button("debug.finish", "Finish", b.x)) p.request = R::Finish;
    if (named_button("debug.reverse-continue", "Rev continue", b.x)) p.request = R::ReverseContinue;
    ImGui::SameLine();
    if (named_button("debug.reverse-step", "Rev step", b.x)) p.request = R::ReverseStep;
    ImGui::SameLine();
    if (named_button("debug.reverse-next", "Rev next", b.x)) p.request = R::ReverseNext;
    ImGui::SameLine();
    if (named_button("debug.reverse-finish", "Rev finish", b.x)) p.request = R::ReverseFinish;
    ImGui::End();

    // ---- the command line ----
    begin_pane("Command", kCommandRect);
    ImGui::BeginChild("out", {0, kCommandRect.h - 58}, false);
    for (const std::string& l : p.log) ImGui::TextUnformatted(l.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::SetNextItemWidth(kCommandRect.w - 20);
    if (ImGui::InputText("##command", &p.command, ImGuiInputTextFlags_EnterReturnsTrue)) {
        if (!p.command.empty()) run(p, shell, p.command);
        p.command.clear();
        ImGui::SetKeyboardFocusHere(-1);
    }
    ImGui::End();
}

}  // namespace alp85::gui
