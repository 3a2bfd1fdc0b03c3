#include "emu/gui/terminal_pane.h"

#include <imgui.h>

#include <fmt/format.h>

#include "emu/gui/layout.h"

namespace alp85::gui {

std::string terminal_text(const periph::SerialTerminal& terminal) {
    std::string out;
    bool after_cr = false;
    for (const std::uint8_t c : terminal.text()) {
        if (c == '\n') {
            if (!after_cr) out += '\n';
        } else if (c == '\r') {
            out += '\n';
        } else {
            out += c == '\t' || (c >= 0x20 && c <= 0x7E) ? static_cast<char>(c) : '.';
        }
        after_cr = c == '\r';
    }
    return out;
}

namespace {
// Each character typed goes out as it is typed; the line itself stays empty.
int take_typed(ImGuiInputTextCallbackData* data) {
    auto* typed = static_cast<std::string*>(data->UserData);
    if (data->EventChar < 0x80) *typed += static_cast<char>(data->EventChar);
    return 1;  // not kept in the line
}
}  // namespace

std::string draw_terminal_pane(const periph::SerialTerminal& terminal, TerminalPane& pane) {
    // Over the lower part of the table view (or the source pane), movable.
    ImGui::SetNextWindowPos({kTableRect.x + 8, kTableRect.y + kTableRect.h - 168}, ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize({440, 160}, ImGuiCond_FirstUseEver);
    const std::string title = fmt::format("Terminal on SID/SOD, {}###terminal", terminal.format().text());
    std::string typed;
    ImGui::Begin(title.c_str(), nullptr, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    const float line = ImGui::GetFrameHeightWithSpacing();
    ImGui::BeginChild("##received", {0, -line}, true, ImGuiWindowFlags_HorizontalScrollbar);
    const std::string text = terminal_text(terminal);
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);  // follow the end
    ImGui::EndChild();
    if (pane.focus) {
        ImGui::SetKeyboardFocusHere();
        pane.focus = false;
    }
    char line_text[2] = {};
    ImGui::SetNextItemWidth(-1);
    if (ImGui::InputTextWithHint("##send", "type here: each key goes to SID", line_text, sizeof line_text,
                                 ImGuiInputTextFlags_CallbackCharFilter | ImGuiInputTextFlags_EnterReturnsTrue, take_typed, &typed)) {
        typed += '\r';                   // Enter: a carriage return, as a terminal's Return key sends
        ImGui::SetKeyboardFocusHere(-1);  // and the keyboard stays in the line
    }
    pane.focused = ImGui::IsItemActive();
    ImGui::End();
    return typed;
}

}  // namespace alp85::gui
