#include "host/menu.h"

#include <fmt/format.h>
#include <imgui.h>

namespace vitrine::host {
namespace {

const ImVec4 kErrorRed{1.0f, 0.35f, 0.3f, 1.0f};
const ImVec4 kWarningAmber{0.96f, 0.62f, 0.04f, 1.0f};

void drawTimings(const MenuState& state) {
  double gpuMs = 0.0;
  for (const auto& pass : state.passes) gpuMs += pass.ms;
  ImGui::Text("%.1f fps   CPU %.2f ms   GPU %.2f ms", state.fps, state.cpuMs, gpuMs);
  if (!ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingFixedFit)) return;
  for (const auto& pass : state.passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(pass.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%7.3f ms", pass.ms);
  }
  ImGui::EndTable();
}

const SceneInfo* drawSceneList(const SceneInfo& current, ImFont* font) {
  const SceneInfo* chosen = nullptr;
  if (font) ImGui::PushFont(font);
  for (const auto& info : sceneRegistry()) {
    const std::string label = fmt::format("{}  {}", info.key, info.title);
    if (ImGui::Selectable(label.c_str(), &info == &current)) chosen = &info;
  }
  if (font) ImGui::PopFont();
  return chosen;
}

void drawWrapped(std::string_view text) {
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
  ImGui::TextUnformatted(text.data(), text.data() + text.size());
  ImGui::PopTextWrapPos();
}

}  // namespace

MenuChoice drawMenu(const MenuState& state) {
  MenuChoice choice{nullptr, state.vsync, std::nullopt, state.time};
  ImGui::SetNextWindowPos(ImVec2(12.0f, 12.0f), ImGuiCond_FirstUseEver);
  if (ImGui::Begin("Vitrine", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    drawTimings(state);
    ImGui::Checkbox("vsync (V)", &choice.vsync);
    ImGui::SameLine();
    ImGui::Checkbox("pause (P)", &choice.time.paused);
    if (choice.time.paused) {
      ImGui::SameLine();
      if (ImGui::SmallButton("step (.)")) choice.time.stepRequested = true;
    }
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
    ImGui::SliderFloat("speed", &choice.time.speed, 0.0f, TimeControl::kMaxSpeed, "%.2fx");
    ImGui::SameLine();
    if (ImGui::SmallButton("restart (F5)")) choice.scene = &state.current;
    ImGui::Separator();
    choice.scene = drawSceneList(state.current, state.titleFont);
    const std::string header = fmt::format("{}###scene panel", state.current.title);
    if (ImGui::CollapsingHeader(header.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      if (state.panel) choice.edit = state.panel->draw(state.scene.parameters(), std::string(state.panelError));
      state.scene.drawPanel();
    }
    if (!state.shaderError.empty()) {
      ImGui::Separator();
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorRed);
      ImGui::TextUnformatted("Shader reload failed; the previous pipeline is kept:");
      drawWrapped(state.shaderError);
      ImGui::PopStyleColor();
    }
    if (!state.screenshot.empty()) drawWrapped(state.screenshot);
    if (!state.missingAssets.empty() && ImGui::CollapsingHeader("Missing assets")) {
      ImGui::PushStyleColor(ImGuiCol_Text, kWarningAmber);
      for (const auto& line : state.missingAssets) drawWrapped(line);
      ImGui::PopStyleColor();
    }
    ImGui::Separator();
    ImGui::TextDisabled("1-9 scene  Tab hide UI  P pause  . step  F5 restart  M mute  F11 fullscreen  F12 screenshot  "
                        "Esc quit");
  }
  ImGui::End();
  return choice;
}

}  // namespace vitrine::host
