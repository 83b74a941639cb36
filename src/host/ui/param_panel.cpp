#include "host/ui/param_panel.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace vitrine::host {
namespace {

void tooltip(const params::Param& param) {
  if (ImGui::IsItemHovered() && !param.help.empty())
    ImGui::SetTooltip("%s\n%s: %s (default %s)", param.help.c_str(), param.key.c_str(), param.typeName().c_str(),
                      param.defaultText.c_str());
}

std::string numberText(const params::Param& param, double value) {
  return param.kind == params::Kind::Int ? fmt::to_string(int(std::lround(value)))
                                         : params::formatFloat(float(value));
}

// Whether the current values are `values` applied over themselves: every value a preset sets is the
// value now, in canonical form.
bool matches(const params::Bound& bound, const params::KeyValues& now, const params::KeyValues& values) {
  const auto scratch = bound.schema->makeDefaults();
  const params::Bound copy{bound.schema, scratch.get()};
  if (!params::applyValues(copy, now).empty() || !params::applyValues(copy, values).empty()) return false;
  return params::snapshot(copy) == now;
}

std::string yours(const std::string& name) { return name + " (yours)"; }

}  // namespace

const params::Preset* matchingPreset(const params::Bound& bound) {
  const params::KeyValues now = params::snapshot(bound);
  for (const params::Preset& preset : bound.schema->presets())
    if (matches(bound, now, preset.values)) return &preset;
  return nullptr;
}

const params::UserPreset* matchingUserPreset(const params::Bound& bound, const UserPresets& mine) {
  const params::KeyValues now = params::snapshot(bound);
  for (const params::UserPreset* preset : mine)
    if (matches(bound, now, preset->values)) return preset;
  return nullptr;
}

std::string presetLabel(const params::Bound& bound, const UserPresets& mine) {
  if (const params::Preset* preset = matchingPreset(bound)) return preset->name;
  if (const params::UserPreset* preset = matchingUserPreset(bound, mine)) return yours(preset->name);
  const auto defaults = bound.schema->makeDefaults();
  return params::snapshot({bound.schema, defaults.get()}) == params::snapshot(bound) ? "defaults" : "custom";
}

