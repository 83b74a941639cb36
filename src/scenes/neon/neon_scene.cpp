// neon: CPU-controlled GPU particle chains drawn as neon tubes over a facade (seed 002, "Neon").
// A particle engine on its own thread owns each tube's life (released by the cursor or the autopilot,
// two steps initialising, then decaying); its heads stream to the GPU every frame through the host's
// upload ring, where a compute pass moves every chain: heads through curl noise, followers toward the
// particle ahead. The facade and the tubes are drawn in render passes; the tubes also go to a glow
// target that a mip-chain bloom blurs; depth of field, the tint, vignette, grain, aberration and the
// ground's mirror are compute passes.
#include "scenes/neon/neon_scene.h"
#include "scenes/adaptive_quality.h"

#include "scenes/neon/camera.h"
#include "scenes/neon/chains.h"
#include "scenes/neon/facade.h"
#include "scenes/neon/look.h"
#include "scenes/neon/look_passes.h"
#include "scenes/neon/particle_engine.h"
#include "scenes/neon/settings.h"
#include "scenes/neon/tube_light.h"
#include "lights/signals.h"
#include "maths/color.h"
#include "maths/hash.h"
#include "shaders/neon/facade_blocks.h"
#include "shaders/neon/frame.h"
#include "shaders/neon/merge_push.h"

#include <fmt/format.h>
#include <imgui.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace vitrine::neon {
namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr uint32_t kLightingSize = 512;
constexpr glm::vec3 kNightSky{0.004f, 0.005f, 0.012f};
// The lighting texture's light on the building, scaled down so the tubes, not the facade, hold the eye.
constexpr float kFacadeBrightness = 0.55f;
constexpr uint32_t kAutopilotPens = 3;
constexpr size_t kMaxChainStepsPerFrame = 16;  // steps kept for one frame at most (the host makes up 4)
// --reduced-motion: the heads swim this much slower, the flow does not drift, the autopilot releases
// a quarter as often, and the tint, ripples and grain stand still.
constexpr float kReducedMotionFlow = 0.35f;
constexpr float kReducedMotionAutopilot = 0.25f;

constexpr VkFormat kDepthCopyFormat = VK_FORMAT_R32_SFLOAT;  // the facade's depth, written by compute

gpu::ImageDecl screenImage(std::string name, VkFormat format, VkImageUsageFlags usage, uint32_t mips = 1) {
  return {std::move(name), format, usage, gpu::ImageSize::relative(1.0f), mips};
}

template <typename T> std::vector<std::byte> bytesOf(const std::vector<T>& values) {
  const auto bytes = std::as_bytes(std::span(values));
  return {bytes.begin(), bytes.end()};
}

// The heads, in device memory (every particle of a chain reads its head, every tube its release's
// colour), refreshed through the frame's upload ring whenever the chains move; all inactive at first.
gpu::BufferDecl headsDecl(int chains) {
  const std::vector<HeadState> inactive(size_t(chains), HeadState{});
  return {.name = "neon heads",
          .size = gpu::BufferSize::absolute(inactive.size() * sizeof(HeadState)),
          .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
          .initial = bytesOf(inactive),
          .initialUse = gpu::use::ComputeReadBuffer};
}

// Every particle's position and life, chain-major: a pair, as each chain step reads last step's and
// writes the other. Both start with every particle out of sight (life 0, under the ground) until its
// chain is released.
gpu::BufferDecl particlesDecl(int chains, int particles) {
  const std::vector<glm::vec4> hidden(size_t(chains) * particles, glm::vec4(0.0f, -100.0f, 0.0f, 0.0f));
  return {.name = "neon particles",
          .size = gpu::BufferSize::absolute(hidden.size() * sizeof(glm::vec4)),
          .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
          .pairing = gpu::Pairing::PingPong,
          .initial = bytesOf(hidden),
          .initialUse = gpu::use::ComputeReadBuffer,
          .state = true};  // checkpoints save the chains
}

// The building's boxes, uploaded once.
gpu::BufferDecl boxesDecl(const std::vector<Box>& boxes) {
  return {.name = "neon facade boxes",
          .size = gpu::BufferSize::absolute(boxes.size() * sizeof(Box)),
          .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
          .initial = bytesOf(boxes),
          .initialUse = gpu::use::ComputeReadBuffer};
}

