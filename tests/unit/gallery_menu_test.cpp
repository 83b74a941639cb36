// The gallery's menu, drawn by Dear ImGui with no window and no GPU: a context of 1280x720 whose
// frames are built and thrown away, with the mouse put where a person would rest it. What a resting
// cursor points at must not change when a scene switch empties the timings for a frame, and a field
// that a click has just activated has the keyboard.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/ui/menu.h"
#include "host/ui/param_panel.h"
#include "host/plural.h"
#include "host/gallery/tier_watch.h"
#include "scenes/scene.h"

namespace vitrine::host {
namespace {

// A scene of the registry reduced to its parameters: the menu needs nothing else.
class StillScene final : public Scene {
 public:
  explicit StillScene(const SceneInfo& info) : schema_(&info.schema()), settings_(info.schema().makeDefaults()) {}
  void update(const FrameInput&) override {}
  void record(const FrameContext&) override {}
  params::Bound parameters() override { return {schema_, settings_.get()}; }

 private:
  const params::Schema* schema_;
  std::shared_ptr<void> settings_;
};

class HeadlessImGui {
 public:
  HeadlessImGui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280.0f, 720.0f);
    io.DeltaTime = 1.0f / 60.0f;
    io.Fonts->AddFontDefault();
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }

  // One frame with the mouse at `mouse`; returns the widget under it (0: none, or plain text).
  ImGuiID frame(ImVec2 mouse, const std::function<void()>& draw, bool down = false, bool ctrl = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[0] = down;
    io.KeyCtrl = ctrl;
    ImGui::NewFrame();
    draw();
    const ImGuiID hovered = ImGui::GetCurrentContext()->HoveredId;
    ImGui::Render();
    return hovered;
  }
};

const SceneInfo& sceneWithPresets() {
  for (const auto& info : sceneRegistry())
    if (!info.schema().presets().empty()) return info;
  throw std::runtime_error("no scene with presets");
}

std::vector<gpu::PassTime> somePasses(int n) {
  std::vector<gpu::PassTime> passes;
  for (int i = 0; i < n; ++i) passes.push_back({"pass " + std::to_string(i), 0.5 + i});
  return passes;
}

// The per-pass timing rows vanished for a frame after a switch, so everything below them
// moved up 100-200 px and a click meant for the preset list switched scene.
TEST(GalleryMenu, NothingMovesUnderARestingCursorWhenTheTimingsEmpty) {
  HeadlessImGui imgui;
  const SceneInfo& info = sceneWithPresets();
  StillScene scene(info);
  ParamPanel panel;
  MenuLayout layout;
  layout.time = layout.panel = layout.timings = true;  // everything open: the most there is to move
  const auto passes = somePasses(9);
  std::span<const gpu::PassTime> shown = passes;
  const auto draw = [&] {
    MenuState state{.current = info, .scene = scene, .fps = 60.0, .passes = shown, .panel = &panel, .layout = &layout};
    drawMenu(state);
  };
  // Settle with the timings showing (the menu sizes itself over a few frames).
  for (int i = 0; i < 4; ++i) imgui.frame({-100, -100}, draw);
  std::vector<ImGuiID> before, after;
  int widgets = 0;
  for (float y = 14.0f; y < 700.0f; y += 6.0f) {
    shown = passes;
    imgui.frame({60.0f, y}, draw);
    before.push_back(imgui.frame({60.0f, y}, draw));
    shown = {};  // the frame after a switch: no timings yet
    imgui.frame({60.0f, y}, draw);
    after.push_back(imgui.frame({60.0f, y}, draw));
    widgets += before.back() != 0;
  }
  EXPECT_GT(widgets, 10) << "the scan should cross the scene list, the sections and the panel";
  for (size_t i = 0; i < before.size(); ++i)
    EXPECT_EQ(before[i], after[i]) << "the widget under the cursor at y=" << 14 + 6 * i << " changed";
}

// A first start shows the scene list, not half the window.
TEST(GalleryMenu, StartsNarrowAndFoldedToItsSceneList) {
  HeadlessImGui imgui;
  const SceneInfo& info = sceneWithPresets();
  StillScene scene(info);
  ParamPanel panel;
  MenuLayout layout;  // as on a first start
  const auto passes = somePasses(9);
  const auto draw = [&] {
    MenuState state{.current = info, .scene = scene, .fps = 60.0, .passes = passes, .panel = &panel, .layout = &layout};
    drawMenu(state);
  };
  for (int i = 0; i < 4; ++i) imgui.frame({-100, -100}, draw);
  const ImGuiWindow* menu = ImGui::FindWindowByName("Vitrine");
  ASSERT_NE(menu, nullptr);
  const float area = menu->Size.x * menu->Size.y;
  EXPECT_LT(menu->Size.x, 1280.0f * 0.3f) << menu->Size.x;
  EXPECT_LT(area, 1280.0f * 720.0f * 0.15f) << menu->Size.x << "x" << menu->Size.y;
}

