#include "scenes/glass/backgrounds.h"

#include "core/bounded_file.h"
#include "core/error.h"
#include "image/image_io.h"
#include "scenes/glass/studio.h"

#include <Imath/half.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>

namespace vitrine::glass {

BackdropSource resolveBackdrop(std::string_view value, const Assets& assets) {
  BackdropSource source;
  if (value == "gradient") return source;
  if (value == "checker") {
    source.kind = BackdropKind::Checker;
    return source;
  }
  if (value == "page" || value == "photo") {
    source.kind = value == "page" ? BackdropKind::Page : BackdropKind::Photo;
    source.pictures = assets.photos();
    return source;
  }
  const std::filesystem::path path(value);
  std::error_code ec;
  source.kind = BackdropKind::Photo;
  if (std::filesystem::is_directory(path, ec)) {
    source.pictures = filesIn(path, kPictureExtensions);
    if (source.pictures.empty()) source.problem = fmt::format("{}: no pictures in this folder", value);
  } else if (std::filesystem::is_regular_file(path, ec)) {
    source.pictures = {path};
  } else {
    source.problem = fmt::format("{}: {}", value, std::filesystem::exists(path, ec) ? "not a file or folder" : "not found");
  }
  if (!source.problem.empty()) source.kind = BackdropKind::Gradient;
  return source;
}

std::string backgroundProblem(std::string_view value, const Assets& assets) {
  const BackdropSource source = resolveBackdrop(value, assets);
  if (!source.problem.empty()) {
    const std::filesystem::path path(value);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec) && path.extension().empty() && path.parent_path().empty())
      return fmt::format("background {}: not page, photo, gradient or checker, nor an image file or folder", value);
    return fmt::format("background {}", source.problem);
  }
  if (source.kind != BackdropKind::Photo || source.pictures.size() != 1 || value == "photo") return {};
  try {
    readPicture(source.pictures.front(), 16);
    return {};
  } catch (const Error& error) {
    return fmt::format("background {}: {}", value, error.what());
  }
}

std::string panoramaProblem(std::string_view value, const Assets& assets) {
  if (value == kStudioPanorama) return {};
  for (const auto& candidate : assets.panoramas())
    if (candidate.stem() == value) return {};
  const std::filesystem::path path(value);
  std::error_code ec;
  const auto names = fmt::format("{}", fmt::join(panoramaNames(assets), ", "));
  if (!std::filesystem::exists(path, ec))
    return fmt::format("panorama {}: not one of {} nor an EXR file", value, names);
  try {
    checkBoundedFile(path, kMaxPictureFileBytes);
  } catch (const FileRefused& refused) {
    return fmt::format("panorama {}: {}", value, refused.why);
  }
  std::ifstream file(path, std::ios::binary);
  unsigned char magic[4] = {};
  file.read(reinterpret_cast<char*>(magic), 4);
  if (!file || magic[0] != 0x76 || magic[1] != 0x2f || magic[2] != 0x31 || magic[3] != 0x01)
    return fmt::format("panorama {}: not an EXR file (an equirectangular OpenEXR panorama is needed)", value);
  return {};
}

void PictureCycle::reset(std::vector<std::filesystem::path> pictures, size_t start) {
  pictures_ = std::move(pictures);
  index_ = pictures_.empty() ? 0 : start % pictures_.size();
  problem_.clear();
}

bool PictureCycle::load(uint32_t maxSide, Picture& out) {
  for (size_t tried = 0; tried < pictures_.size(); ++tried) {
    try {
      out = readPicture(pictures_[index_], maxSide);
      return true;
    } catch (const Error& error) {
      problem_ = error.what();
      next();
    }
  }
  return false;
}

std::string PictureCycle::currentName() const {
  return pictures_.empty() ? std::string() : pictures_[index_].filename().string();
}

void bakeStudio(uint32_t width, uint32_t height, Panorama& out) {
  out.width = width;
  out.height = height;
  out.halves.resize(size_t(width) * height * 4);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const glm::vec3 c = studioRadiance(equirectDirection({(float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)}));
      uint16_t* texel = &out.halves[(size_t(y) * width + x) * 4];
      for (int k = 0; k < 3; ++k) texel[k] = half(c[k]).bits();
      texel[3] = half(1.0f).bits();
    }
}

std::vector<std::string> panoramaNames(const Assets& assets) {
  std::vector<std::string> names{std::string(kStudioPanorama)};
  for (const auto& path : assets.panoramas()) names.push_back(path.stem().string());
  return names;
}

bool loadPanorama(std::string_view nameOrPath, const Assets& assets, Panorama& out, std::string& problem) {
  if (nameOrPath == kStudioPanorama) {
    bakeStudio(kStudioWidth, kStudioWidth / 2, out);
    return true;
  }
  std::filesystem::path path;
  for (const auto& candidate : assets.panoramas())
    if (candidate.stem() == nameOrPath) path = candidate;
  if (path.empty()) {
    const auto file = assets.file(nameOrPath, "a procedural sky");
    if (!file) {
      problem = fmt::format("panorama {}: not a fetched panorama ({}) nor a readable file", nameOrPath,
                            fmt::join(panoramaNames(assets), ", "));
      return false;
    }
    path = *file;
  }
  try {
    const ImageRgba image = readImage(path);
    out.width = image.width;
    out.height = image.height;
    out.halves.resize(image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i)
      out.halves[i] = half(std::min(image.pixels[i], 60000.0f)).bits();  // the sun stays finite in half
    for (size_t i = 3; i < out.halves.size(); i += 4) out.halves[i] = half(1.0f).bits();
    return true;
  } catch (const Error& error) {
    problem = error.what();
    return false;
  }
}

}  // namespace vitrine::glass
