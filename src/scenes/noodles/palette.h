#pragma once
// Strand colours from the strand's index, linear RGB. Mirrored by shaders/noodles/palette.glsl.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace vitrine::noodles {

enum class Colouring : uint32_t { Gradient, Hsv, Grey };

inline constexpr glm::vec3 kGradientFirst{0.06f, 0.16f, 0.55f};  // deep blue
inline constexpr glm::vec3 kGradientLast{1.0f, 0.62f, 0.30f};    // warm sand
// The write-up's grey ramp runs from black to white by index; it starts at this grey instead, since a
// black strand would vanish into the near-black background.
inline constexpr float kGreyFirst = 0.12f;

// Fully saturated hue h in [0, 1), then pulled towards white by (1 - saturation), times value.
inline glm::vec3 hsvToRgb(glm::vec3 hsv) {
  const glm::vec3 phase = glm::fract(glm::vec3(hsv.x) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f;
  const glm::vec3 hue = glm::clamp(glm::abs(phase) - 1.0f, 0.0f, 1.0f);
  return hsv.z * glm::mix(glm::vec3(1.0f), hue, hsv.y);
}

inline glm::vec3 strandColour(uint32_t strand, uint32_t strands, Colouring colouring) {
  const float t = strands > 1 ? float(strand) / float(strands - 1) : 0.0f;
  if (colouring == Colouring::Hsv) return hsvToRgb({t * 0.9f, 0.4f, 1.0f});  // the write-up's pastel wheel
  if (colouring == Colouring::Grey) return glm::vec3(glm::mix(kGreyFirst, 1.0f, t));
  return glm::mix(kGradientFirst, kGradientLast, t);
}

}  // namespace vitrine::noodles
