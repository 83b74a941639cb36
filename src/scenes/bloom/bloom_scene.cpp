// bloom: a vapochromic octahedral crystal (seed 000, "The Bloom"). The cursor is the vapour: it
// diffuses through a 3D lattice in a compute pass, the crystal is raymarched over an octahedral
// proxy so only its pixels pay, and its colour flips white -> amber -> rose -> crimson at sharp
// thresholds. The phases are read from the lattice itself (statistics reduced on the GPU, read back
// a few frames later, never a stall) and reported as scene events.
#include "scenes/bloom/bloom_scene.h"
#include "scenes/adaptive_quality.h"

#include "core/error.h"
#include "gpu/buffer_commands.h"
#include "gpu/program_variants.h"
#include "gpu/readback_ring.h"
#include "lights/signals.h"
#include "scenes/bloom/bloom_math.h"
#include "scenes/bloom/settings.h"
#include "shaders/bloom/chamber_push.h"
#include "shaders/bloom/crystal_push.h"
#include "shaders/bloom/diffuse_push.h"
#include "shaders/bloom/stats_blocks.h"
#include "text/text_pass.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

namespace vitrine::bloom {
namespace {

// One 32-bit float a voxel (the seed's RGBA16F holds one value in 8 bytes). Not half floats: a
// 256^3 sub-step's decay of a concentration near 1 is under half a half-float step, so a half lattice
// vents at a speed set by the lattice size and the driver's rounding instead of the physics. The
// lattices the diffusion steps are storage buffers (diffuse.comp says why); the crystal samples the
// view, an image in this format.
constexpr VkFormat kViewFormat = VK_FORMAT_R32_SFLOAT;
// Simulated time one frame's diffusion catches up at most: all of it down to 2 fps, so the vapour
// follows the clock on a slow device; below that the frame's own GPU time would grow with its
// slowness, so the rest is given up and the gallery says the simulation is behind.
constexpr float kMaxSecondsPerFrame = 0.5f;
constexpr uint32_t kStatsReadbacks = 4;  // copies in flight before a frame's is skipped (gpu/readback_ring.h)

constexpr std::array<std::string_view, 4> kLabelWords{"", "AMBER", "ROSE", "CRIMSON"};
const text::Shaping kLabelShaping{0.18f};  // small caps, widely tracked

gpu::GraphicsState crystalState() {
  gpu::GraphicsState state;
  state.vertex = "bloom/crystal.vert";
  state.fragment = "bloom/crystal.frag";
  state.colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT};
  state.blend = gpu::GraphicsState::Blend::Premultiplied;
  state.cull = VK_CULL_MODE_FRONT_BIT;  // the proxy's far faces only: one fragment a covered pixel
  return state;
}

// What a statistics pass counted (shaders/bloom/stats_blocks.h), as the scene reads it.
struct LatticeStats {
  uint32_t interior = 0;            // the crystal's voxels inside its core (bloom_math.h: insideCore)
  std::array<uint32_t, 4> above{};  // of those, past the amber, rose, crimson and climax thresholds
  float peak = 0.0f;                // over the whole crystal
  static LatticeStats from(const shader::BloomLatticeCounts& counts) {
    LatticeStats stats;
    stats.interior = counts.interior;
    std::copy(std::begin(counts.above), std::end(counts.above), stats.above.begin());
    stats.peak = std::bit_cast<float>(counts.peakBits);
    return stats;
  }
  std::array<float, 4> fractions() const {
    std::array<float, 4> f{};
    for (size_t i = 0; i < 4; ++i) f[i] = interior ? float(above[i]) / float(interior) : 0.0f;
    return f;
  }
};

class BloomScene final : public Scene {
 public:
  explicit BloomScene(const SceneContext& context)
      : device_(context.device),
        resources_(context.resources),
        events_(context.events),
        quality_(context),
        audio_(context.audio),
        fill_(context.programs, "bloom/fill.comp"),
        resample_(context.programs, "bloom/resample.comp"),
        diffuse_(context.programs, "bloom/diffuse.comp"),
        statistics_(context.programs, "bloom/stats.comp"),
        chamber_(context.programs, "bloom/chamber.comp"),
        crystal_(context.programs, crystalState()),
        // Zeroed each frame before the pass counts into it, then copied out for the CPU.
        statsCounts_(context.resources.declare(
            {.name = "bloom statistics",
             .size = gpu::BufferSize::absolute(sizeof(shader::BloomLatticeCounts)),
             .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                      VK_BUFFER_USAGE_TRANSFER_DST_BIT})),
        statsReadback_(context.device, context.resources, sizeof(shader::BloomLatticeCounts), kStatsReadbacks,
                       "bloom statistics readback"),
        labelFont_(text::Font::fromAssets(context.assets, "CormorantSC")),
        titleFont_(text::Font::fromAssets(context.assets, "FrauncesItalic")),
        text_(context, {{&labelFont_, {"AMBER", "ROSE", "CRIMSON"}, kLabelShaping}, {&titleFont_, {"CHROMA"}, {}}}) {
    for (size_t i = 1; i < 4; ++i)
      labels_[i] = text_.layout(labelFont_, std::string(kLabelWords[i]), kLabelShaping);
    chroma_ = text_.layout(titleFont_, "CHROMA");
    const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT |
                                        VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    if ((context.device.optimalTilingFeatures(kViewFormat) & needed) != needed)
      throw Error(fmt::format("bloom needs r32f 3D images it can store to and filter linearly, which {} lacks",
                              context.device.properties().deviceName));
    lattice_ = resources_.declare(latticeDecl(settings_.lattice));
    stage_ = resources_.declare(stageDecl(settings_.lattice));
    view_ = resources_.declare(viewDecl(settings_.lattice));
    builtLattice_ = builtSetting_ = settings_.lattice;
  }
  ~BloomScene() override { audio_.drone(time_, false); }

