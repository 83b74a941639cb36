// glass: spectral dispersion through SDF glass (seed 001, "Spectral Glass"). A frame is four passes,
// each in its own file:
// - compose (compose_pass.h), only when the backdrop's source or the view's size changes: the photo,
//   gradient or checker, for the page its paper and text, then the mip chain the glass samples;
// - spectral (spectral_pass.h): the per-wavelength work where glass covers the screen, by default a
//   compute pass over the screen, or the original's instanced proxies; it writes colour and motion;
// - resolve (resolve_pass.h): the backdrop or panorama where no glass is, then the history, an EMA
//   reprojected from last frame's rotations and places, progressive while the world stands still;
// - post (post_pass.h): the tone map, then FXAA if chosen.
// The scene itself keeps the clock and the settings, reads the input (input.h), moves the instances
// (instances.h), loads the pictures (picture_textures.h) and fills the frame block (frame_values.h).
// Optics, shapes and the diamond live in plain C++ the shaders mirror (optics.h, shapes.h, diamond.h).
#include "scenes/glass/glass_scene.h"
#include "scenes/adaptive_quality.h"

#include "scenes/glass/compose_pass.h"
#include "scenes/glass/diamond_buffers.h"
#include "scenes/glass/frame_values.h"
#include "scenes/glass/input.h"
#include "scenes/glass/instances.h"
#include "scenes/glass/materials.h"
#include "scenes/glass/picture_textures.h"
#include "scenes/glass/post_pass.h"
#include "scenes/glass/resolve_pass.h"
#include "scenes/glass/scene_shape.h"
#include "scenes/glass/screen_images.h"
#include "scenes/glass/settings.h"
#include "scenes/glass/spectral_pass.h"
#include "scenes/glass/world_view.h"

#include <imgui.h>

#include <string>

namespace vitrine::glass {

class GlassScene final : public Scene {
 public:
  explicit GlassScene(const SceneContext& context)
      : quality_(context),
        compose_(context),
        spectral_(context.programs),
        resolve_(context.programs),
        post_(context.programs),
        screen_(context.resources),
        pictures_(context),
        diamond_(context.resources, Settings{}.diamondSize) {
    // Laid out before the first resize, in a square view: the opening places the golden frames hold.
    instances_.layOut(settings_.shape, viewSize(moment_.extent));
  }

  void resize(VkExtent2D target) override {
    moment_.extent = target;
    backdropDirty_ = true;
    resetHistory_ = true;
  }

  void update(const FrameInput& input) override;
  void record(const FrameContext& frame) override;
  params::Bound parameters() override { return {&schema(), &settings_}; }
  // A background or panorama that names nothing usable refuses the change: headless runs stop with the
  // value named, the gallery's panel shows why and keeps what it had.
  std::string checkParameters() const override { return pictures_.problem(settings_); }
  float renderScale() const override { return tierScale(quality_.active()); }
  void drawPanel() override;

 private:
  void syncMaterial();
  void applyKeys(const KeyRequests& keys);

  AdaptiveQuality quality_;
  ComposePass compose_;
  SpectralShadePass spectral_;
  ResolvePass resolve_;
  PostPass post_;
  ScreenImages screen_;
  PictureTextures pictures_;
  DiamondBuffers diamond_;
  Instances instances_;

