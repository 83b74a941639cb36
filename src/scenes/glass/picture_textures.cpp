#include "scenes/glass/picture_textures.h"

#include "core/error.h"

#include <Imath/half.h>
#include <fmt/format.h>

#include <cstdio>
#include <cstring>
#include <vector>

namespace vitrine::glass {
namespace {

constexpr uint32_t kMaxPictureSide = 2048;

template <typename Texel>
gpu::ImageDecl textureDecl(std::string name, VkFormat format, uint32_t width, uint32_t height,
                           const std::vector<Texel>& texels, uint32_t mips) {
  gpu::ImageDecl decl{std::move(name), format, VK_IMAGE_USAGE_SAMPLED_BIT, gpu::ImageSize::absolute(width, height), mips};
  decl.initial.resize(texels.size() * sizeof(Texel));
  std::memcpy(decl.initial.data(), texels.data(), decl.initial.size());
  decl.initialUse = gpu::use::FragmentSample;
  return decl;
}

}  // namespace

PictureTextures::PictureTextures(const SceneContext& context)
    : resources_(context.resources), assets_(context.assets), realtime_(context.realtime) {
  const std::vector<uint32_t> white{0xffffffffu};
  photo_ = resources_.declare(textureDecl("glass photo", VK_FORMAT_R8G8B8A8_SRGB, 1, 1, white, 1));
  const std::vector<uint16_t> black(4, 0);
  panorama_ = resources_.declare(textureDecl("glass panorama", VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, black, 1));
}

PictureTextures::Loaded PictureTextures::update(const Settings& settings) {
  Loaded loaded;
  if (settings.background != appliedBackground_) {
    appliedBackground_ = settings.background;
    source_ = resolveBackdrop(settings.background, assets_);
    pictures_.reset(source_.pictures);
    photoLoaded_ = false;
  }
  if (!photoLoaded_) {
    loaded.photo = true;
    loadPhoto(settings);
  }
  if (settings.environment && (!panoramaLoaded_ || settings.panorama != appliedPanorama_)) {
    loadPanorama(settings);
    loaded.panorama = true;
  }
  return loaded;
}

void PictureTextures::nextPhoto() {
  pictures_.next();
  photoLoaded_ = false;
}

std::string PictureTextures::problem(const Settings& settings) const {
  auto cached = [](std::pair<std::string, std::string>& entry, const std::string& value, auto judge) {
    if (entry.first != value || value.empty()) entry = {value, judge(value)};
    return entry.second;
  };
  std::string why = cached(checkedBackground_, settings.background,
                           [&](const std::string& v) { return glass::backgroundProblem(v, assets_); });
  if (why.empty())
    why = cached(checkedPanorama_, settings.panorama,
                 [&](const std::string& v) { return glass::panoramaProblem(v, assets_); });
  return why;
}

void PictureTextures::warn(const std::string& why) const {
  if (!realtime_) throw Error(why);
  std::fprintf(stderr, "vitrine: glass: %s\n", why.c_str());
}

void PictureTextures::loadPhoto(const Settings& settings) {
  photoLoaded_ = true;
  backgroundProblem_ = source_.problem;
  Picture picture;
  if (!pictures_.load(kMaxPictureSide, picture)) {
    photoSize_ = {0.0f, 0.0f};
    const bool named = source_.kind == BackdropKind::Photo && settings.background != "photo";
    if (backgroundProblem_.empty()) backgroundProblem_ = pictures_.problem();
    if (!backgroundProblem_.empty() && named) return warn(fmt::format("background {}", backgroundProblem_));
    if (source_.kind == BackdropKind::Page || source_.kind == BackdropKind::Photo) {
      // No photo to lie on: say so rather than draw the gradient in silence (not an error: the page reads).
      backgroundProblem_ = backgroundProblem_.empty() ? "no photos fetched (scripts/setup): the gradient stands in"
                                                      : backgroundProblem_ + ": the gradient stands in";
      std::fprintf(stderr, "vitrine: glass: background %s: %s\n", settings.background.c_str(),
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

void PictureTextures::loadPanorama(const Settings& settings) {
  panoramaLoaded_ = true;
  appliedPanorama_ = settings.panorama;
  Panorama pano;
  if (!glass::loadPanorama(settings.panorama, assets_, pano, panoramaProblem_)) {
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
}

}  // namespace vitrine::glass
