#include "host/menu.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>

namespace vitrine::host {
namespace {

const ImVec4 kErrorRed{1.0f, 0.35f, 0.3f, 1.0f};
const ImVec4 kWarningAmber{0.96f, 0.62f, 0.04f, 1.0f};

void drawTimings(const MenuState& state) {
  double gpuMs = 0.0;
  for (const auto& pass : state.passes) gpuMs += pass.ms;
  ImGui::Text("%.1f fps   CPU %.2f ms   GPU %.2f ms", state.fps, state.cpuMs, gpuMs);
  if (!ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingFixedFit)) return;
  // Widths from the text itself: an auto-sized window measures a table's columns a frame late, which
  // clipped names and units whenever the passes changed.
  float nameWidth = ImGui::CalcTextSize("overlay").x;
  for (const auto& pass : state.passes) nameWidth = std::max(nameWidth, ImGui::CalcTextSize(pass.name.c_str()).x);
  ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthFixed, nameWidth);
  ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00000.000 ms").x);
  for (const auto& pass : state.passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(pass.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%9.3f ms", pass.ms);
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

// The help card: the gallery's keys, the scenes and their keys, and what the current one's drag does.
void drawHelp(const MenuState& state, bool& open) {
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Help (F1)", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_SizingFixedFit)) {
    for (const auto& [key, does] : galleryKeys()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(key.data(), key.data() + key.size());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(does.data(), does.data() + does.size());
    }
    ImGui::EndTable();
  }
  ImGui::Separator();
  for (const auto& info : sceneRegistry())
    ImGui::BulletText("%d  %.*s", info.key, int(info.title.size()), info.title.data());
  ImGui::Separator();
  ImGui::Text("%.*s:", int(state.current.title.size()), state.current.title.data());
  drawWrapped(state.current.input);
  ImGui::TextDisabled("Hover a parameter in the panel for what it does.");
  ImGui::End();
}

}  // namespace

std::span<const std::pair<std::string_view, std::string_view>> galleryKeys() {
  static const std::pair<std::string_view, std::string_view> keys[] = {
      {"number keys", "switch scene"},
      {"Tab", "hide or show all UI"},
      {"F1, ?", "this help"},
      {"P", "pause and resume"},
      {".", "one step while paused"},
      {"F5", "restart the scene, its parameters kept"},
      {"V", "vsync on or off"},
      {"M", "sound on or off"},
      {"F11", "fullscreen"},
      {"F9", "capture every frame to an EXR sequence, or stop"},
      {"F12", "screenshot (EXR and PNG)"},
      {"Esc", "quit"},
  };
  return keys;
}

std::string sceneKeyRange() {
  int lo = 10, hi = 0;
  for (const auto& info : sceneRegistry()) lo = std::min(lo, info.key), hi = std::max(hi, info.key);
  return lo == hi ? fmt::format("{}", lo) : fmt::format("{}-{}", lo, hi);
}

namespace {

// Asks before an edit that would freeze the window for seconds.
std::optional<bool> askAboutCostlyEdit(const std::string& why) {
  if (why.empty()) return std::nullopt;
  ImGui::OpenPopup("Apply this change?");
  std::optional<bool> answer;
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (ImGui::BeginPopupModal("Apply this change?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    drawWrapped(why);
    if (ImGui::Button("Apply")) answer = true;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) answer = false;
    if (answer) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  return answer;
}

}  // namespace

MenuChoice drawMenu(const MenuState& state) {
  MenuChoice choice{nullptr, state.vsync, std::nullopt, state.time, state.help, state.capturing};
  if (choice.help) drawHelp(state, choice.help);
  choice.costly = askAboutCostlyEdit(state.costly);
  ImGui::SetNextWindowPos(ImVec2(12.0f, 12.0f), ImGuiCond_FirstUseEver);
  // Never taller than the window: a long panel scrolls instead of falling off the bottom, and the
  // title bar's arrow folds the whole menu away.
  const ImVec2 view = ImGui::GetMainViewport()->WorkSize;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(std::max(200.0f, view.x - 24.0f),
                                                                 std::max(120.0f, view.y - 24.0f)));
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
    if (!state.reloaded.empty()) ImGui::TextColored(ImVec4(0.55f, 0.85f, 0.55f, 1.0f), "%.*s", int(state.reloaded.size()),
                                                    state.reloaded.data());
    if (!state.shaderError.empty()) {
      ImGui::Separator();
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorRed);
      ImGui::TextUnformatted("Shader reload failed; the previous pipeline is kept:");
      drawWrapped(state.shaderError);
      ImGui::PopStyleColor();
    }
    ImGui::Checkbox("capture (F9)", &choice.capture);
    if (!state.capture.empty()) {
      ImGui::SameLine();
      if (state.capturing) ImGui::TextColored(kErrorRed, "REC");
      drawWrapped(state.capture);
    }
    if (!state.note.empty()) drawWrapped(state.note);
    if (!state.remote.empty()) ImGui::TextDisabled("%s", state.remote.c_str());
    if (!state.missingAssets.empty() && ImGui::CollapsingHeader("Missing assets")) {
      ImGui::PushStyleColor(ImGuiCol_Text, kWarningAmber);
      for (const auto& line : state.missingAssets) drawWrapped(line);
      ImGui::PopStyleColor();
    }
    ImGui::Separator();
    ImGui::TextDisabled("%s scene  Tab hide UI  F1 help  P pause  F5 restart  M mute  F9 capture  F12 screenshot  Esc quit",
                        sceneKeyRange().c_str());
  }
  ImGui::End();
  return choice;
}

}  // namespace vitrine::host