  void resize(VkExtent2D target) override {
    aspect_ = float(target.width) / float(std::max(target.height, 1u));
    labelPosition_ = projectToView({0.0f, kCrystalRadius + 0.2f, 0.0f}, aspect_);  // just above the top vertex
  }

  void update(const FrameInput& input) override {
    quality_.update(settings_.tier, settings_.targetMs, input);
    time_ = input.time;
    reducedMotion_ = input.reducedMotion;
    // The drone is always under the piece; the panel's volume and mute reach the mix as they change.
    if (!droning_) audio_.drone(time_, droning_ = true);
    const float gain = settings_.mute ? 0.0f : settings_.volume;
    if (gain != appliedGain_) audio_.volume(time_, appliedGain_ = gain);
    frame_ = input.frame;
    seed_ = input.seed;
    // The cursor's ray, unprojected into the crystal's space, is the vapour source over the crystal's
    // footprint (bloom_math.h: cursorVapour).
    const Ray ray = cameraRay(input.cursor.normalized.x, input.cursor.normalized.y, aspect_);
    const CursorVapour vapour = cursorVapour(ray, settings_.reach);
    const bool near = input.cursor.present && vapour.over;
    // Without the cursor, the crystal breathes vapour in at its heart as strongly as `breath` says
    // (live input plays it with the music's level).
    const bool breathing = !near && settings_.breath > 0.0f;
    source_.point = breathing ? glm::vec3(0.0f) : vapour.point;
    source_.rate = settings_.sourceRate * (breathing ? settings_.breath : input.cursor.dragging ? settings_.dragBoost : 1.0f) *
                   boost(source_.point);
    stepSeconds_ = input.dt;
    if (stepsPending_ < std::max(1, int(std::lround(kMaxSecondsPerFrame / stepSeconds_))))
      ++stepsPending_;
    else
      givenUpSeconds_ += double(stepSeconds_);

    // The seed's CPU proxy runs beside the lattice, as a selectable source and for the panel's plot.
    const bool overCrystal = input.cursor.present && octahedronChord(ray, kCrystalRadius).has_value();
    proxy_ = proxyStep(proxy_, !exhaling_ && (overCrystal || breathing), input.dt,
                       {0.20f, settings_.decayRising, settings_.decayVenting});
    if (settings_.phaseSource == PhaseSource::Cpu)
      detect({proxy_, proxy_, proxy_, proxy_}, proxyBands(thresholds()), time_);
    for (const Reading& reading : std::exchange(carried_, {})) observe(reading);
    while (auto reading = pollStatistics()) observe(*reading);  // finished a frame or more ago: no waiting
    if (settings_.vent) {
      settings_.vent = false;
      restart(0.0f);
    }
    // The arc: the climax blooms for kBloomSeconds, then the crystal exhales back to pristine before
    // any vapour enters again, so a cursor that simply stays sees every flip, the bloom and the vent.
    if (detector_.climax() && !exhaling_ && time_ - climaxTime_ >= kBloomSeconds) exhaling_ = true;
    if (exhaling_ && !detector_.climax() && detector_.phase() == Phase::Pristine) exhaling_ = false;
    source_.on = (near || breathing) && !exhaling_;
    if (source_.on) lastVapour_ = time_;
    // Here, not in record: a new lattice's initial texels are uploaded as the next frame begins. A new
    // lattice setting or fill starts afresh; a new tier's side (before the first frame: its own start)
    // carries the vapour over.
    const int wanted = tierLattice(settings_.lattice, quality_.active());
    if (settings_.lattice != builtSetting_ || settings_.fill != builtFill_ || (!recorded_ && wanted != builtLattice_))
      restart(settings_.fill);
    else
      advanceCarry(wanted);
  }

