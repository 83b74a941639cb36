// calibrate: a broadcast-style test card for setting up a screen or projector, and the strobe that
// checks the flash guard (docs/INSTALLATIONS.md).
#include "scenes/calibrate/calibrate_scene.h"

#include "scenes/calibrate/settings.h"
#include "shaders/calibrate/card_push.h"
#include "text/text_pass.h"

#include <fmt/format.h>
#include <imgui.h>

#include <cmath>
#include <string>

namespace vitrine::calibrate {
namespace {

const text::Shaping kCaps{0.12f};  // small caps, tracked
// Every character the caption can hold, so its glyphs are in the atlas from the start.
constexpr const char* kGlyphs = "VITRINE · OFFSCREEN GALLERY WINDOW 0123456789 ×";

class CalibrateScene final : public Scene {
 public:
  explicit CalibrateScene(const SceneContext& context)
      : output_(context.realtime ? "GALLERY WINDOW" : "OFFSCREEN"),
        card_(context.programs, "calibrate/card.comp"),
        font_(text::Font::fromAssets(context.assets, "CormorantSC")),
        text_(context, {{&font_, {kGlyphs}, kCaps}}) {}

  void resize(VkExtent2D target) override {
    caption_ = text_.layout(font_, fmt::format("VITRINE · {} · {} × {}", output_, target.width, target.height), kCaps);
  }

  // The strobe follows simulation time, not frames, so it flashes at its rate at any frame rate; it
  // ignores reduced motion on purpose (see the parameter's help).
  void update(const FrameInput& input) override {
    const double phase = input.time * double(settings_.strobeHz);
    lit_ = phase - std::floor(phase) < 0.5;
  }

  void record(const FrameContext& frame) override {
    if (!frame.draws) return;  // a frame depends on its time alone
    {
      const auto pass = frame.pass("calibrate card");
      const glm::vec3 colour = settings_.strobeColour == StrobeColour::Red ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(1.0f);
      frame.transition(frame.target, gpu::use::ComputeWrite);
      card_.bind(frame.cmd);
      card_.push(frame.cmd, gpu::Bindings().storageImage("target", frame.target.view()));
      card_.constants(frame.cmd, shader::CalibrateCardPush{glm::vec4(colour, 0.0f), lit_ ? 1u : 0u,
                                                           settings_.strobe ? 1u : 0u});
      card_.dispatchOver(frame.cmd, frame.target.extent2d());
    }
    const auto pass = frame.pass("calibrate type");
    const float height = float(frame.target.extent2d().height);
    text::TextDraw caption;
    caption.layout = &caption_;
    caption.position = {0.5f, 0.566f};  // in the dark band, below the centre cross's arm
    caption.normalized = true;
    caption.sizePx = height * 0.032f;
    caption.color = glm::vec4(0.85f, 0.85f, 0.85f, 1.0f);
    text_.record(frame, {caption});
  }

  void drawPanel() override {
    ImGui::TextUnformatted("Grid squares are square and circles round when the output is not stretched.");
    if (settings_.strobe) ImGui::TextUnformatted("The strobe is on: turn on the flash guard before watching.");
  }

  params::Bound parameters() override { return {&schema(), &settings_}; }
  bool checkpoints() const override { return true; }  // a frame depends on its time and parameters alone

 private:
  std::string output_;
  gpu::ComputeProgram card_;
  text::Font font_;
  text::TextPass text_;
  text::TextLayout caption_;
  Settings settings_;
  bool lit_ = false;
};

}  // namespace

std::unique_ptr<Scene> create(const SceneContext& context) { return std::make_unique<CalibrateScene>(context); }

}  // namespace vitrine::calibrate
