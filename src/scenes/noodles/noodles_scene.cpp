// noodles: streamlines of divergence-free noise (seed 004), integrated on the GPU one strand per
// invocation and drawn as round tubes by a compute rasteriser (ray-capsule casts into a visibility
// buffer, then one shading pass), a few thousand strands by default and millions on demand.
#include "scenes/noodles/noodles_scene.h"
#include "scenes/adaptive_quality.h"

#include "core/error.h"
#include "gpu/frame_resources.h"
#include "scenes/noodles/camera_rig.h"
#include "scenes/noodles/integrate_pass.h"
#include "scenes/noodles/raster_pass.h"
#include "scenes/noodles/settings.h"
#include "scenes/noodles/shade_pass.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/tube_view.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace vitrine::noodles {
namespace {

class NoodlesScene final : public Scene {
 public:
  explicit NoodlesScene(const SceneContext& context)
      : resources_(context.resources),
        device_(context.device),
        events_(context.events),
        quality_(context),
        budget_(deviceBudget(context.device)),
        integrate_(context.programs),
        raster_(context),
        shade_(context.programs) {
    ensureStrands();
  }

  void update(const FrameInput& input) override {
    // The drift accumulates time x speed, so changing the speed never jumps the field.
    if (!lastTime_) writhe_ = input.time * settings_.speed;
    else writhe_ += (input.time - *lastTime_) * settings_.speed;
    lastTime_ = input.time;
    reducedMotion_ = input.reducedMotion;
    quality_.update(settings_.tier, settings_.targetMs, input);
    if (settings_.orbit != pinned_) {
      pinned_ = settings_.orbit;
      if (pinned_.pinned) camera_.pin({pinned_.azimuth, pinned_.elevation, pinned_.distance});
      else camera_.unpin();
    }
    camera_.update(input, nestRadius(), nestCentre());
    // A drag takes the camera off its flight and a release sends it back: tests and recordings see when.
    if (input.cursor.dragging != dragging_) {
      dragging_ = input.cursor.dragging;
      events_.emit(input.time, {dragging_ ? "orbit_grab" : "orbit_release",
                                {{"x", input.cursor.normalized.x}, {"y", input.cursor.normalized.y}}});
    }
  }

  void record(const FrameContext& frame) override {
    if (!frame.draws) return;  // the strands are integrated afresh from the settings each time they change
    ensureStrands();
    const StrandSettings strands = strandSettings();
    gpu::Buffer& nodes = frame.buffer(nodes_);
    if (integrated_ != strands) {  // nothing moves under reduced motion: integrate once
      ensureBakeVolume(strands.bake);
      BakedFlow baked;
      if (strands.bake.baked()) {
        const auto pass = frame.pass("noodles bake");
        gpu::Image& volume = frame.image(bakeVolume_);
        frame.transition(volume, gpu::use::ComputeWrite);
        integrate_.recordBake(frame.cmd, strands, volume.storageView());
        frame.transition(volume, gpu::use::ComputeSample);
        baked = {volume.view(), device_.sampler(gpu::Device::Filter::Nearest, gpu::Device::Address::Clamp)};
      }
      const auto pass = frame.pass("noodles integrate");
      frame.transition(nodes, gpu::use::ComputeWriteBuffer);
      integrate_.record(frame.cmd, layout_, nodes.handle(), strands, baked);
      integrated_ = strands;
    }
    frame.transition(nodes, gpu::use::ComputeReadBuffer);
    const TubeView view = tubeView(frame.target.extent2d());
    {
      const auto pass = frame.pass("noodles raster");
      raster_.record(frame, layout_, nodes.handle(), view);
    }
    const auto pass = frame.pass("noodles shade");
    shade_.record(frame, layout_, nodes.handle(), raster_.visibility(frame), raster_.samplesPerAxis(), view);
  }

  params::Bound parameters() override { return {&schema(), &settings_}; }
  float renderScale() const override { return tierScale(quality_.active()); }
  double frameCost(const void* values) const override {  // segments integrated and drawn
    const auto& v = *static_cast<const NoodleSettings*>(values);
    return double(v.grid.x) * v.grid.y * v.grid.z * double(v.segments);
  }

  // Refuses strands the device cannot hold, judged on the final grid and segment count together.
  std::string checkParameters() const override {
    try {
      planStrands(settings_.grid, uint32_t(settings_.segments), budget_, workgroups());
      return {};
    } catch (const Error& e) {
      return e.what();
    }
  }

  void drawPanel() override;

  // The strands are integrated afresh from the settings and the drift: only the drift and the camera
  // carry over from frame to frame.
  bool checkpoints() const override { return true; }
  void simulationState(StateArchive& state) override {
    state(writhe_, lastTime_, reducedMotion_, pinned_, dragging_, camera_);
    if (state.isRestoring()) integrated_.reset();
  }

