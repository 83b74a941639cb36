#include "scenes/glass/backgrounds.h"

#include "core/error.h"

#include <Imath/half.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

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
  if (!source.pictures.empty() && !canReadPictures()) {
    source.problem = fmt::format("{}: this build reads no pictures (VITRINE_WITH_OIIO=OFF)", value);
    source.pictures.clear();
  }
  if (!source.problem.empty()) source.kind = BackdropKind::Gradient;
  return source;
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

std::vector<std::string> panoramaNames(const Assets& assets) {
  std::vector<std::string> names;
  for (const auto& path : assets.panoramas()) names.push_back(path.stem().string());
  return names;
}

bool loadPanorama(std::string_view nameOrPath, const Assets& assets, Panorama& out, std::string& problem) {
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