gpu::GraphicsState tubeState() {
  gpu::GraphicsState state;
  state.vertex = "neon/tube.vert";
  state.fragment = "neon/tube.frag";
  state.colorFormats = {kColourFormat};  // the tubes' own light, merged into the scene and bloomed
  state.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  state.blend = gpu::GraphicsState::Blend::AdditiveMaxAlpha;  // alpha: the nearest tube's depth
  return state;
}

glm::vec3 linear(glm::vec3 srgb) { return maths::srgbToLinear(srgb); }

}  // namespace

class NeonScene final : public Scene {
 public:
  explicit NeonScene(const SceneContext& context)
      : device_(context.device),
        resources_(context.resources),
        events_(context.events),
        quality_(context),
        mode_(context.realtime ? EngineMode::Worker : EngineMode::LockStep),
        chains_(context.programs, "neon/chains.comp"),
        facade_(context.programs, "neon/facade.comp"),
        tubes_(context.programs, tubeState()),
        merge_(context.programs, "neon/merge.comp"),
        clear_(context.programs, "neon/clear.comp"),
        look_(context) {
    colour_ = resources_.declare(screenImage("neon scene", kColourFormat,
                                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
    depth_ = resources_.declare(screenImage("neon depth", kDepthCopyFormat,
                                            VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
    // The facade, drawn once a size: the camera never moves, so every frame's would be the same.
    facadeColour_ = resources_.declare(screenImage("neon facade colour", kColourFormat, VK_IMAGE_USAGE_STORAGE_BIT));
    facadeDepth_ = resources_.declare(screenImage("neon facade depth", kDepthCopyFormat,
                                                  VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
    glow_ = resources_.declare(screenImage("neon glow", kColourFormat,
                                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                               VK_IMAGE_USAGE_STORAGE_BIT));
    const std::vector<uint8_t> texels = facadeLightingTexture(kLightingSize);
    gpu::ImageDecl lighting{"neon facade lighting", VK_FORMAT_R8G8B8A8_SRGB, VK_IMAGE_USAGE_SAMPLED_BIT,
                            gpu::ImageSize::absolute(kLightingSize, kLightingSize), 0};
    lighting.initial = bytesOf(texels);
    lighting.initialUse = gpu::use::ComputeSample;
    lighting_ = resources_.declare(std::move(lighting));
    const std::vector<Box> boxes = facadeBoxes();
    boxCount_ = uint32_t(boxes.size());
    boxes_ = resources_.declare(boxesDecl(boxes));
    heads_ = resources_.declare(headsDecl(settings_.chains));
    particles_ = resources_.declare(particlesDecl(settings_.chains, settings_.particles));
    startEngine();
  }

  void resize(VkExtent2D target) override {
    extent_ = target;
    glowCleared_ = false;  // a new target
    facadeDrawnWith_ = 0;
    aspect_ = float(target.width) / float(std::max(target.height, 1u));
  }

  void update(const FrameInput& input) override;
  void record(const FrameContext& frame) override;
  params::Bound parameters() override { return {&schema(), &settings_}; }
  float renderScale() const override { return tierRenderScale(quality_.active()); }
  double frameCost(const void* values) const override {  // particles stepped and tubes drawn
    const auto& v = *static_cast<const Settings*>(values);
    return double(v.chains) * double(v.particles);
  }
  void drawPanel() override;
  void lightSignals(lights::Signals& out) override;
  bool checkpoints() const override { return true; }
  void simulationState(StateArchive& state) override;

 private:
  void startEngine();
  void resizeChains();
  void release(double time, glm::vec3 position, const char* by);
  void handleCursor(const FrameInput& input);
  void autopilot(const FrameInput& input);
  glm::vec3 penPosition(double t, uint32_t pen) const;
  void recordChains(const FrameContext& frame);
  uint32_t aliveChains();
  void recordFacadeAndTubes(const FrameContext& frame, const gpu::StreamSlice& block);

  const gpu::Device& device_;
  gpu::FrameResources& resources_;
  SceneEvents events_;
  AdaptiveQuality quality_;
  EngineMode mode_;
  gpu::ComputeProgram chains_;
  gpu::ComputeProgram facade_;
  gpu::GraphicsProgram tubes_;
  gpu::ComputeProgram merge_;
  gpu::ComputeProgram clear_;
  LookPasses look_;
  Settings settings_;
  std::unique_ptr<ParticleEngine> engine_;
  std::optional<PlacementGuard> placement_;
  std::vector<HeadState> uploadHeads_;
  int builtChains_ = 0, builtParticles_ = 0;
  uint32_t slots_ = 0;        // the chains the engine releases into: the tier's (tierChains)
  uint32_t drawnChains_ = 0;  // the chains the passes step and draw: the slots, and any above still alive
  // current(particles_) holds the latest positions: the chain pass reads it, writes previous() and flips.
  gpu::BufferHandle heads_, particles_, boxes_;
  uint32_t boxCount_ = 0;
  std::vector<ChainParams> stepsPending_;  // one per simulation step since the chains last moved
  gpu::ImageHandle colour_, depth_, glow_, lighting_, facadeColour_, facadeDepth_;
  bool glowCleared_ = false;  // the tubes' target holds zeros (cleared after its last use, or at creation)
  // Which of the facade program's builds drew facadeColour_ and facadeDepth_ at this size; 0: not drawn.
  // A hot-reloaded facade.comp is a new build, so the edit shows at once, not at the next resize.
  uint32_t facadeDrawnWith_ = 0;
  VkExtent2D extent_{1, 1};
  float aspect_ = 16.0f / 9.0f;

  double time_ = 0.0;
  double lastInput_ = -1e9;  // when the cursor last drew
  bool drawing_ = false;     // a drag is steering its tube
  bool reducedMotion_ = false;
  double autopilotNext_ = 0.0;
  uint64_t releases_ = 0;
};

// An engine for the current number of chains, with none released.
void NeonScene::startEngine() {
  builtChains_ = settings_.chains;
  builtParticles_ = settings_.particles;
  engine_ = std::make_unique<ParticleEngine>(EngineSettings{uint32_t(settings_.chains), settings_.decay}, mode_);
  placement_.emplace(uint32_t(settings_.chains));
  slots_ = drawnChains_ = uint32_t(settings_.chains);
}

// The chains or their particles changed: a new engine, and buffers of the new sizes with every particle
// hidden again (the host retires the old ones, never waits for them).
void NeonScene::resizeChains() {
  resources_.redeclare(heads_, headsDecl(settings_.chains));
  resources_.redeclare(particles_, particlesDecl(settings_.chains, settings_.particles));
  startEngine();
}

void NeonScene::release(double time, glm::vec3 position, const char* by) {
  engine_->release(position);
  ++releases_;
  events_.emit(time, {"release", {{"x", position.x}, {"y", position.y}, {"z", position.z}, {"by", by}}});
}

// A drag draws one tube: its press releases a steered head (a pen) under the cursor, every step of the
// drag moves the pen there, and its chain records the path; the button's release lets the tube go: it
// keeps the stroke's shape where it was drawn and fades.
void NeonScene::handleCursor(const FrameInput& input) {
  if (!input.cursor.dragging) {
    if (std::exchange(drawing_, false)) engine_->endSteer();
    return;
  }
  const auto at = cursorOnReleasePlane(input.cursor.normalized, aspect_);
  if (!at) return;
  lastInput_ = input.time;
  if (!drawing_) {
    engine_->release(*at, true);
    ++releases_;
    events_.emit(input.time, {"release", {{"x", at->x}, {"y", at->y}, {"z", at->z}, {"by", "cursor"}}});
    drawing_ = true;
  } else {
    engine_->steer(*at);
  }
}

// When nobody plays, pens wander slow Lissajous paths over the release plane and release heads as
// they go, taking turns, each release a little off its pen's path; the first drag takes over at once.
// Three pens for the default rate, more for a faster one (one for every 1.5 heads a second, up to 48),
// so a dense autopilot spreads its tubes over the facade instead of piling them onto three points.
void NeonScene::autopilot(const FrameInput& input) {
  if (input.time - lastInput_ < settings_.autopilotIdle) {
    autopilotNext_ = input.time;
    return;
  }
  const float rate = settings_.autopilotRate * (reducedMotion_ ? kReducedMotionAutopilot : 1.0f);
  const uint32_t pens = std::clamp(uint32_t(std::lround(rate / 1.5f)), kAutopilotPens, 48u);
  // A step that starts far into the piece (--time 1e9, a checkpoint's time) would owe a release for every
  // period since 0; the engine keeps at most slots_ heads, so only the latest slots_ of them are made.
  // The skipped ones still count, so the pens and their jitter go on as if they had been made.
  const double period = 1.0 / double(rate), owed = std::floor((input.time - autopilotNext_) / period) + 1.0;
  const uint32_t kept = std::max(slots_, 1u);
  if (const double skipped = owed - double(kept); skipped > 0.0) {
    autopilotNext_ += skipped * period;
    releases_ += uint64_t(std::fmod(skipped, 0x1p62));
  }
  uint32_t made = 0;
  for (; autopilotNext_ <= input.time && made <= kept; autopilotNext_ += period, ++made)  // the pens take turns
    release(autopilotNext_, penPosition(autopilotNext_, uint32_t(releases_ % pens)), "autopilot");
  // Past about 1e15 s a period is below the time's resolution and adding it changes nothing.
  if (autopilotNext_ <= input.time) autopilotNext_ = std::nextafter(input.time, HUGE_VAL);
}

// Where pen `pen` is at time t, a little off its Lissajous path (the jitter changes with every release).
glm::vec3 NeonScene::penPosition(double t, uint32_t pen) const {
  const double phase = double(pen) * (pen < kAutopilotPens ? 2.1 : 2.39996);
  const glm::vec3 jitter{maths::hash01({uint32_t(releases_), 1u, 0x6a11u}) - 0.5f,
                         maths::hash01({uint32_t(releases_), 2u, 0x6a11u}) - 0.5f, 0.0f};
  const glm::vec3 at{float(7.5 * std::sin(0.23 * t + phase)), float(7.0 + 5.0 * std::sin(0.31 * t + 1.7 * phase)),
                     kReleasePlaneZ + float(1.5 * std::sin(0.17 * t + phase))};
  return at + jitter * 1.2f;
}

void NeonScene::update(const FrameInput& input) {
  quality_.update(settings_.tier, settings_.targetMs, input);
  time_ = input.time;
  reducedMotion_ = input.reducedMotion;
  if (settings_.chains != builtChains_ || settings_.particles != builtParticles_) {
    resizeChains();
    drawing_ = false;  // the new engine has no pen
    stepsPending_.clear();
  }
  engine_->setDecayPerSecond(settings_.decay);
  if (const auto slots = uint32_t(tierChains(settings_.chains, quality_.active())); slots != slots_)
    engine_->setSlots(slots_ = slots);
  handleCursor(input);
  for (const ActionCall& call : input.actions)  // checked against kActions (settings.cpp) by the host
    if (call.name == "release") {
      lastInput_ = input.time;
      release(input.time, clampToReleaseVolume({call.args[0], call.args[1], call.args[2]}), "action");
    } else if (call.name == "burst") {  // an accent (a beat): the autopilot plays on around it
      for (uint32_t pen = 0; pen < kAutopilotPens; ++pen) release(input.time, penPosition(input.time, pen), "burst");
    }
  autopilot(input);
  engine_->step(input.dt);
  // The chains move once per simulation step, by that step's dt and time, whatever the frame rate: a
  // paused gallery draws frames with no step (the tubes stand still), a 144 Hz display draws some
  // frames with none and a slow one some with two. The potentials drift slowly through noise space,
  // so the flow the heads ride keeps changing (not under --reduced-motion).
  const float strength = settings_.fieldStrength * (reducedMotion_ ? kReducedMotionFlow : 1.0f);
  if (stepsPending_.size() >= kMaxChainStepsPerFrame) stepsPending_.erase(stepsPending_.begin());
  stepsPending_.push_back({input.dt, followerLerp(settings_.lerp, input.dt), strength, settings_.fieldScale,
                           reducedMotion_ ? 0.0 : input.time * 0.05});
}

// Between frames: the engine, which chains the GPU has placed, the autopilot, and every particle.
void NeonScene::simulationState(StateArchive& state) {
  int chains = builtChains_, particles = builtParticles_;
  state(chains, particles);
  if (state.isRestoring()) {
    if (chains != settings_.chains || particles != settings_.particles)
      throw Error("neon's saved chains do not match its parameters");
    resizeChains();  // buffers and an engine of the saved size, restored below
  }
  engine_->simulationState(state);
  placement_->simulationState(state);
  // slots_ too: the engine restores its own limit, and the scene must know it to post the next change.
  state(releases_, lastInput_, drawing_, autopilotNext_, time_, reducedMotion_, stepsPending_, slots_);
  state.contents(resources_, particles_);
}

uint32_t NeonScene::aliveChains() {
  uint32_t alive = 0;
  for (const HeadState& head : engine_->latest().heads) alive += chainState(head) != ChainState::Inactive;
  return alive;
}

void NeonScene::recordChains(const FrameContext& frame) {
  if (stepsPending_.empty()) return;  // no simulation step since the last frame: the chains stand
  const auto pass = frame.pass("neon chains");
  // A head the GPU never saw initialising (the worker ran ahead of the frames) is sent as initialising
  // once, so its chain starts at its origin instead of streaking in from the slot's last tube.
  const Snapshot& snapshot = engine_->latest();
  uploadHeads_.resize(snapshot.heads.size());
  placement_->copy(snapshot.heads, uploadHeads_);
  // Chains above a lowered tier's slots swim on until they die (ParticleEngine::setSlots): the passes
  // take every slot up to the highest one alive. A slot left out holds a stale chain nobody draws;
  // taken in again it is written before it is drawn (inactive: life 0; released: at its origin).
  drawnChains_ = slots_;
  for (auto slot = uint32_t(snapshot.heads.size()); slot > drawnChains_; --slot)
    if (chainState(snapshot.heads[slot - 1]) != ChainState::Inactive) {
      drawnChains_ = slot;
      break;
    }
  gpu::Buffer& heads = frame.buffer(heads_);
  frame.upload(heads, 0, std::as_bytes(std::span(uploadHeads_)), gpu::use::ComputeReadBuffer);
  const glm::uvec2 groups = chainGroups(uint64_t(drawnChains_) * uint64_t(builtParticles_), chains_.localSize()[0]);
  chains_.bind(frame.cmd);
  for (const ChainParams& params : std::exchange(stepsPending_, {})) {
    chains_.constants(frame.cmd, chainPush(drawnChains_, uint32_t(builtParticles_), params));
    gpu::Buffer& previous = frame.buffer(particles_);
    gpu::Buffer& next = frame.resources.previous(particles_);
    frame.transition(previous, gpu::use::ComputeReadBuffer);
    frame.transition(next, gpu::use::ComputeWriteBuffer);
    chains_.push(frame.cmd, gpu::Bindings()
                                .storageBuffer("Heads", heads.handle())
                                .storageBuffer("Previous", previous.handle())
                                .storageBuffer("Next", next.handle()));
    chains_.dispatchGroups(frame.cmd, {groups.x, groups.y, 1});
    frame.resources.flip(particles_);
  }
}

void NeonScene::recordFacadeAndTubes(const FrameContext& frame, const gpu::StreamSlice& block) {
  gpu::Image& colour = frame.image(colour_);
  gpu::Image& depth = frame.image(depth_);
  gpu::Image& glow = frame.image(glow_);
  gpu::Image& facadeColour = frame.image(facadeColour_);
  gpu::Image& facadeDepth = frame.image(facadeDepth_);
  const VkSampler nearest = device_.sampler(gpu::Device::Filter::Nearest, gpu::Device::Address::Clamp);
  constexpr VkImageLayout kReadOnly = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  if (facadeDrawnWith_ != facade_.builds()) {
    const auto pass = frame.pass("neon facade");
    gpu::Image& lighting = frame.image(lighting_);
    gpu::Buffer& boxes = frame.buffer(boxes_);
    frame.transition(boxes, gpu::use::ComputeReadBuffer);
    frame.transition(lighting, gpu::use::ComputeSample);
    frame.transition(facadeColour, gpu::use::ComputeWrite);
    frame.transition(facadeDepth, gpu::use::ComputeWrite);
    facade_.bind(frame.cmd);
    facade_.constants(frame.cmd, shader::NeonFacadePush{kNightSky, kFacadeBrightness});
    facade_.push(frame.cmd, gpu::Bindings()
                                .uniformBuffer("Frame", block.buffer, block.offset, sizeof(shader::NeonFrame))
                                .storageBuffer("Boxes", boxes.handle())
                                .sampledImage("lighting", lighting.view(),
                                              device_.sampler(gpu::Device::Filter::Linear,
                                                              gpu::Device::Address::Clamp, true),
                                              kReadOnly)
                                .storageImage("colour", facadeColour.view())
                                .storageImage("depth", facadeDepth.view()));
    facade_.dispatchOver(frame.cmd, extent_);
    facadeDrawnWith_ = facade_.builds();
  }
  {
    const auto pass = frame.pass("neon tubes");
    gpu::Buffer& positions = frame.buffer(particles_);
    gpu::Buffer& heads = frame.buffer(heads_);
    frame.transition(positions, gpu::use::VertexReadBuffer);
    frame.transition(heads, gpu::use::VertexReadBuffer);
    frame.transition(facadeDepth, gpu::use::FragmentSample);
    gpu::RenderingDesc desc;
    // Zeroed by the clear pass at the end of the last frame; a new target is cleared here once.
    desc.colors = {{&glow, glowCleared_ ? std::nullopt : std::optional<VkClearColorValue>(VkClearColorValue{})}};
    const auto rendering = frame.rendering(desc);
    if (settings_.stage != Stage::Base) {  // the base stage is the facade alone
      tubes_.bind(frame.cmd);
      tubes_.push(frame.cmd, gpu::Bindings()
                                 .uniformBuffer("Frame", block.buffer, block.offset, sizeof(shader::NeonFrame))
                                 .storageBuffer("Particles", positions.handle())
                                 .storageBuffer("Heads", heads.handle())
                                 .sampledImage("facadeDepth", facadeDepth.view(), nearest, kReadOnly));
      vkCmdDraw(frame.cmd, 2u * (uint32_t(builtParticles_) + 2u), drawnChains_, 0, 0);  // and two caps
    }
  }
  const auto pass = frame.pass("neon merge");
  frame.transition(facadeColour, gpu::use::ComputeRead);
  frame.transition(facadeDepth, gpu::use::ComputeRead);
  frame.transition(colour, gpu::use::ComputeWrite);
  frame.transition(depth, gpu::use::ComputeWrite);
  frame.transition(glow, gpu::use::ComputeReadWrite);
  merge_.bind(frame.cmd);
  merge_.constants(frame.cmd, shader::NeonMergePush{{glm::vec4(linear(settings_.colourA), 0.0f),
                                                     glm::vec4(linear(settings_.colourB), 0.0f),
                                                     glm::vec4(linear(settings_.colourC), 0.0f)}});
  merge_.push(frame.cmd, gpu::Bindings()
                             .storageImage("facade", facadeColour.view())
                             .storageImage("facadeDepth", facadeDepth.view())
                             .storageImage("scene", colour.view())
                             .storageImage("depth", depth.view())
                             .storageImage("tubes", glow.view()));
  merge_.dispatchOver(frame.cmd, extent_);
}

void NeonScene::record(const FrameContext& frame) {
  recordChains(frame);
  if (!frame.draws) return;  // the chains are the simulation; the rest draws them
  const glm::mat4 viewProjection = projectionMatrix(aspect_) * viewMatrix();
  const glm::mat3 axes = glm::transpose(glm::mat3(viewMatrix()));  // the camera's right, up and back in world
  const float tanHalf = std::tan(0.5f * kFovY);
  const float focalPixels = 0.5f * float(extent_.height) / tanHalf;
  const shader::NeonFrame block{.viewProjection = viewProjection,
                                .eye = kEye,
                                .near = kNear,
                                .right = axes[0] * tanHalf * aspect_,
                                .frameWidth = float(extent_.width),
                                .up = axes[1] * tanHalf,
                                .frameHeight = float(extent_.height),
                                .forward = -axes[2],
                                .focalPixels = focalPixels,
                                .colourA = linear(settings_.colourA),
                                .glow = settings_.glow,
                                .colourB = linear(settings_.colourB),
                                .tubeRadius = settings_.radius,
                                .colourC = linear(settings_.colourC),
                                .exposure = tubeExposure(aliveChains()),
                                .minTubeRadiusPixels = kMinTubeRadiusPixels,
                                .chains = uint32_t(builtChains_),
                                .particlesPerChain = uint32_t(builtParticles_),
                                .boxes = boxCount_};
  recordFacadeAndTubes(frame, frame.uniform(block));
  // The ground mirrors about the facade's foot, where it meets the ground straight ahead.
  const float footY = projectedRow(viewProjection, glm::vec3(0.0f), float(extent_.height));
  // The low tier's half-size frame has circles of confusion half as wide: 16 taps cover a quarter of
  // the area as densely as 32 cover the whole, and the depth of field costs half.
  const uint32_t dofTaps = quality_.active() == Tier::Low ? 16u : 32u;
  look_.record(frame, settings_, {frame.image(colour_), frame.image(depth_), frame.image(glow_), footY, kNear,
                                  reducedMotion_ ? 0.0f : float(time_), dofTaps});
  const auto pass = frame.pass("neon clear");
  gpu::Image& glow = frame.image(glow_);
  frame.transition(glow, gpu::use::ComputeWrite);
  clear_.bind(frame.cmd);
  clear_.push(frame.cmd, gpu::Bindings().storageImage("target", glow.view()));
  clear_.dispatchOver(frame.cmd, extent_);
  glowCleared_ = true;
}

// The tubes for a strip along the room: the facade's width in kStripCells cells, each lit by the tubes
// whose heads are over it (a pen where it is; a free head where its launch has carried it, the flow's
// swirl left out), in the tube's own colour at its brightness (the gas dims below kFadeLife); and the
// light of all the tubes together.
void NeonScene::lightSignals(lights::Signals& out) {
  static constexpr int kStripCells = 32;
  std::vector<glm::vec3> strip(kStripCells, glm::vec3(0.0f));
  glm::vec3 glow(0.0f);
  const glm::vec3 colours[3] = {settings_.colourA, settings_.colourB, settings_.colourC};
  for (const HeadState& head : engine_->latest().heads) {
    if (chainState(head) == ChainState::Inactive) continue;
    const glm::vec3 light = colours[tubeColour(head.serial)] * std::clamp(head.life / kFadeLife, 0.0f, 1.0f);
    const float age = float(head.steps) / 60.0f;
    const float x = head.origin.x + ((head.flags & kHeadSteered) ? 0.0f : head.launch.x * age);
    const int cell = int(std::floor((x + kFacadeHalfWidth) / (2.0f * kFacadeHalfWidth) * float(kStripCells)));
    strip[size_t(std::clamp(cell, 0, kStripCells - 1))] += light;
    glow += light;
  }
  out.set("neon.tubes", std::move(strip));
  out.set("neon.glow", std::vector<glm::vec3>{glm::min(glow / 3.0f, glm::vec3(1.0f))});
}

void NeonScene::drawPanel() {
  const uint32_t alive = aliveChains();
  ImGui::Text("%u of %u chains alive (%d at the high tier), %llu released", alive, slots_, builtChains_,
              (unsigned long long)releases_);
  ImGui::Text("particle engine: %s", mode_ == EngineMode::Worker ? "worker thread" : "lock-step");
  if (time_ - lastInput_ >= settings_.autopilotIdle) ImGui::TextDisabled("autopilot playing; drag to take over");
}

std::unique_ptr<Scene> create(const SceneContext& context) { return std::make_unique<NeonScene>(context); }

}  // namespace vitrine::neon
