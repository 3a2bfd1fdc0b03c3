#include "emu/gui/controls.h"

#include <cctype>
#include <string_view>

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include "emu/gui/layout.h"

namespace alp85::gui {

void ControlsState::add_log(std::string line) {
    // Where a line's time begins (" at 1.200 s (3686400 T-states)"), or npos.
    const auto time_at = [](std::string_view l) {
        const auto at = l.rfind(" at ");
        if (at == std::string_view::npos || at + 4 >= l.size() || !std::isdigit(static_cast<unsigned char>(l[at + 4])) ||
            (l.back() != 's' && l.back() != ')'))
            return std::string_view::npos;
        return at;
    };
    const auto base = [&](std::string_view l) { return l.substr(0, time_at(l)); };
    if (repeats_ > 0 && !log.empty() && base(line) == base(repeated_)) {
        ++repeats_;
        const auto at = time_at(line);
        log.back() = at == std::string::npos ? fmt::format("{} ({} times)", repeated_, repeats_)
                                             : fmt::format("{} ({} times, the last at {})", repeated_, repeats_, line.substr(at + 4));
        return;
    }
    repeated_ = line;
    repeats_ = 1;
    log.push_back(std::move(line));
    while (log.size() > 200) log.pop_front();
}

std::map<std::string, ButtonRect, std::less<>>& drawn_buttons() {
    static std::map<std::string, ButtonRect, std::less<>> rects;
    return rects;
}

bool named_button(const char* name, const char* label, float width) {
    const bool pressed = ImGui::Button(label, {width, 0});
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    drawn_buttons()[name] = {a.x, a.y, b.x, b.y};
    return pressed;
}

std::vector<Action> controls_panel(ControlsState& s) {
    std::vector<Action> out;
    using K = Action::Kind;
    const Rect r = kControlsRect;
    ImGui::SetNextWindowPos({r.x, r.y});
    ImGui::SetNextWindowSize({r.w, r.h});
    ImGui::Begin("Controls", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBackground |
                     ImGuiWindowFlags_MenuBar);
    if (ImGui::BeginMenuBar()) {
        // The menu's place, for the test hooks' clicks (BeginMenu leaves no item rect to read once open).
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const ImVec2 text = ImGui::CalcTextSize("Machine tool");
        drawn_buttons()["controls.machine-tool"] = {at.x, at.y, at.x + text.x + 2 * ImGui::GetStyle().ItemSpacing.x,
                                                    at.y + ImGui::GetFrameHeight()};
        if (s.tool && ImGui::BeginMenu("Machine tool")) {
            // The operator's set-up between two jobs (docs/machine.md): the tables back at the start.
            if (ImGui::MenuItem("Set up a new workpiece")) out.push_back({K::NewWorkpiece, {}});
            const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
            drawn_buttons()["controls.new-workpiece"] = {a.x, a.y, b.x, b.y};
            ImGui::EndMenu();
        }
        // The logic analyzer's pane (signals_pane.h), over the table view or the source pane.
        if (ImGui::MenuItem("Signals", nullptr, s.signals)) out.push_back({K::Signals, {}});
        const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
        drawn_buttons()["controls.signals"] = {a.x, a.y, b.x, b.y};
        ImGui::EndMenuBar();
    }
    if (named_button("controls.run", s.running ? "Pause###run" : "Run###run", 60)) out.push_back({K::RunPause, {}});
    ImGui::SameLine();
    if (ImGui::Button("Reset")) out.push_back({K::Reset, {}});
    ImGui::SameLine();
    ImGui::SetNextItemWidth(190);
    if (ImGui::BeginCombo("speed", kSpeeds[static_cast<std::size_t>(s.speed)].label)) {
        for (int i = 0; i < static_cast<int>(kSpeeds.size()); ++i)
            if (ImGui::Selectable(kSpeeds[static_cast<std::size_t>(i)].label, i == s.speed)) out.push_back({K::Speed, {}, i});
        ImGui::EndCombo();
    }
    ImGui::TextUnformatted(s.status.c_str());
    ImGui::Separator();
    if (!s.firmware_names.empty()) {
        ImGui::SetNextItemWidth(160);
        if (ImGui::BeginCombo("##fw", s.firmware_names[static_cast<std::size_t>(s.firmware)].c_str())) {
            for (int i = 0; i < static_cast<int>(s.firmware_names.size()); ++i)
                if (ImGui::Selectable(s.firmware_names[static_cast<std::size_t>(i)].c_str(), i == s.firmware)) s.firmware = i;
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        if (ImGui::Button("Load firmware + reset")) out.push_back({K::Firmware, s.firmware_names[static_cast<std::size_t>(s.firmware)]});
    }
    ImGui::SetNextItemWidth(260);
    ImGui::InputText("##file", &s.file);
    ImGui::SameLine();
    if (named_button("controls.load", "Load .asm/.hex")) out.push_back({K::LoadFile, s.file});
    ImGui::SetNextItemWidth(260);
    ImGui::InputText("##snap", &s.snapshot);
    ImGui::SameLine();
    if (named_button("controls.save", "Save snapshot")) out.push_back({K::SaveSnapshot, s.snapshot});
    ImGui::SameLine();
    if (named_button("controls.restore", "Restore")) out.push_back({K::LoadSnapshot, s.snapshot});
    ImGui::SetNextItemWidth(260);
    ImGui::InputText("##shot", &s.screenshot);
    ImGui::SameLine();
    if (ImGui::Button("Screenshot")) out.push_back({K::Screenshot, s.screenshot});
    ImGui::SetNextItemWidth(120);
    ImGui::InputText("##rec", &s.record);
    ImGui::SameLine();
    if (named_button("controls.record", s.recording ? "Stop recording###rec" : "Record CSV###rec"))
        out.push_back({s.recording ? K::RecordStop : K::RecordStart, s.record});
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    ImGui::InputText("##plot", &s.plot);
    ImGui::SameLine();
    if (named_button("controls.plot", "Plot")) out.push_back({K::Plot, s.plot});
    ImGui::Separator();
    ImGui::BeginChild("log", {0, 0}, false);
    for (const std::string& line : s.log) ImGui::TextUnformatted(line.c_str());
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::End();
    return out;
}

}  // namespace alp85::gui