 private:
  // (Re)declares the node buffer when grid or segments changed (the host retires the old one, which
  // frames in flight may still read). Nothing is allocated in frames where they did not change.
  void ensureStrands() {
    const glm::uvec3 grid = settings_.grid;
    const uint32_t segments = uint32_t(settings_.segments);
    const bool declared = layout_.segments > 0;
    if (declared && layout_.grid == grid && layout_.segments == segments) return;
    StrandLayout layout = planStrands(grid, segments, budget_, workgroups());
    const gpu::BufferDecl nodes{.name = "noodles nodes",
                                .size = gpu::BufferSize::absolute(layout.bytes),
                                .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT};
    if (declared) resources_.redeclare(nodes_, nodes);
    else nodes_ = resources_.declare(nodes);
    layout_ = std::move(layout);
    integrated_.reset();
  }

  // (Re)declares the baked flow's volume when its size changes; an exact flow leaves one texel.
  void ensureBakeVolume(const FieldBake& bake) {
    const glm::uvec3 size = bake.baked() ? bake.texels : glm::uvec3(1);
    if (bakeDeclared_ == size) return;
    const gpu::ImageDecl decl{.name = "noodles baked flow",
                              .format = kBakedFlowFormat,
                              .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                              .size = gpu::ImageSize::absolute(size.x, size.y, size.z),
                              .storageFormat = kBakedFlowStorageFormat};
    if (bakeDeclared_ == glm::uvec3(0)) bakeVolume_ = resources_.declare(decl);
    else resources_.redeclare(bakeVolume_, decl);
    bakeDeclared_ = size;
  }

  StrandWorkgroups workgroups() const { return {integrate_.workgroupSize(), raster_.workgroupSize()}; }

  StrandSettings strandSettings() const {
    StrandSettings s;
    s.grid = layout_.grid;
    s.segments = layout_.segments;
    s.spacing = settings_.spacing;
    s.step = settings_.step;
    s.field = fieldAtTime(settings_.field, settings_.noiseScale, settings_.lift, reducedMotion_ ? 0.0 : writhe_);
    s.integrator = settings_.integrator;
    s.tangent = settings_.tangent;
    s.frames = settings_.frames;
    s.bake = planFieldBake(s, settings_.fieldSource);
    return s;
  }

  // Roughly how far the strands reach from the nest centre: half the seed grid plus most of a
  // strand (curl noise moves at about 1.1 units per unit step, bitangent at 0.5; strands curl back).
  float nestRadius() const {
    const glm::vec3 extent = (glm::vec3(settings_.grid) - 1.0f) * settings_.spacing;
    const float halfGrid = 0.5f * std::max(extent.x, std::max(extent.y, extent.z));
    return std::max(halfGrid + 0.75f * float(settings_.segments) * settings_.step, 0.5f);
  }

  // Lift carries the whole nest upwards by about half a strand's climb: look at its middle.
  glm::vec3 nestCentre() const {
    const float lift = settings_.lift;
    const float climb = settings_.tangent == TangentMode::Raw ? lift : lift / std::sqrt(lift * lift + 1.0f);
    return {0.0f, 0.0f, 0.5f * float(settings_.segments) * settings_.step * climb};
  }

  // Every tier casts the samples msaa asks for: one a pixel breaks tubes thinner than a pixel into
  // dots, so lower tiers render fewer pixels instead.
  TubeView tubeView(VkExtent2D extent) const {
    return {screenViewOf(camera_.pose(), glm::vec2(float(extent.width), float(extent.height))), settings_.radius,
            settings_.colour, settings_.stripe, settings_.msaa, settings_.occluders};
  }

  gpu::FrameResources& resources_;
  const gpu::Device& device_;
  SceneEvents events_;
  AdaptiveQuality quality_;
  const DeviceBudget budget_;
  NoodleSettings settings_;
  StrandLayout layout_;  // segments 0 until the node buffer is declared
  gpu::BufferHandle nodes_;
  gpu::ImageHandle bakeVolume_;
  glm::uvec3 bakeDeclared_{0};  // the baked flow volume's size, 0 until declared
  std::optional<StrandSettings> integrated_;  // what the node buffer holds now
  IntegratePass integrate_;
  RasterPass raster_;
  ShadePass shade_;
  CameraRig camera_;
  std::optional<double> lastTime_;
  double writhe_ = 0.0;  // noise units the potentials have drifted
  bool reducedMotion_ = false;
  OrbitPin pinned_;  // what the camera rig was last told
  bool dragging_ = false;
};

void NoodlesScene::drawPanel() {
  ImGui::Text("%s; %u strands x %u segments = %llu segments", quality_.describe().c_str(), layout_.strands, layout_.segments,
              static_cast<unsigned long long>(layout_.segmentCount));
  if (integrated_ && integrated_->bake.baked()) {
    const FieldBake& bake = integrated_->bake;
    ImGui::Text("flow baked into %ux%ux%u texels (%s)", bake.texels.x, bake.texels.y, bake.texels.z,
                describeBytes(bake.count() * kBakedTexelBytes).c_str());
  } else {
    ImGui::Text("flow evaluated exactly at every step");
  }
  ImGui::Text("node buffer %s in %zu binding%s", describeBytes(layout_.bytes).c_str(), layout_.chunks.size(),
              layout_.chunks.size() == 1 ? "" : "s");
}

}  // namespace

std::unique_ptr<Scene> create(const SceneContext& context) { return std::make_unique<NoodlesScene>(context); }

}  // namespace vitrine::noodles