  void record(const FrameContext& frame) override {
    recorded_ = true;
    fill(frame);
    carry(frame);
    simulate(frame);  // writes the view: every frame after an update runs a super step (but a carry's first)
    measure(frame);  // the phases follow the lattice's statistics, seen or not
    if (!frame.draws) return;
    drawChamber(frame);
    drawCrystal(frame);
    drawType(frame);
  }

  params::Bound parameters() override { return {&schema(), &settings_}; }
  float renderScale() const override { return tierScale(quality_.active()); }

  // Between frames. The statistics of the frame just finished wait in the readback ring: they are taken
  // out and carried, so the next update reads them exactly as it would have.
  bool checkpoints() const override { return true; }
  void simulationState(StateArchive& state) override {
    if (!state.isRestoring())
      while (auto reading = pollStatistics()) carried_.push_back(*reading);
    state(droning_, appliedGain_, builtLattice_, builtSetting_, builtFill_, recorded_, time_, frame_, seed_, source_, stepsPending_,
          givenUpSeconds_, stepSeconds_, proxy_, stats_, detector_, history_, carried_, label_, labelTime_,
          chromaTime_, crimsonAtVent_, climaxTime_, exhaling_, reducedMotion_, shownPhase_, flipFrom_, flipTime_, statsTime_,
          lastVapour_);
    if (state.isRestoring()) {  // the checkpoint's vapour, over zeros
      redeclareLattices(builtLattice_);  // a carry half done starts again from the restored lattice
      pendingFill_ = 0.0f;
    }
    state.contents(resources_, lattice_);
  }
  double frameCost(const void* values) const override {  // the lattice's diffusion dominates
    const auto& v = *static_cast<const Settings*>(values);
    return std::pow(double(v.lattice), 3.0) * (1.0 + double(v.samples) / 256.0);
  }
  double takeGivenUpSeconds() override { return std::exchange(givenUpSeconds_, 0.0); }
  // The room follows the crystal: the chamber glow's colour (flipping with the phase, as the picture's),
  // how full of vapour the chamber glows, and 1 through the climax.
  void lightSignals(lights::Signals& out) override {
    out.set("bloom.phase", std::vector<glm::vec3>{tint()});
    out.set("bloom.chamber", std::min(float(stats_.peak), 1.0f));
    out.set("bloom.climax", detector_.climax() ? 1.0f : 0.0f);
  }

  std::string checkParameters() const override {
    if (std::string order = thresholdOrderError(thresholds()); !order.empty()) return order;
    return latticeFitError(uint32_t(settings_.lattice),
                           {device_.limits().maxImageDimension3D, device_.limits().maxStorageBufferRange,
                            device_.memoryLimits().largestDeviceLocalHeap},
                           device_.properties().deviceName);
  }

  void drawPanel() override {
    const auto f = stats_.fractions();
    ImGui::Text("phase %s%s   peak %.2f", std::string(kPhaseNames[size_t(detector_.phase())]).c_str(),
                detector_.climax() ? " + CHROMA" : "", stats_.peak);
    ImGui::Text("interior past each threshold: %.0f%% %.0f%% %.0f%% %.0f%%", f[0] * 100, f[1] * 100, f[2] * 100,
                f[3] * 100);
    std::vector<float> peak, amber, proxy;
    for (const auto& h : history_) peak.push_back(h.peak), amber.push_back(h.fraction), proxy.push_back(h.proxy);
    ImGui::PlotLines("GPU peak", peak.data(), int(peak.size()), 0, nullptr, 0.0f, 1.05f, ImVec2(0, 40));
    ImGui::PlotLines("GPU past rose", amber.data(), int(amber.size()), 0, nullptr, 0.0f, 1.0f, ImVec2(0, 40));
    ImGui::PlotLines("CPU proxy V", proxy.data(), int(proxy.size()), 0, nullptr, 0.0f, 1.05f, ImVec2(0, 40));
    ImGui::Text("lattice %d^3 at %s", builtLattice_, quality_.describe().c_str());
    const DiffusionPlan plan = this->plan();
    ImGui::Text("%u diffusion passes a frame (%s; %.1f explicit steps' worth)%s", plan.passes(),
                plan.stages > 1 ? "Runge-Kutta-Legendre stages" : "explicit sub-steps",
                explicitStepsFor(scaledD(), stepSeconds_), exhaling_ ? "   exhaling" : "");
  }

