// kifs: the volumetric KIFS fractal of seed 003, rebuilt stage by stage in one compute pass.
#include "scenes/kifs/kifs_scene.h"

#include "scenes/kifs/kifs_math.h"
#include "scenes/kifs/quality.h"
#include "scenes/parameters.h"

#include <imgui.h>

#include <array>

namespace vitrine::kifs {
namespace {

constexpr std::array<const char*, kStepCount> kStageNames = {
    "1 glowing sphere",  "2 under-stepped march", "3 hard union", "4 smooth union",          "5 domain warp",
    "6 fold + scale",    "7 orbit trap",          "8 ACES + vignette", "9 jitter + grain (final)"};
constexpr std::array<const char*, 4> kTierNames = {"auto", "high", "medium", "low"};

struct Push {
  glm::vec2 angles;
  uint32_t frame;
  uint32_t seed;
  int32_t step;
  int32_t maxSteps;
  float grain;
  uint32_t jitterFrame;
};

class KifsScene final : public Scene {
 public:
  explicit KifsScene(const SceneContext& context)
      : march_(context.programs, "kifs/kifs.comp", {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(Push)}) {}

  void update(const FrameInput& input) override {
    drag_ += input.cursor.dragging ? input.cursor.dragDelta * 2.0f : glm::vec2(0.0f);
    const float tumble = input.reducedMotion ? 0.0f : float(input.time);
    angles_ = tumble * kTumbleRate + drag_ * kDragToAngle;
    reducedMotion_ = input.reducedMotion;
    if (tier_ == Tier::Auto) active_ = autoTier_.observe(input.lastGpuMs, targetMs_);
  }

  void record(const FrameContext& frame) override {
    const auto pass = frame.pass("kifs march");
    const Push push{angles_,
                    uint32_t(frame.input.frame),
                    frame.input.seed,
                    step_,
                    settingsFor(activeTier()).marchSteps,
                    reducedMotion_ ? 0.0f : 0.045f,
                    reducedMotion_ ? 0u : uint32_t(frame.input.frame)};
    march_.bind(frame.cmd);
    march_.push(frame.cmd, gpu::Bindings().storageImage(frame.target.view));
    march_.constants(frame.cmd, push);
    march_.dispatchOver(frame.cmd, frame.target.extent, {8, 8});
  }

  float renderScale() const override { return settingsFor(activeTier()).renderScale; }

  void drawPanel() override {
    ImGui::SliderInt("stage", &step_, 1, kStepCount, kStageNames[step_ - 1]);
    int tier = int(tier_);
    if (ImGui::Combo("quality", &tier, kTierNames.data(), int(kTierNames.size()))) tier_ = Tier(tier);
    if (tier_ == Tier::Auto) {
      float target = float(targetMs_);
      if (ImGui::SliderFloat("target GPU ms", &target, 1.0f, 33.0f, "%.1f")) targetMs_ = target;
      ImGui::Text("auto tier: %s", kTierNames[int(active_)]);
    }
    const auto settings = settingsFor(activeTier());
    ImGui::Text("%d march steps, render scale %.2f", settings.marchSteps, settings.renderScale);
    if (ImGui::Button("reset drag")) drag_ = glm::vec2(0.0f);
  }

  bool setParameter(std::string_view key, std::string_view value, std::string* error) override {
    if (key == "step") return parseInt(value, 1, kStepCount, step_, error);
    if (key == "tier") {
      int index = 0;
      if (!parseChoice(value, kTierNames, index, error)) return false;
      tier_ = Tier(index);
      return true;
    }
    if (key == "target_ms") return parseFloat(value, 0.1f, 1000.0f, targetMs_, error);
    if (key == "drag_x") return parseFloat(value, -100.0f, 100.0f, drag_.x, error);
    if (key == "drag_y") return parseFloat(value, -100.0f, 100.0f, drag_.y, error);
    *error = "unknown parameter";
    return false;
  }

  std::vector<std::string> parameterNames() const override {
    return {"step", "tier", "target_ms", "drag_x", "drag_y"};
  }

 private:
  Tier activeTier() const { return tier_ == Tier::Auto ? active_ : tier_; }

  gpu::ComputeProgram march_;
  int step_ = kStepCount;
  Tier tier_ = Tier::High;
  Tier active_ = Tier::High;
  AutoTier autoTier_;
  float targetMs_ = 8.0f;
  glm::vec2 drag_{0.0f};
  glm::vec2 angles_{0.0f};
  bool reducedMotion_ = false;
};

}  // namespace

const SceneInfo kSceneInfo{"kifs", "Volumetric KIFS", 4,
                           [](const SceneContext& context) -> std::unique_ptr<Scene> {
                             return std::make_unique<KifsScene>(context);
                           }};

}  // namespace vitrine::kifs
