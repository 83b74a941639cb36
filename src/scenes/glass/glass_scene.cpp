// glass: spectral dispersion through SDF glass (seed 001, "Spectral Glass"). A cheap backdrop, then an
// instanced proxy per shape whose fragment shader does the per-wavelength work only where glass covers
// the screen; a compute resolve fills the uncovered pixels and blends the history (EMA, progressive
// when the world stops, reprojected from the previous frame's rotations), and a compute post pass
// applies FXAA and the tone map. Optics, shapes and the diamond live in plain C++ the shaders mirror.
#include "scenes/glass/glass_scene.h"
#include "scenes/adaptive_quality.h"

#include "core/error.h"
#include "scenes/glass/backgrounds.h"
#include "scenes/glass/diamond.h"
#include "scenes/glass/frame_block.h"
#include "scenes/glass/materials.h"
#include "scenes/glass/optics.h"
#include "scenes/glass/page.h"
#include "scenes/glass/settings.h"
#include "scenes/glass/shapes.h"
#include "maths/hash.h"
#include "text/text_pass.h"

#include <GLFW/glfw3.h>
#include <Imath/half.h>
#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace vitrine::glass {
namespace {

constexpr float kViewHeight = 1073.0f;  // world units down the view: the original's canvas height
constexpr VkFormat kColourFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkFormat kMotionFormat = VK_FORMAT_R16G16_SFLOAT;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr uint32_t kMaxPictureSide = 2048;
constexpr float kPageBodyEm = 19.0f;  // body text size, world units

struct ComposePush {
  glm::vec4 photo;  // photo aspect / view aspect cover scale xy, has photo, page panel
  glm::ivec4 kind;  // 0 gradient, 1 checker, 2 photo; panel on
  glm::vec4 panel;  // the page's paper, in pixels: x0, y0, x1, y1
};

struct ResolvePush {
  float alpha;        // weight of this frame
  uint32_t valid;     // the history holds last frame
  uint32_t reproject;
  uint32_t pad;
};

struct PostPush {
  uint32_t fxaa;
  uint32_t filmic;
  uint32_t pad0, pad1;
};

const gpu::ProgramLayout kComposeLayout{
    {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(ComposePush)};

// The spectral programs' bindings: the frame block, the backdrop and the panorama, the diamond's planes,
// The spectral programs' bindings: the frame block, the backdrop and the panorama, the diamond's planes,
gpu::ProgramLayout spectralLayout(ShapeKind shape, bool compute) {
  std::vector<VkDescriptorType> bindings{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
  if (compute) bindings.insert(bindings.end(), {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  else bindings.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  return {bindings, 0, {int32_t(shape)}};
}

gpu::GraphicsState glassState() {
  gpu::GraphicsState state;
  state.vertex = "glass/proxy.vert";
  state.fragment = "glass/glass.frag";
  state.colorFormats = {kColourFormat, kMotionFormat};
  state.depthFormat = kDepthFormat;
  state.cull = VK_CULL_MODE_FRONT_BIT;  // back faces: one fragment per covered pixel, even from inside
  return state;
}

gpu::ImageDecl screenImage(std::string name, VkFormat format, VkImageUsageFlags usage) {
  gpu::ImageDecl decl{std::move(name), format, usage, gpu::ImageSize::relative(1.0f)};
  return decl;
}

template <typename Texel>
gpu::ImageDecl textureDecl(std::string name, VkFormat format, uint32_t width, uint32_t height,
                           const std::vector<Texel>& texels, uint32_t mips) {
  gpu::ImageDecl decl{std::move(name), format, VK_IMAGE_USAGE_SAMPLED_BIT, gpu::ImageSize::absolute(width, height), mips};
  decl.initial.resize(texels.size() * sizeof(Texel));
  std::memcpy(decl.initial.data(), texels.data(), decl.initial.size());
  decl.initialUse = gpu::use::FragmentSample;
  return decl;
}

glm::mat4 padded(const glm::mat3& m) { return glm::mat4(m); }

}  // namespace

class GlassScene final : public Scene {
 public:
  explicit GlassScene(const SceneContext& context)
      : device_(context.device),
        realtime_(context.realtime),
        quality_(context),
        resources_(context.resources),
        assets_(context.assets),
        programs_(context.programs),
        compose_(context.programs, "glass/compose.comp", kComposeLayout),
        resolve_(context.programs, "glass/resolve.comp",
                 {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                   VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                   VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                   VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                  sizeof(ResolvePush)}),
        post_(context.programs, "glass/post.comp",
              {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(PostPush)}),
        bodyFont_(text::Font::fromAssets(context.assets, "Fraunces")),
        titleFont_(text::Font::fromAssets(context.assets, "CormorantSC")),
        text_(context, {{&bodyFont_, pageParagraphs(), {}}, {&titleFont_, {pageParagraphs().front()}, {0.04f}}},
              text::AtlasOptions{1024, 1024, 48, 8, 1}),
        diamond_(makeDiamond(Settings{}.diamondSize)) {
    colour_ = resources_.declare(screenImage("glass colour", kColourFormat,
                                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
    motion_ = resources_.declare(screenImage("glass motion", kMotionFormat,
                                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT));
    depth_ = resources_.declare(screenImage("glass depth", kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT));
    auto history = screenImage("glass history", kColourFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
    history.pairing = gpu::Pairing::History;
    history_ = resources_.declare(history);
    auto backdrop = screenImage("glass backdrop", kColourFormat, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT);
    backdrop.mips = 0;  // the original's LOD rule reads a full chain
    backdrop_ = resources_.declare(backdrop);
    const std::vector<uint32_t> white{0xffffffffu};
    photo_ = resources_.declare(textureDecl("glass photo", VK_FORMAT_R8G8B8A8_SRGB, 1, 1, white, 1));
    const std::vector<uint16_t> black(4, 0);
    panorama_ = resources_.declare(textureDecl("glass panorama", VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, black, 1));

    const auto measure = [&](const std::string& candidate, bool title) {
      return text_.layout(title ? titleFont_ : bodyFont_, candidate, title ? text::Shaping{0.04f} : text::Shaping{})
          .advance;
    };
    for (const PageLine& line : wrapPage(pageParagraphs(), measure)) {
      pageLines_.push_back(line);
      pageLayouts_.push_back(
          text_.layout(line.title ? titleFont_ : bodyFont_, line.text, line.title ? text::Shaping{0.04f} : text::Shaping{}));
    }
    layoutInstances();
  }

  void resize(VkExtent2D target) override {
    extent_ = target;
    backdropDirty_ = true;
    resetHistory_ = true;
  }

  void update(const FrameInput& input) override;
  void record(const FrameContext& frame) override;
  params::Bound parameters() override { return {&schema(), &settings_}; }
  // A background or panorama that names nothing usable refuses the change: headless runs stop with the
  // value named, the gallery's panel shows why and keeps what it had.
  std::string checkParameters() const override;
  float renderScale() const override { return tierScale(quality_.active()); }
  void drawPanel() override;

 private:
  struct Instance {
    glm::vec2 centre{0.0f}, previous{0.0f};
  };

  glm::vec2 viewSize() const {
    const float aspect = extent_.height ? float(extent_.width) / float(extent_.height) : 1.0f;
    return {kViewHeight * aspect, kViewHeight};
  }
  int instanceCount() const { return settings_.shape == ShapeKind::Diamond ? 1 : kMaxInstances; }
  ShapeDims dims() const;
  float hitRadius(glm::vec2 offset) const;
  void layoutInstances();
  void shuffle();
  void syncMaterial();
  void handleKeys(const FrameInput& input);
  void handleDrag(const FrameInput& input);
  void handleDrops(const FrameInput& input);
  void loadBackdrop();
  void loadPanorama();
  FrameBlock frameBlock() const;
  void composeBackdrop(const FrameContext& frame);
  // A compute pass over the view that samples `source` (linear, clamped) and writes `target` through
  // `targetView`, with `push` as its constants.
  template <typename Push>
  void sampleInto(const FrameContext& frame, const gpu::ComputeProgram& program, gpu::Image& source,
                  gpu::Image& target, VkImageView targetView, const Push& push) const {
    frame.transition(source, gpu::use::ComputeSample);
    frame.transition(target, gpu::use::ComputeWrite);
    program.bind(frame.cmd);
    program.constants(frame.cmd, push);
    program.push(frame.cmd, gpu::Bindings()
                                .sampledImage(source.view(), device_.sampler(gpu::Device::Filter::Linear,
                                                                             gpu::Device::Address::Clamp),
                                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                                .storageImage(targetView));
    program.dispatchOver(frame.cmd, extent_, {8, 8});
  }

  // This shape's spectral program for the chosen path, built the first time it is needed.
  const gpu::GraphicsProgram& rasterProgram() {
    auto& program = raster_[size_t(settings_.shape)];
    if (!program) program = std::make_unique<gpu::GraphicsProgram>(programs_, glassState(),
                                                                   spectralLayout(settings_.shape, false));
    return *program;
  }
  const gpu::ComputeProgram& computeProgram() {
    auto& program = compute_[size_t(settings_.shape)];
    if (!program) program = std::make_unique<gpu::ComputeProgram>(programs_, "glass/spectral.comp",
                                                                  spectralLayout(settings_.shape, true));
    return *program;
  }
  void recordSpectral(const FrameContext& frame, const gpu::StreamSlice& block);

  const gpu::Device& device_;
  bool realtime_;  // the gallery: a file that fails to load is a panel warning; headless, an error
  AdaptiveQuality quality_;
  gpu::FrameResources& resources_;
  const Assets& assets_;
  gpu::ProgramLibrary& programs_;
  gpu::ComputeProgram compose_;
  std::array<std::unique_ptr<gpu::GraphicsProgram>, 5> raster_;
  std::array<std::unique_ptr<gpu::ComputeProgram>, 5> compute_;
  gpu::ComputeProgram resolve_;
  gpu::ComputeProgram post_;
  text::Font bodyFont_, titleFont_;
  text::TextPass text_;
  std::vector<PageLine> pageLines_;
  std::vector<text::TextLayout> pageLayouts_;
  DiamondGeometry diamond_;
  std::optional<gpu::Buffer> diamondPlanes_, diamondHull_;
  uint32_t hullVertices_ = 0;
  float builtDiamondSize_ = 0.0f;

  Settings settings_;
  Settings applied_;           // last frame's values: any change restarts the accumulation
  gpu::ImageHandle colour_, motion_, depth_, history_, backdrop_, photo_, panorama_;
  VkExtent2D extent_{1, 1};
  std::array<Instance, kMaxInstances> instances_{};
  ShapeKind laidOut_ = ShapeKind::Cube;
  int dragged_ = -1;
  bool wasDragging_ = false;
  uint32_t shuffles_ = 0;

  double time_ = 0.0, previousTime_ = 0.0;
  uint64_t frame_ = 0;
  uint32_t seed_ = 0;
  bool zHeld_ = false;
  bool resetHistory_ = true;
  uint32_t pausedFrames_ = 0;

  std::string appliedBackground_, appliedPanorama_;
  bool panoramaLoaded_ = false;
  BackdropSource backdropSource_;
  PictureCycle pictures_;
  bool photoLoaded_ = false;
  bool backdropDirty_ = true;
  std::string backgroundProblem_, panoramaProblem_;
  // checkParameters' last answers, so a slider's drag does not read the named file again at every step.
  mutable std::pair<std::string, std::string> checkedBackground_, checkedPanorama_;
  void warn(const std::string& problem);
  glm::vec2 photoSize_{1.0f};
};

ShapeDims GlassScene::dims() const {
  const Settings& s = settings_;
  switch (s.shape) {
    case ShapeKind::Pill:
      return pillDims({s.pillLength, s.pillHeight, s.pillThickness}, s.pillEdge, s.smoothCurvature);
    case ShapeKind::Prism:
      return prismDims({s.prismLength, s.prismWidth, s.prismDepth});
    case ShapeKind::Cube:
      return cubeDims(s.cubeSize, s.cubeEdge, s.smoothCurvature);
    case ShapeKind::Plate:
      return plateDims({s.plateSize, s.plateSize, s.plateThickness}, s.plateEdge, s.waveAmplitude, s.waveLength,
                       plateWavePhase(float(time_)), s.smoothCurvature);
    case ShapeKind::Diamond:
      break;
  }
  return diamondDims(s.diamondSize);
}

// A shape is grabbed within its silhouette's rough extent: a circle for the tumbling cube and diamond.
float GlassScene::hitRadius(glm::vec2 offset) const {
  const glm::vec3 half = shapeHalfExtent(dims());
  if (settings_.shape == ShapeKind::Cube || settings_.shape == ShapeKind::Diamond || settings_.shape == ShapeKind::Plate)
    return glm::length(offset) / std::max(half.x, half.y);
  return std::max(std::abs(offset.x) / half.x, std::abs(offset.y) / half.y);
}

void GlassScene::layoutInstances() {
  laidOut_ = settings_.shape;
  const glm::vec2 view = viewSize();
  if (instanceCount() == 1) {
    instances_[0] = {{0.0f, 0.0f}, {0.0f, 0.0f}};
    return;
  }
  const glm::vec2 spread{std::min(0.22f * view.x, 300.0f), 0.2f * view.y};
  const glm::vec2 at[kMaxInstances] = {{-1, 1}, {1, 1}, {-1, -1}, {1, -1}};
  for (int i = 0; i < kMaxInstances; ++i) instances_[i].centre = instances_[i].previous = at[i] * spread;
}

// Random places inside the view, kept apart where the view has room; the same for the same seed.
void GlassScene::shuffle() {
  const glm::vec2 view = viewSize();
  // A turning shape reaches as far as its box's half diagonal; pill and prism keep their box.
  const glm::vec3 half = shapeHalfExtent(dims());
  const bool turns = settings_.shape != ShapeKind::Pill && settings_.shape != ShapeKind::Prism;
  const glm::vec2 reach = turns ? glm::vec2(glm::length(half)) : glm::vec2(half);
  const glm::vec2 room = glm::max(view * 0.5f - reach, glm::vec2(0.0f));
  ++shuffles_;
  for (int i = 0; i < instanceCount(); ++i) {
    glm::vec2 best{0.0f};
    for (uint32_t attempt = 0; attempt < 64; ++attempt) {
      const glm::uvec3 key{seed_, shuffles_ * 97u + uint32_t(i), attempt};
      best = (glm::vec2(maths::hash01(key), maths::hash01(key + glm::uvec3(0, 0, 7919u))) * 2.0f - 1.0f) * room;
      bool apart = true;
      for (int j = 0; j < i; ++j)
        apart = apart && glm::length(best - instances_[j].centre) > 2.0f * std::max(reach.x, reach.y);
      if (apart) break;
    }
    instances_[i].centre = best;
  }
  resetHistory_ = true;
}

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

void GlassScene::handleKeys(const FrameInput& input) {
  auto acted = [&](std::string_view name) {
    return std::any_of(input.actions.begin(), input.actions.end(), [&](const ActionCall& c) { return c.name == name; });
  };
  if (input.pressed(GLFW_KEY_SPACE) || acted("shuffle")) shuffle();
  if (input.pressed(GLFW_KEY_R) || acted("next_photo")) {
    pictures_.next();
    photoLoaded_ = false;
  }
  const std::pair<int, DiamondView> views[] = {{GLFW_KEY_T, DiamondView::Top}, {GLFW_KEY_S, DiamondView::Side},
                                               {GLFW_KEY_B, DiamondView::Bottom}, {GLFW_KEY_F, DiamondView::Free}};
  for (const auto& [key, view] : views)
    if (input.pressed(key) && settings_.shape == ShapeKind::Diamond) settings_.diamondView = view;
  const bool z = input.held(GLFW_KEY_Z);
  if (z != zHeld_) resetHistory_ = true;
  zHeld_ = z;
}

void GlassScene::handleDrag(const FrameInput& input) {
  const glm::vec2 view = viewSize();
  const glm::vec2 cursor = (input.cursor.normalized - 0.5f) * glm::vec2(1.0f, -1.0f) * view;
  if (input.cursor.dragging && !wasDragging_) {
    dragged_ = -1;
    float nearest = 1.0f;
    for (int i = 0; i < instanceCount(); ++i) {
      const float r = hitRadius(cursor - instances_[i].centre);
      if (r <= nearest) nearest = r, dragged_ = i;
    }
  }
  if (!input.cursor.dragging) dragged_ = -1;
  wasDragging_ = input.cursor.dragging;
  if (dragged_ >= 0) instances_[size_t(dragged_)].centre += input.cursor.dragDelta * glm::vec2(1.0f, -1.0f) * view;
}

// A dropped panorama (EXR) lights the scene when the environment is on; anything else is a backdrop.
void GlassScene::handleDrops(const FrameInput& input) {
  for (const std::string& path : input.droppedFiles) {
    const bool exr = std::filesystem::path(path).extension() == ".exr";
    if (exr && settings_.environment) settings_.panorama = path;
    else settings_.background = path;
  }
}

void GlassScene::update(const FrameInput& input) {
  quality_.update(settings_.tier, settings_.targetMs, input);
  seed_ = input.seed;
  frame_ = input.frame;
  previousTime_ = time_;
  if (!settings_.stopWorld && !input.reducedMotion) time_ += input.dt;
  for (Instance& instance : instances_) instance.previous = instance.centre;

  syncMaterial();
  if (settings_.shape != laidOut_) layoutInstances();
  handleKeys(input);
  handleDrag(input);
  handleDrops(input);

  if (settings_.background != appliedBackground_) {
    appliedBackground_ = settings_.background;
    backdropSource_ = resolveBackdrop(settings_.background, assets_);
    pictures_.reset(backdropSource_.pictures);
    photoLoaded_ = false;
  }
  if (!photoLoaded_) loadBackdrop();
  if (settings_.environment && (!panoramaLoaded_ || settings_.panorama != appliedPanorama_)) loadPanorama();

  if (!(settings_ == applied_)) resetHistory_ = true;
  // A drag while the world stands still restarts the progressive average; in motion the reprojected
  // EMA lets go of the old place within a few frames anyway.
  if (settings_.stopWorld)
    for (const Instance& instance : instances_) resetHistory_ = resetHistory_ || instance.centre != instance.previous;
  applied_ = settings_;
  if (settings_.stopWorld) pausedFrames_ = resetHistory_ ? 1 : pausedFrames_ + 1;
  else pausedFrames_ = 0;
}

std::string GlassScene::checkParameters() const {
  auto cached = [](std::pair<std::string, std::string>& entry, const std::string& value, auto judge) {
    if (entry.first != value || value.empty()) entry = {value, judge(value)};
    return entry.second;
  };
  std::string why = cached(checkedBackground_, settings_.background,
                           [&](const std::string& v) { return backgroundProblem(v, assets_); });
  if (why.empty())
    why = cached(checkedPanorama_, settings_.panorama, [&](const std::string& v) { return panoramaProblem(v, assets_); });
  return why;
}

// What could not be shown: an error in headless runs and tests (the picture would silently be another),
// in the gallery a line on stderr and the panel's warning.
void GlassScene::warn(const std::string& problem) {
  if (!realtime_) throw Error(problem);
  std::fprintf(stderr, "vitrine: glass: %s\n", problem.c_str());
}

// Reads the backdrop's picture here, not while recording: its texels upload as the next frame begins.
void GlassScene::loadBackdrop() {
  photoLoaded_ = true;
  backdropDirty_ = true;
  backgroundProblem_ = backdropSource_.problem;
  Picture picture;
  if (!pictures_.load(kMaxPictureSide, picture)) {
    photoSize_ = {0.0f, 0.0f};
    const bool named = backdropSource_.kind == BackdropKind::Photo && settings_.background != "photo";
    if (backgroundProblem_.empty()) backgroundProblem_ = pictures_.problem();
    if (!backgroundProblem_.empty() && named) return warn(fmt::format("background {}", backgroundProblem_));
    if (backdropSource_.kind == BackdropKind::Page || backdropSource_.kind == BackdropKind::Photo) {
      // No photo to lie on: say so rather than draw the gradient in silence (not an error: the page reads).
      backgroundProblem_ = !canReadPictures() ? "this build reads no pictures (VITRINE_WITH_OIIO=OFF): the gradient "
                                                "stands in for the photo"
                           : backgroundProblem_.empty() ? "no photos fetched (scripts/setup): the gradient stands in"
                                                        : backgroundProblem_ + ": the gradient stands in";
      std::fprintf(stderr, "vitrine: glass: background %s: %s\n", settings_.background.c_str(),
                   backgroundProblem_.c_str());
    }
    return;
  }
  photoSize_ = {float(picture.width), float(picture.height)};
  std::vector<uint32_t> texels(size_t(picture.width) * picture.height);
  std::memcpy(texels.data(), picture.rgba.data(), picture.rgba.size());
  resources_.redeclare(photo_, textureDecl("glass photo", VK_FORMAT_R8G8B8A8_SRGB, picture.width, picture.height,
                                           texels, 1));
}

void GlassScene::loadPanorama() {
  panoramaLoaded_ = true;
  appliedPanorama_ = settings_.panorama;
  Panorama pano;
  if (!glass::loadPanorama(settings_.panorama, assets_, pano, panoramaProblem_)) {
    warn(panoramaProblem_);
    // A sky from two colours stands in: dim ground, bright zenith, so the glass still has light to bend.
    pano = {2, 2, {}};
    for (float v : {0.9f, 1.0f, 1.2f, 1.0f, 0.9f, 1.0f, 1.2f, 1.0f, 0.12f, 0.1f, 0.08f, 1.0f, 0.12f, 0.1f, 0.08f, 1.0f})
      pano.halves.push_back(half(v).bits());
  } else {
    panoramaProblem_.clear();
  }
  resources_.redeclare(panorama_, textureDecl("glass panorama", VK_FORMAT_R16G16B16A16_SFLOAT, pano.width, pano.height,
                                              pano.halves, 0));
  resetHistory_ = true;
}

FrameBlock GlassScene::frameBlock() const {
  const Settings& s = settings_;
  const glm::vec2 view = viewSize();
  FrameBlock b{};
  const bool ortho = s.projection == Projection::Orthographic;
  const float camZ = 0.5f * view.y / std::tan(glm::radians(s.fov) * 0.5f);
  const glm::vec3 eye{0.0f, 0.0f, camZ};
  const glm::mat4 look = glm::lookAtRH(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  glm::mat4 projection = ortho ? glm::orthoRH_ZO(-0.5f * view.x, 0.5f * view.x, -0.5f * view.y, 0.5f * view.y, 1.0f,
                                                 camZ + 4000.0f)
                               : glm::perspectiveRH_ZO(glm::radians(s.fov), view.x / view.y, 1.0f, camZ + 4000.0f);
  projection[1][1] *= -1.0f;  // Vulkan's y points down
  b.viewProjection = projection * look;
  b.camera = {eye, ortho ? 1.0f : 0.0f};
  b.view = {view.x, view.y, float(extent_.width), float(extent_.height)};
  b.glass = {s.ior, s.abbe, s.strength, s.depth};
  const int n = zHeld_ ? 3 : sampleCount(s);
  const bool jitter = s.jitter && !zHeld_;
  b.spectral = {n, s.mode == RefractionMode::Approx ? 1 : 0, jitter ? 1 : 0, s.optics == Optics::Physical ? 1 : 0};
  b.spectralExtra = {heroLambda(uint32_t(frame_), seed_, jitter), 0.0f, 0.0f, 0.0f};
  if (s.dispersion == Dispersion::Sellmeier && s.material > 0)
    if (const auto& coefficients = kMaterials[size_t(s.material - 1)].sellmeier) {
      b.spectralExtra.z = 1.0f;
      b.sellmeierB = {coefficients->B[0], coefficients->B[1], coefficients->B[2], 0.0f};
      b.sellmeierC = {coefficients->C[0], coefficients->C[1], coefficients->C[2], 0.0f};
    }
  b.shape = {int(s.shape), instanceCount(), s.bounces, int(s.diamondDebug)};
  b.frameInfo = {int(frame_), int(seed_), int(s.aa), s.environment ? 1 : 0};
  b.environment = {s.exposure, s.envRotation, 0.0f, s.showProxy ? 1.0f : 0.0f};
  const ShapeDims d = dims();
  b.shapeSize = d.sizeEdge;
  b.shapeWave = d.wave;
  auto rotationAt = [&](double t) -> glm::mat3 {
    switch (s.shape) {
      case ShapeKind::Cube: return cubeRotation(float(t));
      case ShapeKind::Plate: return plateRotation(float(t));
      case ShapeKind::Diamond: return diamondRotation(s.diamondView, float(t));
      default: return glm::mat3(1.0f);
    }
  };
  b.rotation = padded(rotationAt(time_));
  b.previousRotation = padded(rotationAt(previousTime_));
  for (int i = 0; i < kMaxInstances; ++i) b.centres[i] = {instances_[i].centre, instances_[i].previous};
  // Each instance's pixels: its turned proxy box's corners projected, as the raster path's proxy covers.
  const glm::vec3 half = shapeHalfExtent(d) + 1.0f;
  const glm::mat3 toWorld = glm::transpose(glm::mat3(b.rotation));
  const glm::vec2 pixels{float(extent_.width), float(extent_.height)};
  for (int i = 0; i < kMaxInstances; ++i) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local = half * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      const glm::vec4 clip = b.viewProjection * glm::vec4(glm::vec3(instances_[i].centre, 0.0f) + toWorld * local, 1.0f);
      const glm::vec2 pixel = (glm::vec2(clip) / std::max(clip.w, 1e-3f) * 0.5f + 0.5f) * pixels;
      lo = glm::min(lo, pixel);
      hi = glm::max(hi, pixel);
    }
    b.rects[i] = {lo, hi};
  }
  return b;
}

void GlassScene::composeBackdrop(const FrameContext& frame) {
  const auto pass = frame.pass("glass backdrop");
  gpu::Image& backdrop = frame.image(backdrop_);
  gpu::Image& photo = frame.image(photo_);
  const glm::vec2 view{float(extent_.width), float(extent_.height)};
  const bool hasPhoto = photoSize_.x > 0.0f && backdropSource_.kind != BackdropKind::Gradient &&
                        backdropSource_.kind != BackdropKind::Checker;
  // Cover the view with the photo, as CSS' background-size: cover does.
  const float cover = hasPhoto ? std::max(view.x / photoSize_.x, view.y / photoSize_.y) : 1.0f;
  const glm::vec2 scale = hasPhoto ? view / (photoSize_ * cover) : glm::vec2(1.0f);
  const bool page = backdropSource_.kind == BackdropKind::Page;
  const float em = kPageBodyEm * view.y / kViewHeight;  // body em in pixels
  const float columnPx = kPageColumnEm * em;
  const glm::vec4 panel{0.5f * (view.x - columnPx) - 1.5f * em, 0.0f, 0.5f * (view.x + columnPx) + 1.5f * em, view.y};
  const int kind = backdropSource_.kind == BackdropKind::Checker ? 1 : hasPhoto ? 2 : 0;
  ComposePush push{{scale, hasPhoto ? 1.0f : 0.0f, 0.0f}, {kind, page ? 1 : 0, 0, 0}, panel};
  sampleInto(frame, compose_, photo, backdrop, backdrop.mipView(0), push);
  if (page) {
    std::vector<text::TextDraw> draws;
    const float top = 2.5f * em;
    for (size_t i = 0; i < pageLines_.size(); ++i) {
      const PageLine& line = pageLines_[i];
      text::TextDraw draw;
      draw.layout = &pageLayouts_[i];
      draw.anchor = text::Anchor::Baseline;
      draw.sizePx = em * (line.title ? kPageTitleScale : 1.0f);
      draw.position = {0.5f * (view.x - columnPx), top + line.baselineEm * em};
      draw.color = line.title ? glm::vec4(0.35f, 0.08f, 0.05f, 1.0f) : glm::vec4(0.02f, 0.02f, 0.025f, 1.0f);
      draws.push_back(draw);
    }
    text_.record(frame, backdrop, draws);
  }
  gpu::generateMips(frame.cmd, backdrop, gpu::use::FragmentSample);
  backdropDirty_ = false;
}

void GlassScene::record(const FrameContext& frame) {
  const float size = settings_.diamondSize;
  if (!diamondPlanes_ || size != builtDiamondSize_) {
    diamond_ = makeDiamond(size);
    const std::vector<glm::vec4> planes = diamondBufferWords(diamond_);
    std::vector<glm::vec4> hull;
    for (const glm::vec3& v : diamondHullTriangles(diamond_)) hull.emplace_back(v, 1.0f);
    if (!diamondPlanes_) {
      const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
      diamondPlanes_.emplace(device_, planes.size() * sizeof(glm::vec4), usage, gpu::MemoryUse::Device, "glass diamond planes");
      diamondHull_.emplace(device_, hull.size() * sizeof(glm::vec4), usage, gpu::MemoryUse::Device, "glass diamond hull");
    }
    frame.upload(*diamondPlanes_, 0, std::as_bytes(std::span(planes)), gpu::use::FragmentReadBuffer);
    frame.upload(*diamondHull_, 0, std::as_bytes(std::span(hull)), gpu::use::VertexReadBuffer);
    hullVertices_ = uint32_t(hull.size());
    builtDiamondSize_ = size;
  }
  if (backdropDirty_) composeBackdrop(frame);

  const gpu::StreamSlice block = frame.uniform(frameBlock());
  gpu::Image& backdrop = frame.image(backdrop_);
  gpu::Image& panorama = frame.image(panorama_);
  const VkSampler mipped = device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp, true);
  const VkSampler wrapped = device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Repeat, true);
  constexpr VkImageLayout kSampled = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const auto sources = [&](gpu::Bindings bindings) {
    return bindings.storageBuffer(block.buffer, block.offset, sizeof(FrameBlock))
        .sampledImage(backdrop.view(), mipped, kSampled)
        .sampledImage(panorama.view(), wrapped, kSampled);
  };
  recordSpectral(frame, block);
  {
    const auto pass = frame.pass("glass resolve");
    gpu::Image& current = frame.image(history_);
    gpu::Image& previous = frame.resources.previous(history_);
    frame.transition(frame.image(colour_), gpu::use::ComputeRead);
    frame.transition(frame.image(motion_), gpu::use::ComputeRead);
    frame.transition(previous, gpu::use::HistoryRead);
    frame.transition(current, gpu::use::ComputeWrite);
    frame.transition(backdrop, gpu::use::ComputeSample);
    frame.transition(panorama, gpu::use::ComputeSample);
    const bool valid = frame.resources.historyValid(history_) && !resetHistory_;
    // Stop the world: a progressive average whose 1/256 floor keeps fp16 from rounding new samples away.
    const float alpha = !valid ? 1.0f
                        : settings_.stopWorld ? std::max(1.0f / float(std::max(pausedFrames_, 1u)), 1.0f / 256.0f)
                                              : settings_.historyAlpha;
    ResolvePush push{alpha, valid ? 1u : 0u, settings_.stopWorld ? 0u : 1u, 0u};
    resolve_.bind(frame.cmd);
    resolve_.constants(frame.cmd, push);
    resolve_.push(frame.cmd, sources(gpu::Bindings())
                                 .storageImage(frame.image(colour_).view())
                                 .storageImage(frame.image(motion_).view())
                                 .sampledImage(previous.view(), device_.sampler(gpu::Device::Filter::Linear,
                                                                                gpu::Device::Address::Clamp),
                                               kSampled)
                                 .storageImage(current.view()));
    resolve_.dispatchOver(frame.cmd, extent_, {8, 8});
    resetHistory_ = false;
  }
  {
    const auto pass = frame.pass("glass post");
    gpu::Image& current = frame.image(history_);
    const PostPush push{settings_.aa == Antialiasing::Fxaa ? 1u : 0u, settings_.optics == Optics::Physical ? 1u : 0u,
                        0, 0};
    sampleInto(frame, post_, current, frame.target, frame.target.view(), push);
  }
}

void GlassScene::recordSpectral(const FrameContext& frame, const gpu::StreamSlice& block) {
  const auto pass = frame.pass("glass spectral");
  gpu::Image& backdrop = frame.image(backdrop_);
  gpu::Image& panorama = frame.image(panorama_);
  const bool compute = settings_.pass == SpectralPass::Compute;
  const gpu::ImageUse sampled = compute ? gpu::use::ComputeSample : gpu::use::FragmentSample;
  frame.transition(backdrop, sampled);
  frame.transition(panorama, sampled);
  frame.transition(*diamondPlanes_, compute ? gpu::use::ComputeReadBuffer : gpu::use::FragmentReadBuffer);
  constexpr VkImageLayout kSampled = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  const auto bindings = gpu::Bindings()
                            .storageBuffer(block.buffer, block.offset, sizeof(FrameBlock))
                            .sampledImage(backdrop.view(), device_.sampler(gpu::Device::Filter::Linear,
                                                                           gpu::Device::Address::Clamp, true),
                                          kSampled)
                            .sampledImage(panorama.view(), device_.sampler(gpu::Device::Filter::Linear,
                                                                           gpu::Device::Address::Repeat, true),
                                          kSampled)
                            .storageBuffer(diamondPlanes_->handle());
  if (compute) {
    gpu::Image& colour = frame.image(colour_);
    gpu::Image& motion = frame.image(motion_);
    frame.transition(colour, gpu::use::ComputeWrite);
    frame.transition(motion, gpu::use::ComputeWrite);
    const gpu::ComputeProgram& program = computeProgram();
    program.bind(frame.cmd);
    program.push(frame.cmd, gpu::Bindings(bindings).storageImage(colour.view()).storageImage(motion.view()));
    program.dispatchOver(frame.cmd, extent_, {8, 8});
    return;
  }
  frame.transition(*diamondHull_, gpu::use::VertexReadBuffer);
  gpu::RenderingDesc desc;
  desc.colors = {{&frame.image(colour_), VkClearColorValue{}}, {&frame.image(motion_), VkClearColorValue{}}};
  desc.depth = gpu::DepthAttachment{&frame.image(depth_)};
  const auto rendering = frame.rendering(desc);
  const gpu::GraphicsProgram& program = rasterProgram();
  program.bind(frame.cmd);
  program.push(frame.cmd, gpu::Bindings(bindings).storageBuffer(diamondHull_->handle()));
  const bool diamond = settings_.shape == ShapeKind::Diamond;
  vkCmdDraw(frame.cmd, diamond ? hullVertices_ : 36u, uint32_t(instanceCount()), 0, 0);
}

void GlassScene::drawPanel() {
  const int n = zHeld_ ? 3 : sampleCount(settings_);
  ImGui::Text("%d wavelengths%s, %s optics", n, zHeld_ ? " (Z held: jitter off)" : "",
              settings_.optics == Optics::Physical ? "physical" : "seed");
  if (settings_.material > 0) {
    const Material& m = kMaterials[size_t(settings_.material - 1)];
    ImGui::Text("%s: n_d %.4f, V_d %.1f%s", std::string(m.label).c_str(), m.nd, m.vd,
                m.sellmeier ? ", Sellmeier known" : "");
  }
  if (!settings_.environment) {
    const std::string name = pictures_.currentName();
    ImGui::Text("backdrop: %s%s", settings_.background.c_str(), name.empty() ? "" : (" - " + name).c_str());
  }
  const auto warning = [](const std::string& line) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", line.c_str());
    ImGui::PopStyleColor();
  };
  if (!backgroundProblem_.empty()) warning(backgroundProblem_);
  if (settings_.environment && !panoramaProblem_.empty()) warning(panoramaProblem_);
  if (settings_.stopWorld) ImGui::Text("accumulated %u frames", pausedFrames_);
  ImGui::TextDisabled("drag a shape; Space shuffles, R next photo, hold Z, T/S/B/F diamond views");
}

constexpr SceneAction kActions[] = {
    {"shuffle", {}, "the shapes to new places (Space)"},
    {"next_photo", {}, "the next photo behind the glass (R)"},
};

constinit const SceneInfo kSceneInfo = sceneInfo<GlassScene>("glass", "Spectral Glass", 2, &schema,
    "Drag a shape to move it. Space shuffles them, hold Z for three wavelengths without jitter, T / S / B / F turn "
    "the diamond, R shows the next photo; drop an image (or an EXR panorama) on the window.", kActions);

}  // namespace vitrine::glass