// What the menu remembers comes back from its ini lines; anything else in them is ignored.
TEST(GalleryMenu, LayoutSurvivesItsIniLines) {
  MenuLayout open;
  open.panel = open.timings = true;
  open.rig = false;
  open.passRows = 12;
  MenuLayout read;
  std::string text = open.text();
  for (size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
    read.readLine(std::string_view(text).substr(start, end - start));
  read.readLine("time=banana");
  read.readLine("unknown=1");
  EXPECT_FALSE(read.time);
  EXPECT_TRUE(read.panel);
  EXPECT_TRUE(read.timings);
  EXPECT_FALSE(read.rig);
  EXPECT_EQ(read.passRows, 12);
  read.readLine("pass_rows=100000");
  EXPECT_LE(read.passRows, 64);
}

// Digits typed into a field switched scenes. At a few frames a second the click that
// activates the field and the digits typed after it arrive in one frame: the gallery asks after the
// menu has seen the click, when the field already has the keyboard (WantTextInput says so only a
// frame later).
TEST(GalleryMenu, AFieldActivatedThisFrameHasTheKeyboard) {
  HeadlessImGui imgui;
  const SceneInfo& info = sceneWithPresets();
  StillScene scene(info);
  ParamPanel panel;
  MenuLayout layout;
  layout.time = true;
  TimeControl time;
  const auto draw = [&] {
    MenuState state{.current = info, .scene = scene, .fps = 60.0, .panel = &panel, .time = time, .layout = &layout};
    time = drawMenu(state).time;
  };
  for (int i = 0; i < 4; ++i) imgui.frame({-100, -100}, draw);
  // Find the speed slider by hovering down the menu.
  const ImGuiID speed = [&] {
    ImGuiWindow* menu = ImGui::FindWindowByName("Vitrine");
    return menu->GetID("speed");
  }();
  float y = 14.0f;
  for (; y < 700.0f; y += 2.0f) {
    imgui.frame({40.0f, y}, draw);
    if (imgui.frame({40.0f, y}, draw) == speed) break;
  }
  ASSERT_LT(y, 700.0f) << "no speed slider in the open time section";
  EXPECT_FALSE(menuHasKeyboard());
  imgui.frame({40.0f, y}, draw, /*down=*/true, /*ctrl=*/true);  // Ctrl+click: the slider becomes a field
  EXPECT_FALSE(ImGui::GetIO().WantTextInput) << "(what the gallery asked before: not yet)";
  EXPECT_TRUE(menuHasKeyboard()) << "the field has the keyboard in the frame it was clicked";
  imgui.frame({40.0f, y}, draw);
  EXPECT_TRUE(menuHasKeyboard());
}

// The speed field showed any number typed into it.
TEST(GalleryMenu, TheSpeedFieldClampsWhatIsTyped) {
  HeadlessImGui imgui;
  const SceneInfo& info = sceneWithPresets();
  StillScene scene(info);
  ParamPanel panel;
  MenuLayout layout;
  TimeControl time;
  time.speed = 111111114326016.0f;
  MenuState state{.current = info, .scene = scene, .panel = &panel, .time = time, .layout = &layout};
  MenuChoice choice;
  imgui.frame({-100, -100}, [&] { choice = drawMenu(state); });
  EXPECT_EQ(choice.time.speed, TimeControl::kMaxSpeed);
}

// The preset list always read "choose...": it names the preset the values match.
TEST(ParamPanel, NamesThePresetTheValuesMatch) {
  const SceneInfo& info = sceneWithPresets();
  StillScene scene(info);
  const params::Bound bound = scene.parameters();
  const params::Preset& first = info.schema().presets().front();
  EXPECT_EQ(presetLabel(bound), matchingPreset(bound) ? matchingPreset(bound)->name : "defaults");
  ASSERT_TRUE(params::applyValues(bound, first.values).empty());
  const params::Preset* matching = matchingPreset(bound);
  ASSERT_NE(matching, nullptr);
  EXPECT_EQ(matching->values, first.values) << matching->name;  // that one, or one with the same values
  // One value the preset sets, moved off it: the values are the user's own.
  bool moved = false;
  for (const auto& [key, value] : first.values) {
    const params::Param* param = info.schema().find(key);
    if (!param || (param->kind != params::Kind::Float && param->kind != params::Kind::Int)) continue;
    const double now = param->number(bound.settings);
    const double other = now == param->max ? param->min : param->max;
    const std::string text = param->kind == params::Kind::Int ? std::to_string(int(other)) : params::formatFloat(float(other));
    ASSERT_TRUE(params::applyValues(bound, {{key, text}}).empty()) << key << "=" << text;
    moved = true;
    break;
  }
  ASSERT_TRUE(moved) << "the first preset sets no number";
  EXPECT_EQ(matchingPreset(bound), nullptr);
  EXPECT_EQ(presetLabel(bound), "custom");
}

TEST(Wording, CountsAreSingularForOne) {
  EXPECT_EQ(counted(1, "message"), "1 message");
  EXPECT_EQ(counted(0, "message"), "0 messages");
  EXPECT_EQ(counted(8, "frame"), "8 frames");
}

// The quality choice reads the tier auto runs at: on a CPU device a scene starts low without any
// "tier" event, and the menu must say so, as the scene's own line under it does.
TEST(TierWatch, AutoStartsAtTheDevicesStartingTier) {
  TierWatch watch;
  watch.setStartingTier("low");
  watch.started("kifs");
  EXPECT_EQ(watch.describe("kifs", {{"tier", "auto"}}), "auto: low");
  watch.emit(1.0, "kifs", {"tier", {{"from", std::string("low")}, {"to", std::string("medium")}}});
  EXPECT_EQ(watch.describe("kifs", {{"tier", "auto"}}), "auto: medium");
  EXPECT_EQ(watch.describe("kifs", {{"tier", "high"}}), "");
  watch.started("kifs");  // made afresh: back to where a new scene starts
  EXPECT_EQ(watch.describe("kifs", {{"tier", "auto"}}), "auto: low");
}

}  // namespace
}  // namespace vitrine::host