 private:
  struct Sample {
    float peak, fraction, proxy;
  };
  struct Reading {  // one frame's statistics, tagged with its time
    LatticeStats stats;
    double time;
  };

  std::optional<Reading> pollStatistics() {
    const auto result = statsReadback_.poll();
    if (!result) return std::nullopt;
    shader::BloomLatticeCounts counts;
    std::memcpy(&counts, result->bytes.data(), sizeof(counts));
    return Reading{LatticeStats::from(counts), result->tag};
  }

  void observe(const Reading& reading) {
    stats_ = reading.stats;
    statsTime_ = reading.time;
    history_.push_back({float(stats_.peak), stats_.fractions()[1], proxy_});
    if (history_.size() > kHistory) history_.pop_front();
    if (settings_.phaseSource == PhaseSource::Gpu) detect(stats_.fractions(), kFractionBands, reading.time);
  }
  static constexpr size_t kHistory = 600;  // ten seconds of readings

  // Made zero on the GPU (a 512^3 pair is a gigabyte, too much to build and upload from the CPU);
  // fill.comp then puts a fill inside the crystal.
  static gpu::BufferDecl latticeDecl(int n) {
    return {.name = "bloom vapour",
            .size = gpu::BufferSize::absolute(latticeBytes(uint32_t(n))),
            .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
            .pairing = gpu::Pairing::PingPong,
            .clear = true,   // diffuse.comp never writes a voxel outside the crystal
            .state = true};  // checkpoints save the vapour
  }
  // The third lattice a super step's stages rotate through; it never holds the state between frames.
  static gpu::BufferDecl stageDecl(int n) {
    gpu::BufferDecl decl = latticeDecl(n);
    decl.name = "bloom vapour stage";
    decl.pairing = gpu::Pairing::Single;
    decl.state = false;
    return decl;
  }
  // What the crystal samples (filtered) and the statistics count: the lattice as the frame's diffusion
  // left it.
  static gpu::ImageDecl viewDecl(int n) {
    gpu::ImageDecl decl{"bloom vapour view", kViewFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                        gpu::ImageSize::absolute(uint32_t(n), uint32_t(n), uint32_t(n))};
    decl.zeroed = true;  // outside the crystal, as in the lattices
    return decl;
  }
  // Fresh lattices and view of side n, all zero; the old ones are retired behind frames in flight.
  void redeclareLattices(int n) {
    resources_.redeclare(lattice_, latticeDecl(n));
    resources_.redeclare(stage_, stageDecl(n));
    resources_.redeclare(view_, viewDecl(n));
    carry_ = Carry::None;
  }

  // A new lattice (size change, fill, vent).
  void restart(float fill) {
    exhaling_ = false;
    pendingFill_ = fill;
    lastVapour_ = time_;
    builtLattice_ = tierLattice(settings_.lattice, quality_.active());
    builtSetting_ = settings_.lattice;
    builtFill_ = settings_.fill;
    redeclareLattices(builtLattice_);
  }

  // A tier's new side while the piece runs (the gallery's auto tier, or the panel) keeps the vapour:
  // the lattices are redeclared at the new side and the old view resampled into them; in the next
  // update the view is redeclared, and that frame's diffusion writes it. The frame between skips its
  // diffusion (its steps wait for the next), as the view it would write is still the old side. Steps
  // advance here, in update, and the passes in record, so several updates before one record (a slow
  // frame's) wait for it.
  void advanceCarry(int wanted) {
    if (carry_ == Carry::Resampled) {
      resources_.redeclare(view_, viewDecl(builtLattice_));
      carry_ = Carry::None;
    } else if (carry_ == Carry::None && wanted != builtLattice_) {
      resources_.redeclare(lattice_, latticeDecl(wanted));
      resources_.redeclare(stage_, stageDecl(wanted));
      builtLattice_ = wanted;
      carry_ = Carry::Resample;
    }
  }
  void carry(const FrameContext& frame) {
    if (carry_ != Carry::Resample) return;
    const auto pass = frame.pass("bloom carry");
    gpu::Image& from = frame.image(view_);
    gpu::Buffer& to = frame.buffer(lattice_);
    frame.transition(from, gpu::use::ComputeSample);
    frame.transition(to, gpu::use::ComputeWriteBuffer);
    overLattice(frame, resample_,
                gpu::Bindings()
                    .sampledImage("source", from.view(),
                                  device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                  gpu::use::ComputeSample.layout)
                    .storageBuffer("Lattice", to.handle()),
                shader::BloomResamplePush{uint32_t(builtLattice_)});
    carry_ = Carry::Resampled;
  }
  // One invocation a voxel of the lattice (fill.comp, resample.comp).
  template <typename Push>
  void overLattice(const FrameContext& frame, const gpu::ComputeProgram& program, const gpu::Bindings& bindings,
                   const Push& push) const {
    const uint32_t n = uint32_t(builtLattice_);
    program.bind(frame.cmd);
    program.push(frame.cmd, bindings);
    program.constants(frame.cmd, push);
    program.dispatchOver(frame.cmd, VkExtent3D{n, n, n});
  }

