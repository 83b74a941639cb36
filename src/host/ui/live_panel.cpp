#include "host/ui/live_panel.h"

#include <imgui.h>

#include <string_view>

namespace vitrine::host {

LivePanelChoice LivePanel::draw(const LivePanelState& state) {
  LivePanelChoice choice;
  ImGui::BeginDisabled(state.audioFromFile);
  bool on = state.audioOn;
  if (ImGui::Checkbox("audio input", &on)) choice.audioOn = on;
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Music playing on this machine (or the chosen input) plays each scene's audio mappings");
  const std::string shown = state.audioDevice.empty() ? "default monitor" : state.audioDevice;
  if (ImGui::BeginCombo("audio device", shown.c_str())) {
    if (ImGui::Selectable("default monitor", state.audioDevice.empty())) choice.audioDevice = "";
    for (const std::string& device : state.devices)
      if (ImGui::Selectable(device.c_str(), device == state.audioDevice)) choice.audioDevice = device;
    ImGui::EndCombo();
  }
  ImGui::EndDisabled();
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  for (const std::string& line : state.status) ImGui::TextWrapped("%s", line.c_str());
  ImGui::PopStyleColor();

  // The mappings playing now: the shaped value's meter, a remove button for the user's own, the line
  // (greyed for --map's and the scene's audio mappings, dimmer still while a knob waits to take over).
  const float meter = ImGui::GetFontSize() * 2.5f;
  for (size_t i = 0; i < state.mappings.size(); ++i) {
    const live::MappingState& mapping = state.mappings[i];
    ImGui::PushID(int(i));
    ImGui::ProgressBar(mapping.shaped, ImVec2(meter, 0.0f), "");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(mapping.engaged ? "source %.2f, shaped %.2f" : "source %.2f: move the control to the value to take over",
                        double(mapping.source), double(mapping.shaped));
    ImGui::SameLine();
    const bool mine = i < state.userMappings;
    if (mine && ImGui::SmallButton("x")) choice.remove = i;
    if (mine && ImGui::IsItemHovered()) ImGui::SetTooltip("remove this mapping");
    if (mine) ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(mine && mapping.engaged ? ImGuiCol_Text : ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s%s", mapping.engaged ? "" : "(waiting) ", mapping.text.c_str());
    ImGui::PopStyleColor();
    if (!mine && ImGui::IsItemHovered()) ImGui::SetTooltip("from --map or the scene's audio mappings");
    ImGui::PopID();
  }
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputTextWithHint("##map", "add SOURCE=KEY[:LO:HI] [options]", line_, sizeof line_,
                               ImGuiInputTextFlags_EnterReturnsTrue) && line_[0] != 0) {
    choice.add = line_;
    line_[0] = 0;
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("audio.bass=fold:1:1.12 release=0.3, midi.cc.1.21=exposure, lfo.sine.8=... (Enter)");

  switch (state.learn) {
    case LearnStep::Idle:
      if (ImGui::SmallButton("MIDI learn")) choice.learn = true;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("then click a parameter and move a MIDI control or gamepad stick");
      break;
    case LearnStep::ClickParameter:
      ImGui::TextColored(ImVec4(0.95f, 0.75f, 0.3f, 1.0f), "click a parameter above");
      ImGui::SameLine();
      choice.cancelLearn = ImGui::SmallButton("cancel");
      break;
    case LearnStep::MoveControl:
      ImGui::TextColored(ImVec4(0.95f, 0.75f, 0.3f, 1.0f), "move a control for %s", state.learnKey.c_str());
      ImGui::SameLine();
      choice.cancelLearn = ImGui::SmallButton("cancel");
      break;
  }
  ImGui::InputText("file", file_, sizeof file_);
  if (ImGui::SmallButton("save mappings")) choice.save = file_;
  ImGui::SameLine();
  if (ImGui::SmallButton("load")) choice.load = file_;
  if (!state.message.empty()) ImGui::TextWrapped("%s", state.message.c_str());
  return choice;
}

}  // namespace vitrine::host
