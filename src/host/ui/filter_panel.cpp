#include "host/ui/filter_panel.h"

#include <fmt/format.h>
#include <imgui.h>

namespace vitrine::host {

FilterPanelChoice FilterPanel::draw(std::span<const FilterRow> chain, std::span<const std::filesystem::path> available,
                                    const TransitionRow& transition, std::string_view error) {
  FilterPanelChoice choice;
  panels_.resize(chain.size());
  if (chain.empty()) ImGui::TextDisabled("none: the scene's picture as it is");
  for (size_t i = 0; i < chain.size(); ++i) {
    ImGui::PushID(int(i));
    const bool open = ImGui::TreeNodeEx("filter", ImGuiTreeNodeFlags_DefaultOpen, "%zu. %s", i + 1, chain[i].name.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("remove")) choice.remove = i;
    if (open) {
      if (auto edit = panels_[i].draw(chain[i].bound)) choice.edit = std::pair{i, std::move(*edit)};
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (available.empty()) {
    ImGui::TextDisabled("no filters in the pieces folder (%s)", "$XDG_DATA_HOME/vitrine/pieces");
  } else if (ImGui::BeginCombo("add filter", "...")) {
    for (const std::filesystem::path& file : available)
      if (ImGui::Selectable(file.filename().string().c_str())) choice.add = file;
    ImGui::EndCombo();
  }
  ImGui::Separator();
  if (ImGui::BeginCombo("transition", transition.name.empty() ? "cross-fade" : transition.name.c_str())) {
    if (ImGui::Selectable("cross-fade", transition.name.empty())) choice.transition = std::optional<std::filesystem::path>();
    for (const std::filesystem::path& file : transition.available)
      if (ImGui::Selectable(file.filename().string().c_str(), file.filename().string() == transition.name))
        choice.transition = file;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("How scene switches and the kiosk's changes are drawn (the pieces folder's transitions)");
  if (transition.bound) {
    ImGui::PushID("transition");
    choice.transitionEdit = transitionPanel_.draw(*transition.bound);
    ImGui::PopID();
  }
  if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%.*s", int(error.size()), error.data());
  return choice;
}

}  // namespace vitrine::host