  std::array<float, 4> thresholds() const {
    return {settings_.thresholdAmber, settings_.thresholdRose, settings_.thresholdCrimson, settings_.thresholdChroma};
  }
  float scaledD() const { return scaledDiffusion(settings_.diffusion, uint32_t(builtLattice_)); }
  // Whether the crystal is clear glass now: the newest statistics saw no voxel at half of kCoverFrom,
  // and no vapour has entered since (no source, no new fill); without a source the lattice only
  // spreads and decays, so its peak only falls (the half leaves room for a stage's rounding).
  bool clearGlass() const { return statsTime_ >= lastVapour_ && stats_.peak < 0.5 * kCoverFrom; }
  DiffusionPlan plan() const { return diffusionPlan(scaledD(), stepSeconds_); }

  void fill(const FrameContext& frame) {
    if (pendingFill_ <= 0.0f) return;
    const auto pass = frame.pass("bloom fill");
    gpu::Buffer& lattice = frame.buffer(lattice_);
    frame.transition(lattice, gpu::use::ComputeWriteBuffer);
    overLattice(frame, fill_, gpu::Bindings().storageBuffer("Lattice", lattice.handle()),
                shader::BloomFillPush{pendingFill_, uint32_t(builtLattice_)});
    pendingFill_ = 0.0f;
  }

  // Each pending step is a frame of the plan: explicit sub-steps, or the stages of one super step
  // rotating the lattice pair and the stage lattice (bloom_math.h: resultSlot), ending in the pair;
  // the frame's last stage also writes the view.
  void simulate(const FrameContext& frame) {
    if (stepsPending_ == 0 || carry_ != Carry::None) return;  // a carry's frame: the view is the old side
    const auto pass = frame.pass("bloom diffuse");
    const uint32_t n = uint32_t(builtLattice_);
    const DiffusionPlan plan = this->plan();
    shader::BloomDiffusePush push{.source = worldToVoxel(source_.point, n),
                                  .diffusion = scaledD(),
                                  .decay = source_.on ? settings_.decayRising : settings_.decayVenting,
                                  .sigma = scaledSigma(settings_.sigma, n),
                                  .sourceRate = source_.on ? source_.rate : 0.0f,
                                  .side = n};
    gpu::Image& view = frame.image(view_);
    frame.transition(view, gpu::use::ComputeWrite);  // bound in every stage, written by the frame's last
    const uint32_t steps = uint32_t(stepsPending_) * plan.superSteps;
    for (uint32_t step = 0; step < steps; ++step) {
      gpu::Buffer* slots[3] = {&frame.buffer(lattice_), &frame.resources.previous(lattice_), &frame.buffer(stage_)};
      uint32_t older = 0, here = 0;
      for (uint32_t j = 1; j <= plan.stages; ++j) {
        const uint32_t next = stageSlot(j, plan.stages, here, older);
        const StageWeights w = rklStage(j, plan.stages);
        push.dt = w.step * plan.dt;
        push.keep = w.keep;
        push.older = w.older;
        push.last = j == plan.stages ? 1u : 0u;
        // diffuse.comp's READS_OLDER and WRITES_VIEW: the frame's last stage writes the view.
        const gpu::ComputeProgram& diffuse = diffuse_({w.older != 0.0f, push.last && step + 1 == steps});
        diffuse.bind(frame.cmd);
        frame.transition(*slots[here], gpu::use::ComputeReadBuffer);
        frame.transition(*slots[older], gpu::use::ComputeReadBuffer);
        frame.transition(*slots[next], gpu::use::ComputeWriteBuffer);
        diffuse.push(frame.cmd, gpu::Bindings()
                                    .storageBuffer("Current", slots[here]->handle())
                                    .storageBuffer("Older", slots[older]->handle())
                                    .storageBuffer("Next", slots[next]->handle())
                                    .storageImage("view", view.view()));
        diffuse.constants(frame.cmd, push);
        diffuse.dispatchOver(frame.cmd,
                             VkExtent3D{n, n, (n + shader::kBloomDiffuseColumn - 1) / shader::kBloomDiffuseColumn});
        older = here, here = next;
      }
      if (here == 1) frame.resources.flip(lattice_);
    }
    stepsPending_ = 0;
  }

