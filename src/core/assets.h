#pragma once
// Where the fetched, optional assets are (scripts/setup puts them in assets/cache/), and which ones
// are missing. Nothing here is required: every user has a built-in fallback and names what it lacks.
#include <filesystem>
#include <array>
#include <span>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {

// The picture files a folder of backgrounds is searched for (lower case).
inline constexpr std::array<std::string_view, 8> kPictureExtensions = {".jpg", ".jpeg", ".png", ".webp",
                                                                       ".tif", ".tiff", ".bmp", ".exr"};

// Regular files in `folder` with one of `extensions` (compared in lower case), sorted by name; none when
// the folder cannot be read.
std::vector<std::filesystem::path> filesIn(const std::filesystem::path& folder,
                                           std::span<const std::string_view> extensions);

class Assets {
 public:
  // VITRINE_ASSETS overrides the folder; otherwise an installed binary's ../share/vitrine, else the checkout's assets/cache.
  static Assets locate();
  explicit Assets(std::filesystem::path root);

  const std::filesystem::path& root() const { return root_; }
  std::optional<std::filesystem::path> font(const std::string& family) const;  // "Fraunces", "CormorantSC"
  std::vector<std::filesystem::path> panoramas() const;                       // HDR environment maps
  std::vector<std::filesystem::path> photos() const;                          // pictures for backgrounds
  // A file a user named (a panorama or font given on the command line or in a parameter), relative
  // paths from the working directory: the path when it is a readable regular file; otherwise none, and
  // "PATH: WHY; using FALLBACK" joins missing() and is printed once, so the gallery shows it too.
  std::optional<std::filesystem::path> file(const std::filesystem::path& path, std::string_view fallback) const;
  // Scenes report an asset they could not use the same way (a font FreeType could not read, say).
  void reportMissing(std::string line) const;
  // One line per expected asset that is absent, saying what replaces it, then what was reported.
  std::vector<std::string> missing() const;

 private:
  std::filesystem::path root_;
  mutable std::vector<std::string> reported_;  // a cache of what was found wanting, not state of the assets
};

}  // namespace vitrine
