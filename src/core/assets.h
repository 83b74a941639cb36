#pragma once
// Where the fetched, optional assets are (scripts/setup puts them in assets/cache/), and which ones
// are missing. Nothing here is required: every user has a built-in fallback and names what it lacks.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vitrine {

class Assets {
 public:
  // VITRINE_ASSETS overrides the folder; otherwise the checkout's assets/cache.
  static Assets locate();
  explicit Assets(std::filesystem::path root);

  const std::filesystem::path& root() const { return root_; }
  std::optional<std::filesystem::path> font(const std::string& family) const;  // "Fraunces", "CormorantSC"
  std::vector<std::filesystem::path> panoramas() const;                       // HDR environment maps
  // One line per expected asset that is absent, saying what replaces it.
  std::vector<std::string> missing() const;

 private:
  std::filesystem::path root_;
};

}  // namespace vitrine