  void measure(const FrameContext& frame) {
    const auto pass = frame.pass("bloom statistics");
    gpu::Buffer& counts = frame.buffer(statsCounts_);
    gpu::fillBuffer(frame.cmd, counts, 0, gpu::use::ComputeReadWriteBuffer);  // the workgroups' atomics add to it
    // The view, not the lattice: read here, it is still in the L2 when the crystal samples it (reading the
    // lattice made the crystal 6 % slower at 256^3 on the H200). In a carry's frame it is the old side.
    gpu::Image& view = frame.image(view_);
    frame.transition(view, gpu::use::ComputeRead);
    statistics_.bind(frame.cmd);
    statistics_.push(frame.cmd,
                     gpu::Bindings().storageImage("view", view.view()).storageBuffer("Stats", counts.handle()));
    const auto [amber, rose, crimson, climax] = thresholds();
    statistics_.constants(frame.cmd, shader::BloomStatsThresholds{amber, rose, crimson, climax});
    const uint32_t n = view.extent().width;
    statistics_.dispatchOver(frame.cmd, VkExtent3D{n, n, (n + shader::kBloomStatsColumn - 1) / shader::kBloomStatsColumn});
    statsReadback_.record(frame.cmd, counts, time_);
  }

  void drawChamber(const FrameContext& frame) {
    const auto pass = frame.pass("bloom chamber");
    frame.transition(frame.target, gpu::use::ComputeWrite);
    const float fill = std::min(stats_.peak, 1.0f);
    const shader::BloomChamberPush push{.glowColour = tint(), .shadow = 0.22f + 0.12f * fill, .glow = fill * 0.6f};
    chamber_.bind(frame.cmd);
    chamber_.push(frame.cmd, gpu::Bindings().storageImage("target", frame.target.view()));
    chamber_.constants(frame.cmd, push);
    chamber_.dispatchOver(frame.cmd, frame.target.extent2d());
  }

  void drawCrystal(const FrameContext& frame) {
    const auto pass = frame.pass("bloom crystal");
    gpu::Image& vapour = frame.image(view_);
    frame.transition(vapour, gpu::use::FragmentSample);
    const auto rendering = frame.rendering({{{&frame.target, std::nullopt}}, std::nullopt});
    const glm::mat4 view = glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    glm::mat4 projection = glm::perspective(kFieldOfViewY, aspect_, 0.05f, 20.0f);
    projection[1][1] *= -1.0f;  // Vulkan's clip space has y down
    // Reduced motion: no shimmer, and the jitter holds still (a fixed pattern, no crawling grain).
    const float shimmer = detector_.climax() && !reducedMotion_ ? 1.0f : 0.0f;
    const shader::BloomCrystalPush push{.viewProjection = projection * view,
                                        .eye = kEye,
                                        .time = float(time_),
                                        .thresholds = glm::vec3(settings_.thresholdAmber, settings_.thresholdRose,
                                                                settings_.thresholdCrimson),
                                        .seed = seed_,
                                        .frame = reducedMotion_ ? 0u : uint32_t(frame_),
                                        .samples = uint32_t(tierSamples(settings_.samples, settings_.lattice, builtLattice_)),
                                        .shimmer = shimmer,
                                        .clearGlass = clearGlass() ? 1u : 0u};
    crystal_.bind(frame.cmd);
    crystal_.push(frame.cmd, gpu::Bindings().sampledImage(
                                 "vapour", vapour.view(),
                                 device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                 gpu::use::FragmentSample.layout));
    crystal_.constants(frame.cmd, push);
    vkCmdDraw(frame.cmd, 24, 1, 0, 0);  // crystal.vert: the octahedron's 8 faces
  }

