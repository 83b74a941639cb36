// kifs: the volumetric KIFS fractal of seed 003, rebuilt stage by stage in one compute pass.
#include "scenes/kifs/kifs_scene.h"
#include "gpu/program_variants.h"
#include "scenes/adaptive_quality.h"

#include "scenes/kifs/kifs_math.h"
#include "scenes/kifs/settings.h"
#include "scenes/quality.h"
#include "shaders/kifs/march_push.h"

#include <imgui.h>


namespace vitrine::kifs {
namespace {

const std::vector<std::string> kStageNames = {
    "1 glowing sphere",  "2 under-stepped march", "3 hard union",      "4 smooth union",          "5 domain warp",
    "6 fold + scale",    "7 orbit trap",          "8 ACES + vignette", "9 jitter + grain (final)"};

TierMarch settingsFor(Tier tier) { return kTierMarch[int(tier)]; }

class KifsScene final : public Scene {
 public:
  explicit KifsScene(const SceneContext& context) : quality_(context), marches_(context.programs, "kifs/kifs.comp") {}

  void update(const FrameInput& input) override {
    if (input.cursor.dragging) {
      settings_.dragX += input.cursor.dragDelta.x * 2.0f;
      settings_.dragY += input.cursor.dragDelta.y * 2.0f;
    }
    angles_ = tumbleAngles(input.reducedMotion ? 0.0 : input.time, {settings_.dragX, settings_.dragY});
    reducedMotion_ = input.reducedMotion;
    quality_.update(settings_.tier, settings_.targetMs, input);
  }

  void record(const FrameContext& frame) override {
    if (!frame.draws) return;  // nothing but the march, and a frame depends on its time alone
    const auto pass = frame.pass("kifs march");
    const shader::KifsMarchPush push{angles_,
                    uint32_t(frame.input.frame),
                    frame.input.seed,
                    settingsFor(activeTier()).marchSteps,
                    reducedMotion_ ? 0.0f : 0.045f,
                    reducedMotion_ ? 0u : uint32_t(frame.input.frame),
                    settings_.fold};
    frame.transition(frame.target, gpu::use::ComputeWrite);
    const gpu::ComputeProgram& march = marches_({settings_.step});
    march.bind(frame.cmd);
    march.push(frame.cmd, gpu::Bindings().storageImage("target", frame.target.view()));
    march.constants(frame.cmd, push);
    march.dispatchOver(frame.cmd, frame.target.extent2d());
  }

  float renderScale() const override { return settingsFor(activeTier()).renderScale; }

  void drawPanel() override {
    ImGui::TextUnformatted(kStageNames[size_t(settings_.step - 1)].c_str());
    const auto tier = settingsFor(activeTier());
    ImGui::Text("%s: %d march steps, render scale %.2f", quality_.describe().c_str(), tier.marchSteps, tier.renderScale);
  }

  params::Bound parameters() override { return {&schema(), &settings_}; }
  // A frame depends on its time and the parameters alone (a drag lands in dragX and dragY).
  bool checkpoints() const override { return true; }

 private:
  Tier activeTier() const { return quality_.active(); }

  AdaptiveQuality quality_;
  gpu::ComputeVariants marches_;  // kifs.comp specialised on the teaching stage (KIFS_STAGE)
  Settings settings_;
  glm::vec2 angles_{0.0f};
  bool reducedMotion_ = false;
};

}  // namespace

std::unique_ptr<Scene> create(const SceneContext& context) { return std::make_unique<KifsScene>(context); }

}  // namespace vitrine::kifs
