#pragma once
// What the glass refracts, on the CPU side: the `background` parameter's value read as a built-in
// source or as a file or folder of pictures, the folder cycled by R, and the pictures and panoramas
// loaded into texels the scene uploads. Nothing here touches the GPU.
#include "core/assets.h"
#include "image/image_io.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::glass {

enum class BackdropKind {
  Page,      // the scene's own page of text over a photo (the original refracts its README)
  Photo,     // a picture: the fetched photos, a file, or a folder cycled by R
  Gradient,  // procedural fallbacks, always there
  Checker,
};

// The `background` value, resolved: which kind, and for pictures the files to cycle through.
struct BackdropSource {
  BackdropKind kind = BackdropKind::Gradient;
  std::vector<std::filesystem::path> pictures;  // Page and Photo: empty means "use the gradient"
  std::string problem;                          // why a named file or folder could not serve, for the panel
};

// "page", "photo", "gradient", "checker", or a path to an image file or a folder of them.
BackdropSource resolveBackdrop(std::string_view value, const Assets& assets);

// Why `value` cannot serve as the background ("" when it can), naming the value: not one of the keywords
// nor an existing picture file or a folder holding pictures (a misspelt "chcker", "/nonexistent.png"),
// not a regular file ("/dev/zero"), a file the image library cannot read, or any file in a build that
// reads no pictures (VITRINE_WITH_OIIO=OFF). Reads a named file to know (the scene keeps the answer).
std::string backgroundProblem(std::string_view value, const Assets& assets);
// Why `value` cannot serve as the panorama ("" when it can): the built-in studio, a fetched name, or a
// regular file that starts like an EXR.
std::string panoramaProblem(std::string_view value, const Assets& assets);

// The picture a backdrop shows now, cycling with next(); a picture that cannot be read is skipped and
// its reason kept (problem()).
class PictureCycle {
 public:
  void reset(std::vector<std::filesystem::path> pictures, size_t start = 0);
  // Reads the current picture, or the next readable one; false when none is readable.
  bool load(uint32_t maxSide, Picture& out);
  void next() { if (!pictures_.empty()) index_ = (index_ + 1) % pictures_.size(); }
  const std::string& problem() const { return problem_; }
  std::string currentName() const;

 private:
  std::vector<std::filesystem::path> pictures_;
  size_t index_ = 0;
  std::string problem_;
};

// Equirectangular HDR panorama as half-float RGBA texels, from a fetched panorama's name ("studio") or an
// EXR path; none (and `problem` says why) when neither serves.
struct Panorama {
  uint32_t width = 0, height = 0;
  std::vector<uint16_t> halves;  // width * height * 4
};
// "photo_studio" is the built-in studio (studio.h), baked at kStudioWidth x kStudioWidth/2.
bool loadPanorama(std::string_view nameOrPath, const Assets& assets, Panorama& out, std::string& problem);
inline constexpr uint32_t kStudioWidth = 2048;  // 0.18 degrees a texel: the strip lights' 3.4 degrees are 19 texels
void bakeStudio(uint32_t width, uint32_t height, Panorama& out);
// The built-in studio's name, then the fetched panoramas', for the panel's help.
std::vector<std::string> panoramaNames(const Assets& assets);

}  // namespace vitrine::glass
