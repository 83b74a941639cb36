#pragma once
// Light signals: what a scene's picture and story give the room's lights (docs/LIGHTS.md). Each is a
// name and one or more colours, linear RGB 0..1 (a brightness is a grey): `regions` (the frame's mean
// colour over a grid the patch chooses, row after row), `dominant` (its dominant colours, most of the
// frame first), and the scenes' own (`bloom.phase`, `neon.tubes`). A patch's fixtures read them by name.
#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::lights {

// Every name a patch may read; a scene that does not publish one leaves its fixtures dark.
inline constexpr std::array<std::string_view, 7> kSignalNames{
    "regions", "dominant", "bloom.phase", "bloom.chamber", "bloom.climax", "neon.tubes", "neon.glow"};

inline constexpr size_t kDominantColours = 4;  // the k of `dominant`'s k-means
inline constexpr size_t kMaxSignalColours = 2048;

class Signals {
 public:
  void set(std::string_view name, std::vector<glm::vec3> colours);
  void set(std::string_view name, float brightness) { set(name, std::vector<glm::vec3>{glm::vec3(brightness)}); }
  // Null when nobody published `name` this frame.
  const std::vector<glm::vec3>* find(std::string_view name) const;
  const std::map<std::string, std::vector<glm::vec3>, std::less<>>& all() const { return colours_; }
  bool operator==(const Signals&) const = default;

 private:
  std::map<std::string, std::vector<glm::vec3>, std::less<>> colours_;
};

}  // namespace vitrine::lights
