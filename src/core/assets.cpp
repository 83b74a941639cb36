#include "core/assets.h"

#include "core/bounded_file.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace vitrine {

// A panorama or a photo the gallery shows, as large as image_io's kMaxPictureFileBytes.
constexpr uintmax_t kMaxAssetFileBytes = uintmax_t(1) << 30;

Assets Assets::locate() {
  if (const char* env = std::getenv("VITRINE_ASSETS"); env && *env) return Assets(env);
  // An installed binary (/usr/bin/vitrine, /usr/local/bin/vitrine) finds its data in ../share/vitrine,
  // wherever the prefix is; a build in a checkout has no such folder and reads the checkout's cache.
  std::error_code ec;
  const auto installed = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path().parent_path() / "share" / "vitrine";
  if (!ec && std::filesystem::is_directory(installed, ec)) return Assets(installed);
  return Assets(std::filesystem::path(VITRINE_ASSET_DIR) / "cache");
}

Assets::Assets(std::filesystem::path root) : root_(std::move(root)) {}

std::optional<std::filesystem::path> Assets::font(const std::string& family) const {
  const auto path = root_ / "fonts" / (family + ".woff2");
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) > 0) return path;
  return std::nullopt;
}

std::vector<std::filesystem::path> filesIn(const std::filesystem::path& folder,
                                           std::span<const std::string_view> extensions) {
  std::vector<std::filesystem::path> found;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(folder, ec); !ec && it != std::filesystem::directory_iterator();
       it.increment(ec)) {
    std::string extension = it->path().extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (std::find(extensions.begin(), extensions.end(), extension) != extensions.end() && it->is_regular_file(ec))
      found.push_back(it->path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<std::filesystem::path> Assets::panoramas() const {
  constexpr std::array<std::string_view, 1> kExr{".exr"};
  return filesIn(root_ / "hdri", kExr);
}

std::vector<std::filesystem::path> Assets::photos() const { return filesIn(root_ / "photos", kPictureExtensions); }

std::optional<std::filesystem::path> Assets::file(const std::filesystem::path& path, std::string_view fallback) const {
  std::string why;
  try {
    checkBoundedFile(path, kMaxAssetFileBytes);
  } catch (const FileRefused& refused) {
    why = refused.why == "it does not exist" ? "not found" : refused.why;
  }
  if (why.empty()) return path;
  reportMissing(path.string() + ": " + why + "; using " + std::string(fallback));
  return std::nullopt;
}

void Assets::reportMissing(std::string line) const {
  if (std::find(reported_.begin(), reported_.end(), line) != reported_.end()) return;
  std::fprintf(stderr, "vitrine: missing asset: %s\n", line.c_str());
  reported_.push_back(std::move(line));
}

std::vector<std::string> Assets::missing() const {
  std::vector<std::string> lines;
  for (const char* family : {"Fraunces", "FrauncesItalic", "CormorantSC"})
    if (!font(family))
      lines.push_back(std::string("font ") + family + " (" + (root_ / "fonts").string() +
                      "): using a built-in face instead; run scripts/setup to fetch it");
  if (photos().empty())
    lines.push_back("photos (" + (root_ / "photos").string() +
                    "): glass refracts a procedural gradient; run scripts/setup to fetch mate-backgrounds'");
  if (panoramas().empty())
    lines.push_back("HDR panoramas (" + (root_ / "hdri").string() +
                    "): scenes use a procedural sky; run scripts/setup to fetch blender-data's");
  lines.insert(lines.end(), reported_.begin(), reported_.end());
  return lines;
}

}  // namespace vitrine
