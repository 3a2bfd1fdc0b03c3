#include "emu/gui/controls.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include "emu/gui/layout.h"

namespace alp85::gui {

void ControlsState::add_log(std::string line) {
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
    ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoBackground);
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
    ImGui::SetNextItemWidth(160);
    if (!s.firmware_names.empty() &&
        ImGui::BeginCombo("##fw", s.firmware_names[static_cast<std::size_t>(s.firmware)].c_str())) {
        for (int i = 0; i < static_cast<int>(s.firmware_names.size()); ++i)
            if (ImGui::Selectable(s.firmware_names[static_cast<std::size_t>(i)].c_str(), i == s.firmware)) s.firmware = i;
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Load firmware + reset") && !s.firmware_names.empty())
        out.push_back({K::Firmware, s.firmware_names[static_cast<std::size_t>(s.firmware)]});
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
