#include "host/ui/menu.h"

#include "rig/link_clock.h"
#include "scenes/pieces/piece_catalogue.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_internal.h>  // ImGuiSettingsHandler: the menu's layout in the overlay's ini file

#include <algorithm>
#include <charconv>

namespace vitrine::host {
namespace {

const ImVec4 kErrorRed{1.0f, 0.35f, 0.3f, 1.0f};
const ImVec4 kWarningAmber{0.96f, 0.62f, 0.04f, 1.0f};

// The fps line: always one line, so nothing below it moves.
void drawFrameRate(const MenuState& state) {
  double gpuMs = 0.0;
  for (const auto& pass : state.passes) gpuMs += pass.ms;
  ImGui::Text("%.1f fps   CPU %.2f ms   GPU %.2f ms", state.fps, state.cpuMs, gpuMs);
}

// The passes' timings, in as many rows as the most passes seen: after a switch the new scene's
// timings arrive a frame or two late, and a table that shrank meanwhile moved everything under it.
void drawPassTable(const MenuState& state, int rows) {
  if (!ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingFixedFit)) return;
  // Widths from the text itself: an auto-sized window measures a table's columns a frame late, which
  // clipped names and units whenever the passes changed.
  float nameWidth = ImGui::CalcTextSize("screenshot copy").x;
  for (const auto& pass : state.passes) nameWidth = std::max(nameWidth, ImGui::CalcTextSize(pass.name.c_str()).x);
  ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthFixed, nameWidth);
  ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("00000.000 ms").x);
  for (int row = 0; row < rows; ++row) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (size_t(row) >= state.passes.size()) {
      ImGui::TextUnformatted(" ");
      continue;
    }
    const auto& pass = state.passes[size_t(row)];
    ImGui::TextUnformatted(pass.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%9.3f ms", pass.ms);
  }
  ImGui::EndTable();
}

// Each clock and published output on a line, amber while it is not well (a clock lost, frames dropped).
void drawRig(std::span<const rig::RigLine> lines) {
  for (const rig::RigLine& line : lines) {
    ImGui::TextColored(line.ok ? ImGui::GetStyleColorVec4(ImGuiCol_Text) : kWarningAmber, "%s", line.name.c_str());
    ImGui::SameLine();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", line.text.c_str());
    ImGui::PopStyleColor();
  }
}

// Link: in the session or not, its tempo (dragged, or typed with Ctrl+click) and its transport. A
// change is returned; the gallery then leads the session with it.
std::optional<LinkControls> drawLinkControls(const LinkControls& now) {
  LinkControls next = now;
  ImGui::Checkbox("Link", &next.joined);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("In the Link session (off: the timeline runs on alone)");
  ImGui::SameLine();
  constexpr double kMin = rig::LinkClock::kMinBpm, kMax = rig::LinkClock::kMaxBpm;
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 8.0f);
  ImGui::DragScalar("BPM", ImGuiDataType_Double, &next.tempo, 0.05f, &kMin, &kMax, "%.2f",
                    ImGuiSliderFlags_AlwaysClamp);
  ImGui::SameLine();
  if (ImGui::SmallButton(now.playing ? "stop" : "play")) next.playing = !now.playing;
  if (next == now) return std::nullopt;
  return next;
}

// A section header whose open state is the layout's: set from it, and written back when clicked.
bool section(const char* label, bool& open) {
  ImGui::SetNextItemOpen(open, ImGuiCond_Always);
  const bool now = ImGui::CollapsingHeader(label);
  if (now != open) {
    open = now;
    ImGui::MarkIniSettingsDirty();
  }
  return now;
}

const SceneInfo* drawSceneList(const SceneInfo& current, ImFont* font) {
  const SceneInfo* chosen = nullptr;
  if (font) ImGui::PushFont(font);
  for (const auto& info : sceneRegistry()) {
    // Pieces found at run time have no number key; one whose file was refused says why under it.
    const std::string label = info.key > 0 ? fmt::format("{}  {}", info.key, info.title) : fmt::format("   {}", info.title);
    if (ImGui::Selectable(label.c_str(), &info == &current)) chosen = &info;
    if (const pieces::Piece* piece = info.builtIn() ? nullptr : pieces::findPiece(info.name); piece && !piece->error.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", piece->error.c_str());
      ImGui::PopTextWrapPos();
    }
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
  for (const auto& info : sceneRegistry()) {
    if (info.key > 0) ImGui::BulletText("%d  %.*s", info.key, int(info.title.size()), info.title.data());
    else ImGui::BulletText("   %.*s", int(info.title.size()), info.title.data());
  }
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
      {"[  ]", "slower, faster (0-4x, halving and doubling)"},
      {"\\", "back to normal speed (1x)"},
      {"F5", "restart the scene, its parameters kept"},
      {"V", "vsync on or off"},
      {"M", "sound on or off"},
      {"F11", "fullscreen"},
      {"F7", "projector setup: drag the corners, Enter keeps"},
      {"F9", "capture every frame to an EXR sequence, or stop"},
      {"F12", "screenshot (EXR and PNG)"},
      {"L", "the lights' blackout, or back (--lights)"},
      {"Esc", "quit"},
  };
  return keys;
}