// Save the current values as a new preset; rename, delete or export the user's preset they match.
std::optional<PanelEdit> ParamPanel::drawUserPresetActions(const params::Bound& bound, const UserPresets& mine) {
  std::optional<PanelEdit> edit;
  const params::UserPreset* current = matchingUserPreset(bound, mine);
  if (naming_ == Naming::None) {
    if (ImGui::SmallButton("save as...")) naming_ = Naming::SaveAs, name_[0] = '\0', focusName_ = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Save the current values as a preset of your own.");
    if (current) {
      const auto& name = current->name;
      ImGui::SameLine();
      if (ImGui::SmallButton("rename")) {
        naming_ = Naming::Rename;
        focusName_ = true;
        renaming_ = name;
        std::snprintf(name_, sizeof name_, "%s", name.c_str());
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rename your preset '%s'.", name.c_str());
      ImGui::SameLine();
      if (ImGui::SmallButton("delete")) edit = PanelEdit{PanelEdit::What::DeletePreset, {}, name, {}};
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Delete your preset '%s'.", name.c_str());
      ImGui::SameLine();
      if (ImGui::SmallButton("export")) edit = PanelEdit{PanelEdit::What::ExportPreset, {}, name, {}};
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Write '%s' as a file to share (--preset-file FILE reads it).", name.c_str());
    }
    return edit;
  }
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
  if (std::exchange(focusName_, false)) ImGui::SetKeyboardFocusHere();  // typed into at once
  const bool entered = ImGui::InputText(naming_ == Naming::SaveAs ? "name###preset name" : "new name###preset name", name_,
                                        sizeof name_, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if (ImGui::SmallButton("ok") || entered) {
    edit = naming_ == Naming::SaveAs ? PanelEdit{PanelEdit::What::SavePreset, {}, name_, {}}
                                     : PanelEdit{PanelEdit::What::RenamePreset, {}, renaming_, name_};
    naming_ = Naming::None;
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("cancel")) naming_ = Naming::None;
  return edit;
}

std::optional<PanelEdit> ParamPanel::draw(const params::Bound& bound, std::string_view tierInUse, const UserPresets& mine) {
  std::optional<PanelEdit> edit;
  auto set = [&](const std::string& key, std::string value) {
    edit = PanelEdit{PanelEdit::What::Values, {{key, std::move(value)}}, {}};
  };
  const params::Schema& schema = *bound.schema;

  if (!schema.presets().empty() || !mine.empty()) {
    const params::Preset* matching = matchingPreset(bound);
    const params::UserPreset* matchingMine = matching ? nullptr : matchingUserPreset(bound, mine);
    const std::string label = presetLabel(bound, mine);
    if (ImGui::BeginCombo("preset", label.c_str())) {
      for (const auto& preset : schema.presets()) {
        if (ImGui::Selectable(preset.name.c_str(), &preset == matching))
          edit = PanelEdit{PanelEdit::What::Preset, {}, preset.name};
        if (ImGui::IsItemHovered() && !preset.help.empty()) ImGui::SetTooltip("%s", preset.help.c_str());
      }
      if (!mine.empty() && !schema.presets().empty()) ImGui::Separator();
      for (const params::UserPreset* preset : mine) {  // marked as the user's own
        const std::string item = yours(preset->name);
        if (ImGui::Selectable(item.c_str(), preset == matchingMine))
          edit = PanelEdit{PanelEdit::What::Preset, {}, preset->name};
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Saved by you: %zu values.", preset->values.size());
      }
      ImGui::EndCombo();
    }
    ImGui::SameLine();
  }
  if (ImGui::SmallButton("reset all")) edit = PanelEdit{PanelEdit::What::ResetAll, {}, {}};
  if (auto action = drawUserPresetActions(bound, mine)) edit = std::move(action);

  // Sections fold (the first starts open), so a scene with many parameters fits a small window.
  std::string group;
  bool groupOpen = true;  // parameters before the first titled section always show
  int sections = 0;
  for (const params::Param& param : schema.params()) {
    if (param.group != group) {
      group = param.group;
      const std::string header = fmt::format("{}###group {}", group, group);
      groupOpen = ImGui::CollapsingHeader(header.c_str(), sections++ == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    }
    if (!groupOpen) continue;
    ImGui::PushID(param.key.c_str());
    const std::string current = param.format(bound.settings);
    const bool changed = current != param.defaultText;
    // Applying on release keeps a slider from rebuilding buffers on every step of a drag.
    const bool onRelease = param.has(params::kApplyOnRelease) || param.has(params::kRebuilds);
    switch (param.kind) {
      case params::Kind::Float:
      case params::Kind::Int: {
        const bool integer = param.kind == params::Kind::Int;
        auto it = editing_.find(param.key);
        double value = it != editing_.end() ? it->second : param.number(bound.settings);
        const ImGuiSliderFlags flags = param.has(params::kLogarithmic) ? ImGuiSliderFlags_Logarithmic : 0;
        bool moved;
        if (integer) {
          int v = int(std::lround(value));
          moved = ImGui::SliderInt(param.label.c_str(), &v, int(param.min), int(param.max), "%d", flags);
          value = v;
        } else {
          float v = float(value);
          moved = ImGui::SliderFloat(param.label.c_str(), &v, float(param.min), float(param.max), "%.4g", flags);
          value = v;
        }
        if (moved) {
          if (onRelease) editing_[param.key] = value;
          else set(param.key, numberText(param, value));
        }
        if (onRelease && ImGui::IsItemDeactivated() && editing_.count(param.key)) {
          set(param.key, numberText(param, editing_[param.key]));
          editing_.erase(param.key);
        }
        break;
      }
      case params::Kind::Bool: {
        bool on = param.number(bound.settings) != 0.0;
        if (ImGui::Checkbox(param.label.c_str(), &on)) set(param.key, on ? "on" : "off");
        break;
      }
      case params::Kind::Choice: {
        const int index = int(param.number(bound.settings));
        std::string shown = index >= 0 && size_t(index) < param.choices.size() ? param.choices[size_t(index)] : "?";
        // The automatic tier names the one it picked.
        if (param.key == "tier" && !tierInUse.empty()) shown = std::string(tierInUse);
        if (ImGui::BeginCombo(param.label.c_str(), shown.c_str())) {
          for (size_t i = 0; i < param.choices.size(); ++i)
            if (ImGui::Selectable(param.choices[i].c_str(), int(i) == index)) set(param.key, param.choices[i]);
          ImGui::EndCombo();
        }
        break;
      }
      case params::Kind::Colour: {
        glm::vec3 colour{0.0f};
        params::parseColourText(current, colour, nullptr);
        if (ImGui::ColorEdit3(param.label.c_str(), &colour.x)) set(param.key, params::formatColour(colour));
        break;
      }
      case params::Kind::Custom: {  // typed text, applied when the field is left (Enter, Tab, a click)
        const auto typed = typing_.find(param.key);
        char buffer[128];
        std::snprintf(buffer, sizeof buffer, "%s", typed != typing_.end() ? typed->second.c_str() : current.c_str());
        if (ImGui::InputText(param.label.c_str(), buffer, sizeof buffer)) typing_[param.key] = buffer;
        if (ImGui::IsItemDeactivated()) {
          if (auto it = typing_.find(param.key); it != typing_.end() && it->second != current) set(param.key, it->second);
          typing_.erase(param.key);  // show the applied (or kept) value again
        }
        break;
      }
    }
    if (ImGui::IsItemActivated()) clicked_ = param.key;
    tooltip(param);
    if (changed) {
      ImGui::SameLine();
      if (ImGui::SmallButton("reset")) set(param.key, param.defaultText);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to %s", param.defaultText.c_str());
    }
    ImGui::PopID();
  }
  return edit;
}

}  // namespace vitrine::host