  Settings settings_;
  Settings applied_;  // last frame's values: any change restarts the accumulation
  FrameMoment moment_;
  bool resetHistory_ = true;
  bool backdropDirty_ = true;
  uint32_t pausedFrames_ = 0;  // frames averaged while the world stands still
};

// The material choice and the two sliders agree: picking a material sets n_d and V_d; moving either
// slider away from the material's values makes it custom.
void GlassScene::syncMaterial() {
  if (settings_.material != applied_.material && settings_.material > 0) {
    const Material& m = kMaterials[size_t(settings_.material - 1)];
    settings_.ior = m.nd;
    settings_.abbe = m.vd;
  } else if (settings_.material > 0) {
    const Material& m = kMaterials[size_t(settings_.material - 1)];
    if (settings_.ior != m.nd || settings_.abbe != m.vd) settings_.material = 0;
  }
}

void GlassScene::applyKeys(const KeyRequests& keys) {
  if (keys.shuffle) {
    instances_.shuffle(settings_.shape, shapeDims(settings_, moment_.time), viewSize(moment_.extent), moment_.seed);
    resetHistory_ = true;
  }
  if (keys.nextPhoto) pictures_.nextPhoto();
  applyDiamondView(keys, settings_);
  if (keys.zHeld != moment_.zHeld) resetHistory_ = true;
  moment_.zHeld = keys.zHeld;
}

void GlassScene::update(const FrameInput& input) {
  quality_.update(settings_.tier, settings_.targetMs, input);
  moment_.tier = quality_.active();
  moment_.seed = input.seed;
  moment_.frame = input.frame;
  moment_.previousTime = moment_.time;
  if (!settings_.stopWorld && !input.reducedMotion) moment_.time += input.dt;
  instances_.beginFrame();

  syncMaterial();
  if (settings_.shape != instances_.laidOut()) instances_.layOut(settings_.shape, viewSize(moment_.extent));
  applyKeys(readKeys(input));
  instances_.drag(input.cursor, settings_.shape, shapeDims(settings_, moment_.time), viewSize(moment_.extent));
  takeDroppedFiles(input, settings_);

  diamond_.resize(settings_.diamondSize);
  const PictureTextures::Loaded loaded = pictures_.update(settings_);
  if (loaded.photo) backdropDirty_ = true;
  if (loaded.panorama) resetHistory_ = true;

  // In motion the reprojected average lets go of old optics within a few frames, as of an old place, so
  // a glide of ior, abbe, spread or strength (live input plays them) does not throw the history away each frame.
  Settings compared = settings_;
  if (!settings_.stopWorld)
    compared.ior = applied_.ior, compared.abbe = applied_.abbe, compared.spread = applied_.spread,
    compared.strength = applied_.strength;
  if (!(compared == applied_)) resetHistory_ = true;
  // A drag while the world stands still restarts the progressive average; in motion the reprojected
  // EMA lets go of the old place within a few frames anyway.
  if (settings_.stopWorld && instances_.moved()) resetHistory_ = true;
  applied_ = settings_;
  if (settings_.stopWorld) pausedFrames_ = resetHistory_ ? 1 : pausedFrames_ + 1;
  else pausedFrames_ = 0;
}

void GlassScene::record(const FrameContext& frame) {
  gpu::Image& backdrop = frame.image(screen_.backdrop);
  if (backdropDirty_) {
    const auto pass = frame.pass("glass backdrop");
    compose_.record(frame, backdrop, frame.image(pictures_.photo()), pictures_.backdropKind(), pictures_.photoSize(),
                    moment_.extent);
    backdropDirty_ = false;
  }
  const shader::GlassFrame block = frameBlock(settings_, moment_, instances_);
  const FrameSources sources{frame.uniform(block), backdrop, frame.image(pictures_.panorama())};
  {
    const auto pass = frame.pass("glass spectral");
    spectral_.record(frame, sources, screen_, diamond_, settings_.pass, {settings_.shape, shadeOptions(block)},
                     moment_.extent);
  }
  {
    const auto pass = frame.pass("glass resolve");
    const Accumulation accumulation{resetHistory_, settings_.stopWorld, settings_.historyAlpha, pausedFrames_};
    resolve_.record(frame, sources, screen_, accumulation, moment_.extent);
    resetHistory_ = false;
  }
  const auto pass = frame.pass("glass post");
  post_.record(frame, frame.image(screen_.history), settings_, moment_.extent);
}

void GlassScene::drawPanel() {
  const int n = moment_.zHeld ? 3 : tierWavelengths(sampleCount(settings_), moment_.tier, settings_.jitter);
  ImGui::Text("%d wavelengths%s, %s optics", n, moment_.zHeld ? " (Z held: jitter off)" : "",
              settings_.optics == Optics::Physical ? "physical" : "seed");
  if (settings_.material > 0) {
    const Material& m = kMaterials[size_t(settings_.material - 1)];
    ImGui::Text("%s: n_d %.4f, V_d %.1f%s", std::string(m.label).c_str(), m.nd, m.vd,
                m.sellmeier ? ", Sellmeier known" : "");
  }
  if (!settings_.environment) {
    const std::string name = pictures_.photoName();
    ImGui::Text("backdrop: %s%s", settings_.background.c_str(), name.empty() ? "" : (" - " + name).c_str());
  }
  const auto warning = [](const std::string& line) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", line.c_str());
    ImGui::PopStyleColor();
  };
  if (!pictures_.backgroundProblem().empty()) warning(pictures_.backgroundProblem());
  if (settings_.environment && !pictures_.panoramaProblem().empty()) warning(pictures_.panoramaProblem());
  if (settings_.stopWorld) ImGui::Text("accumulated %u frames", pausedFrames_);
  ImGui::TextDisabled("drag a shape; Space shuffles, R next photo, hold Z, T/S/B/F the diamond from the top, side, below or tumbling");
}

std::unique_ptr<Scene> create(const SceneContext& context) { return std::make_unique<GlassScene>(context); }

}  // namespace vitrine::glass