std::string sceneKeyRange() {
  int lo = 10, hi = 0;
  for (const auto& info : sceneRegistry())
    if (info.key > 0) lo = std::min(lo, info.key), hi = std::max(hi, info.key);
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

float menuWidth(float fontSize) { return std::round(fontSize * 19.0f); }

std::string MenuLayout::text() const {
  return fmt::format("time={:d}\npanel={:d}\nlive={:d}\ntimings={:d}\nrig={:d}\npass_rows={}\n", time, panel, live,
                     timings, rig, passRows);
}

void MenuLayout::readLine(std::string_view line) {
  const size_t eq = line.find('=');
  if (eq == std::string_view::npos) return;
  const std::string_view key = line.substr(0, eq), value = line.substr(eq + 1);
  int number = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
  if (error != std::errc() || end == value.data()) return;
  if (key == "time") time = number != 0;
  else if (key == "panel") panel = number != 0;
  else if (key == "timings") timings = number != 0;
  else if (key == "live") live = number != 0;
  else if (key == "rig") rig = number != 0;
  else if (key == "pass_rows") passRows = std::clamp(number, 0, 64);
}

void keepInIni(MenuLayout& layout) {
  ImGuiSettingsHandler handler;
  handler.TypeName = "Vitrine";
  handler.TypeHash = ImHashStr("Vitrine");
  handler.UserData = &layout;
  handler.ReadOpenFn = [](ImGuiContext*, ImGuiSettingsHandler* h, const char* name) -> void* {
    return std::string_view(name) == "menu" ? h->UserData : nullptr;
  };
  handler.ReadLineFn = [](ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
    static_cast<MenuLayout*>(entry)->readLine(line);
  };
  handler.WriteAllFn = [](ImGuiContext*, ImGuiSettingsHandler* h, ImGuiTextBuffer* out) {
    out->appendf("[Vitrine][menu]\n%s\n", static_cast<const MenuLayout*>(h->UserData)->text().c_str());
  };
  ImGui::GetCurrentContext()->SettingsHandlers.push_back(handler);
}

void drawToast(std::string_view text) {
  const ImGuiViewport* view = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(view->WorkPos.x + 12.0f, view->WorkPos.y + view->WorkSize.y - 12.0f), ImGuiCond_Always,
                          ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                     ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoSavedSettings |
                                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("###toast", nullptr, flags)) {
    ImGui::PushTextWrapPos(std::max(200.0f, view->WorkSize.x - 48.0f));
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

bool menuHasKeyboard() {
  const ImGuiIO& io = ImGui::GetIO();
  return io.WantTextInput || io.WantCaptureKeyboard || ImGui::IsAnyItemActive();
}

// The menu, top to bottom in the order of what changes least: the scene list never moves; sections
// the user opens keep their place; messages that come and go are last, where they move nothing.
MenuChoice drawMenu(const MenuState& state) {
  MenuChoice choice{nullptr, state.vsync, std::nullopt, state.time, state.help, state.capturing};
  choice.flashGuard = state.flashGuard;
  choice.time.speed = TimeControl::clampSpeed(choice.time.speed);  // shown and kept within 0-4x
  if (choice.help) drawHelp(state, choice.help);
  choice.costly = askAboutCostlyEdit(state.costly);
  MenuLayout fallback;
  MenuLayout& layout = state.layout ? *state.layout : fallback;
  ImGui::SetNextWindowPos(ImVec2(12.0f, 12.0f), ImGuiCond_FirstUseEver);
  // A fixed width, never taller than the window: a long panel scrolls instead of falling off the
  // bottom, and the title bar's arrow folds the whole menu away.
  const ImVec2 view = ImGui::GetMainViewport()->WorkSize;
  const float width = std::min(menuWidth(ImGui::GetFontSize()), std::max(120.0f, view.x - 24.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, std::max(120.0f, view.y - 24.0f)));
  if (ImGui::Begin("Vitrine", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    // Sliders leave room for their label and the reset button beside them.
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 8.5f);
    drawFrameRate(state);
    ImGui::Separator();
    choice.scene = drawSceneList(state.current, state.titleFont);
    if (section("time and capture###time", layout.time)) {
      ImGui::Checkbox("vsync (V)", &choice.vsync);
      ImGui::SameLine();
      ImGui::Checkbox("pause (P)", &choice.time.paused);
      ImGui::SameLine();
      // Always there (greyed while running), so nothing beside it moves when pause is pressed.
      ImGui::BeginDisabled(!choice.time.paused);
      if (ImGui::SmallButton("step (.)")) choice.time.stepRequested = true;
      ImGui::EndDisabled();
      ImGui::SliderFloat("speed", &choice.time.speed, 0.0f, TimeControl::kMaxSpeed, "%.2fx",
                         ImGuiSliderFlags_AlwaysClamp);
      choice.time.speed = TimeControl::clampSpeed(choice.time.speed);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("[ slower, ] faster, \\ 1x; Ctrl+click to type");
      if (ImGui::SmallButton("restart (F5)")) choice.scene = &state.current;
      ImGui::SameLine();
      ImGui::Checkbox("capture (F9)", &choice.capture);
      if (state.capturing) {
        ImGui::SameLine();
        ImGui::TextColored(kErrorRed, "REC");
      }
      ImGui::Checkbox("flash guard", &choice.flashGuard);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Holds back what would flash over three times a second (WCAG 2.3.1): docs/INSTALLATIONS.md");
    }
    const std::string header = fmt::format("{}###scene panel", state.current.title);
    if (section(header.c_str(), layout.panel)) {
      if (state.panel) choice.edit = state.panel->draw(state.scene.parameters(), state.tierInUse, state.userPresets);
      state.scene.drawPanel();
    }
    if (state.filters && ImGui::CollapsingHeader("filters and transition###filters")) state.filters();
    if (state.livePanel && section("live input###live", layout.live)) choice.live = state.livePanel->draw(state.live);
    layout.passRows = std::max(layout.passRows, int(state.passes.size()));
    if (section("timings###timings", layout.timings)) drawPassTable(state, layout.passRows);
    if ((!state.rig.empty() || state.link) && section("rig: clocks and outputs###rig", layout.rig)) {
      if (state.link) choice.link = drawLinkControls(*state.link);
      drawRig(state.rig);
    }
    ImGui::PopItemWidth();
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s scene  Tab hide UI  F1 help  P pause  [ ] \\ speed  F5 restart  M mute  F9 capture  "
                       "F12 screenshot  Esc quit",
                       sceneKeyRange().c_str());
    ImGui::PopStyleColor();
    // What comes and goes: below everything else.
    if (!state.panelError.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorRed);
      ImGui::TextWrapped("%.*s", int(state.panelError.size()), state.panelError.data());
      ImGui::PopStyleColor();
    }
    if (!state.clock.empty()) ImGui::TextColored(kWarningAmber, "%s", state.clock.c_str());
    if (!state.reloaded.empty()) ImGui::TextColored(ImVec4(0.55f, 0.85f, 0.55f, 1.0f), "%.*s", int(state.reloaded.size()),
                                                    state.reloaded.data());
    if (!state.shaderError.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, kErrorRed);
      ImGui::TextWrapped("Shader reload failed; the previous pipeline is kept:");
      ImGui::TextWrapped("%.*s", int(state.shaderError.size()), state.shaderError.data());
      ImGui::PopStyleColor();
    }
    if (!state.capture.empty()) ImGui::TextWrapped("%s", state.capture.c_str());
    if (!state.note.empty()) ImGui::TextWrapped("%.*s", int(state.note.size()), state.note.data());
    if (!state.remote.empty()) ImGui::TextDisabled("%s", state.remote.c_str());
    if (!state.missingAssets.empty() && ImGui::CollapsingHeader("Missing assets")) {
      ImGui::PushStyleColor(ImGuiCol_Text, kWarningAmber);
      for (const auto& line : state.missingAssets) ImGui::TextWrapped("%s", line.c_str());
      ImGui::PopStyleColor();
    }
  }
  ImGui::End();
  return choice;
}

}  // namespace vitrine::host