  // The type is the chemistry's voice, time-locked to the phases: the new phase's name types in above
  // the crystal in Cormorant SC and fades with the vapour (bloom_math.h: labelPresence); at the climax
  // CHROMA blooms over it in deep-charcoal Fraunces italic, holds while the climax does and fades with
  // the vent (chromaPresence).
  void drawType(const FrameContext& frame) {
    std::vector<text::TextDraw> draws;
    const float height = float(frame.target.extent2d().height);
    const double now = time_;
    const auto [signal, bands] = phaseSignal();
    if (label_ > 0) {
      // It types in (under reduced motion it is simply there, and fades as the others do).
      const float reveal = reducedMotion_ ? 1.0f : float(std::clamp((now - labelTime_) / 0.35, 0.0, 1.0));
      const float presence = labelPresence(label_, signal, bands);
      if (presence > 0.0f) {
        text::TextDraw label;
        label.layout = &labels_[size_t(label_)];
        label.position = labelPosition_;
        label.normalized = true;
        label.sizePx = height * 0.075f;
        label.color = glm::vec4(phaseInk(label_), 1.0f);
        label.opacity = presence;
        label.reveal = reveal;
        draws.push_back(label);
      }
    }
    if (chromaTime_ >= 0.0) {
      const double bloom = reducedMotion_ ? 1.0 : std::clamp((now - chromaTime_) / 0.8, 0.0, 1.0);
      const float presence = chromaPresence(detector_.climax(), signal[2], crimsonAtVent_, bands[2]);
      if (presence <= 0.0f) chromaTime_ = -1.0;
      text::TextDraw title;
      title.layout = &chroma_;
      title.position = {0.5f, 0.47f};
      title.normalized = true;
      title.sizePx = height * 0.21f * float(0.92 + 0.08 * bloom);
      title.color = glm::vec4(0.030f, 0.028f, 0.027f, 1.0f);  // deep charcoal, linear
      title.opacity = float(bloom) * presence;
      title.softnessEm = float(0.25 * (1.0 - bloom));  // it blooms: soft, then sharp
      title.glow = {kCrimson * 0.35f * float(1.0 - bloom * 0.6), 0.12f};
      if (title.opacity > 0.0f) draws.push_back(title);
    }
    if (draws.empty()) return;
    const auto pass = frame.pass("bloom type");
    text_.record(frame, draws);
  }

  // What the phases are read from, with its bands: the interior's shares past each threshold (gpu), or
  // the seed's proxy V against the thresholds (cpu).
  std::pair<std::array<float, 4>, std::array<Hysteresis, 4>> phaseSignal() const {
    if (settings_.phaseSource == PhaseSource::Gpu) return {stats_.fractions(), kFractionBands};
    return {{proxy_, proxy_, proxy_, proxy_}, proxyBands(thresholds())};
  }

  // The source's strength away from the heart (bloom_math.h: sourceBoost), kept while it stays put.
  float boost(glm::vec3 point) {
    const glm::vec3 centre = point / kCrystalRadius;
    const float sigma = settings_.sigma / float(kReferenceLattice) * 2.0f;  // in the normalised cube
    if (centre != boostCentre_ || sigma != boostSigma_)
      boostCentre_ = centre, boostSigma_ = sigma, boost_ = sourceBoost(centre, sigma);
    return boost_;
  }

  // The label's ink: the phase's colour, darkened to read on bone white.
  static glm::vec3 phaseInk(int phase) { return kPhaseColours[size_t(phase)] * 0.55f; }

  // The chamber glow's colour now: flipping (kFlipSeconds; softer under reduced motion) to the state's.
  glm::vec3 tint() const {
    return flipColour(flipFrom_, kPhaseColours[size_t(shownPhase_)], float(time_ - flipTime_),
                      reducedMotion_ ? kReducedMotionFlipSeconds : kFlipSeconds);
  }

  void detect(const std::array<float, 4>& signal, const std::array<Hysteresis, 4>& bands, double time) {
    for (const PhaseEvent& event : detector_.observe(signal, bands)) {
      SceneEvent out{std::string(event.name()), {}};
      if (event.kind == PhaseEvent::Kind::Vent) out.values.push_back({"from", std::string(event.left())});
      out.values.push_back({"source", settings_.phaseSource == PhaseSource::Gpu ? "gpu" : "cpu"});
      events_.emit(time, out);
      sound(event, time);
      // The label types in with every flip: the phase reached on the way up, the one fallen to on the
      // way down (none at pristine, where the crystal is clear again).
      if (event.kind == PhaseEvent::Kind::Up) label_ = int(event.phase), labelTime_ = time_;
      if (event.kind == PhaseEvent::Kind::Vent && !event.fromClimax && event.phase != Phase::Amber)
        label_ = int(event.phase) - 1, labelTime_ = time_;
      if (event.kind == PhaseEvent::Kind::Climax) chromaTime_ = climaxTime_ = time_;
      if (event.kind == PhaseEvent::Kind::Vent && event.fromClimax) crimsonAtVent_ = signal[2];
    }
    // The crystal flips with its label, in the same frame.
    if (int(detector_.phase()) != shownPhase_) {
      flipFrom_ = tint();
      shownPhase_ = int(detector_.phase());
      flipTime_ = time_;
    }
  }

