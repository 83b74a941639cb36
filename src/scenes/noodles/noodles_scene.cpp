// noodles: streamlines of divergence-free noise (seed 004), integrated on the GPU one strand per
// invocation and drawn as instanced tubes, a few thousand strands by default and millions on demand.
#include "scenes/noodles/noodles_scene.h"

#include "gpu/barriers.h"
#include "gpu/check.h"
#include "gpu/resources.h"
#include "scenes/noodles/camera_rig.h"
#include "scenes/noodles/integrate_pass.h"
#include "scenes/noodles/settings.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/tube_pass.h"

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
      : device_(context.device),
        budget_(deviceBudget(context.device)),
        integrate_(context.programs),
        tubes_(context.device, context.programs) {
    ensureStrands();
  }
  // Frames in flight may still read the nodes and attachments released with the members.
  ~NoodlesScene() override { device_.waitIdle(); }

  void update(const FrameInput& input) override {
    // The drift accumulates time x speed, so changing the speed never jumps the field.
    if (!lastTime_) writhe_ = input.time * settings_.speed;
    else writhe_ += (input.time - *lastTime_) * settings_.speed;
    lastTime_ = input.time;
    reducedMotion_ = input.reducedMotion;
    camera_.update(input, nestRadius(), nestCentre());
  }

  void record(const FrameContext& frame) override {
    ensureStrands();
    const StrandSettings strands = strandSettings();
    if (integrated_ != strands) {  // nothing moves under reduced motion: integrate once
      const auto pass = frame.pass("noodles integrate");
      // Earlier draws have finished reading the nodes, earlier dispatches writing them.
      gpu::memoryBarrier(frame.cmd, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      integrate_.record(frame.cmd, layout_, nodes_.handle(), strands);
      gpu::memoryBarrier(frame.cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
      integrated_ = strands;
    }
    const auto pass = frame.pass("noodles draw");
    tubes_.record(frame.cmd, frame.target, layout_, nodes_.handle(), tubeView(frame.target.extent));
  }

  bool setParameter(std::string_view key, std::string_view value, std::string* error) override {
    if (key == "orbit") return setOrbit(value, error);
    NoodleSettings changed = settings_;
    if (!applyParameter(changed, key, value, error)) return false;
    try {  // refuse a size the device cannot hold now, rather than fail at the next frame
      planStrands(changed.grid, uint32_t(changed.segments), budget_);
    } catch (const Error& e) {
      *error = e.what();
      return false;
    }
    settings_ = changed;
    return true;
  }

  std::vector<std::string> parameterNames() const override { return noodles::parameterNames(); }

  void drawPanel() override;

 private:
  // (Re)allocates the node buffer when grid or segments changed; idles the GPU first, since frames
  // in flight may still read the old one. Nothing is allocated in frames where they did not change.
  void ensureStrands() {
    const glm::uvec3 grid = settings_.grid;
    const uint32_t segments = uint32_t(settings_.segments);
    if (nodes_ && layout_.grid == grid && layout_.segments == segments) return;
    StrandLayout layout = planStrands(grid, segments, budget_);
    if (nodes_) device_.waitIdle();
    nodes_ = {};  // free the old buffer before allocating the new one
    nodes_ = gpu::Buffer(device_, layout.bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                         gpu::MemoryUse::Device, "noodles nodes");
    layout_ = std::move(layout);
    integrated_.reset();
  }

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

  TubeView tubeView(VkExtent2D extent) const {
    const CameraPose pose = camera_.pose();
    const float aspect = float(extent.width) / float(std::max(extent.height, 1u));
    return {reverseZPerspective(kFieldOfViewY, aspect, kNearPlane) * lookAtZUp(pose.eye, pose.target), pose.eye,
            settings_.radius, settings_.colour, settings_.stripe, settings_.msaa};
  }

  bool setOrbit(std::string_view value, std::string* error) {
    if (value == "off") {
      camera_.unpin();
      return true;
    }
    float orbit[3];
    if (!parseOrbit(value, orbit, error)) return false;
    if (std::fabs(orbit[1]) > kMaxElevation || orbit[2] <= 0.0f) {
      *error = fmt::format("the elevation must lie within +-{} and the distance be positive", kMaxElevation);
      return false;
    }
    camera_.pin({orbit[0], orbit[1], orbit[2]});
    return true;
  }

  void setFromPanel(const char* key, const std::string& value) {
    std::string why;
    panelError_ = setParameter(key, value, &why) ? std::string() : fmt::format("{}={}: {}", key, value, why);
  }

  const gpu::Device& device_;
  const DeviceBudget budget_;
  NoodleSettings settings_;
  StrandLayout layout_;
  gpu::Buffer nodes_;
  std::optional<StrandSettings> integrated_;  // what the node buffer holds now
  IntegratePass integrate_;
  TubePass tubes_;
  CameraRig camera_;
  std::optional<double> lastTime_;
  double writhe_ = 0.0;  // noise units the potentials have drifted
  bool reducedMotion_ = false;
  // Panel edits to the buffer size apply on release, not on every slider step.
  int panelGrid_[3] = {0, 0, 0};
  int panelSegments_ = 0;
  std::string panelError_;
};

template <typename Enum, size_t N, typename Apply>
void choicePanel(const char* label, Enum value, const std::array<const char*, N>& names, const Apply& apply) {
  int index = int(value);
  if (ImGui::Combo(label, &index, names.data(), int(N))) apply(names[size_t(index)]);
}

void NoodlesScene::drawPanel() {
  ImGui::Text("%u strands x %u segments = %llu segments", layout_.strands, layout_.segments,
              static_cast<unsigned long long>(layout_.segmentCount));
  ImGui::Text("node buffer %s in %zu binding%s", describeBytes(layout_.bytes).c_str(), layout_.chunks.size(),
              layout_.chunks.size() == 1 ? "" : "s");

  if (!ImGui::IsAnyItemActive()) {
    for (int i = 0; i < 3; ++i) panelGrid_[i] = int(settings_.grid[i]);
    panelSegments_ = settings_.segments;
  }
  ImGui::SliderInt3("grid", panelGrid_, 1, 128);
  if (ImGui::IsItemDeactivatedAfterEdit())
    setFromPanel("grid", fmt::format("{}x{}x{}", panelGrid_[0], panelGrid_[1], panelGrid_[2]));
  ImGui::SliderInt("segments", &panelSegments_, 1, 1024, "%d", ImGuiSliderFlags_Logarithmic);
  if (ImGui::IsItemDeactivatedAfterEdit()) setFromPanel("segments", std::to_string(panelSegments_));

  ImGui::SliderFloat("step", &settings_.step, 0.001f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("noise scale", &settings_.noiseScale, 0.05f, 4.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("spacing", &settings_.spacing, 0.01f, 2.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("radius", &settings_.radius, 0.001f, 0.2f, "%.3f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("time speed", &settings_.speed, 0.0f, 4.0f, "%.2f");
  ImGui::SliderFloat("lift", &settings_.lift, -4.0f, 4.0f, "%.2f");

  const auto apply = [this](const char* key) { return [this, key](const char* value) { setFromPanel(key, value); }; };
  choicePanel("field", settings_.field, kFieldNames, apply("field"));
  choicePanel("integrator", settings_.integrator, kIntegratorNames, apply("integrator"));
  choicePanel("tangent", settings_.tangent, kTangentNames, apply("tangent"));
  choicePanel("frames", settings_.frames, kFrameNames, apply("frames"));
  choicePanel("colour", settings_.colour, kColourNames, apply("colour"));
  choicePanel("stripe", settings_.stripe ? 1 : 0, kStripeNames, apply("stripe"));
  choicePanel("msaa", settings_.msaa ? 1 : 0, kMsaaNames, apply("msaa"));
  if (!panelError_.empty()) ImGui::TextWrapped("%s", panelError_.c_str());
}

}  // namespace

const SceneInfo kSceneInfo{"noodles", "Curl-noise noodles", 5,
                           [](const SceneContext& context) -> std::unique_ptr<Scene> {
                             return std::make_unique<NoodlesScene>(context);
                           }};

}  // namespace vitrine::noodles