  // A bell for every flip, rising E4 -> B4 -> E5 through amber, rose and crimson and the same notes
  // falling as it vents; the climax chord opens the plate reverb.
  void sound(const PhaseEvent& event, double time) {
    static constexpr float kNotes[4] = {0.0f, audio::kE4, audio::kB4, audio::kE5};
    switch (event.kind) {
      case PhaseEvent::Kind::Up: audio_.bell(time, kNotes[size_t(event.phase)]); break;
      case PhaseEvent::Kind::Climax: audio_.climax(time, settings_.reverbWet); break;
      case PhaseEvent::Kind::Vent:
        if (!event.fromClimax) audio_.bell(time, kNotes[size_t(event.phase)]);
        break;
    }
  }

  const gpu::Device& device_;
  gpu::FrameResources& resources_;
  SceneEvents events_;
  AdaptiveQuality quality_;
  audio::AudioSink& audio_;
  bool droning_ = false;
  float appliedGain_ = -1.0f;
  gpu::ComputeProgram fill_;
  gpu::ComputeProgram resample_;
  gpu::ComputeVariants diffuse_;
  gpu::ComputeProgram statistics_;
  gpu::ComputeProgram chamber_;
  gpu::GraphicsProgram crystal_;
  gpu::BufferHandle statsCounts_;
  gpu::ReadbackRing statsReadback_;
  gpu::BufferHandle lattice_;  // the pair a frame's diffusion ends in: the vapour, saved by checkpoints
  gpu::BufferHandle stage_;
  gpu::ImageHandle view_;
  Settings settings_;
  int builtLattice_ = 0;  // the pair's side: the lattice setting at the tier in use
  int builtSetting_ = 0;  // the lattice setting it was built for
  float builtFill_ = 0.0f;
  bool recorded_ = false;  // a frame has run: a new tier's side carries the vapour over from now on
  enum class Carry { None, Resample, Resampled };
  Carry carry_ = Carry::None;
  float aspect_ = 16.0f / 9.0f;
  double time_ = 0.0;
  uint64_t frame_ = 0;
  uint32_t seed_ = 0;
  struct {
    bool on = false;
    glm::vec3 point{0.0f};  // world: the pass places it in the lattice it runs on
    float rate = 0.0f;
  } source_;
  int stepsPending_ = 0;
  float pendingFill_ = 0.0f;  // written into the lattice by the next frame's fill pass
  double lastVapour_ = 0.0;   // when vapour last entered: a source's frame, or a new lattice
  double statsTime_ = -1.0;   // the frame the newest statistics measured
  double givenUpSeconds_ = 0.0;  // steps beyond kMaxSecondsPerFrame, until the gallery asks
  float stepSeconds_ = 1.0f / 60.0f;
  float proxy_ = 0.0f;
  LatticeStats stats_;
  std::vector<Reading> carried_;  // readings a checkpoint took out of the ring, for the next update
  PhaseDetector detector_;
  std::deque<Sample> history_;
  text::Font labelFont_;
  text::Font titleFont_;
  text::TextPass text_;
  std::array<text::TextLayout, 4> labels_;  // AMBER, ROSE, CRIMSON by phase
  text::TextLayout chroma_;
  int label_ = 0;  // the phase whose name shows, 0: none
  double labelTime_ = 0.0;
  glm::vec2 labelPosition_{0.5f, 0.1f};
  double chromaTime_ = -1.0;  // when CHROMA bloomed; negative: not showing
  float crimsonAtVent_ = 1.0f;  // the crimson signal when the climax ended: CHROMA fades from there
  double climaxTime_ = 0.0;   // when the last climax began
  bool exhaling_ = false;     // after the bloom: no vapour enters until the crystal is pristine again
  bool reducedMotion_ = false;
  int shownPhase_ = 0;        // the phase whose colour the crystal shows (or flips to)
  glm::vec3 flipFrom_ = kPristine;
  double flipTime_ = -1e9;
  glm::vec3 boostCentre_{0.0f};
  float boostSigma_ = 0.0f, boost_ = 1.0f;
};

}  // namespace

std::unique_ptr<Scene> create(const SceneContext& context) { return std::make_unique<BloomScene>(context); }

}  // namespace vitrine::bloom
