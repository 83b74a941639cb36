#pragma once
// What the tube rasteriser's passes are told about a frame: the camera as rays (capsule.h's
// ScreenView), the tube radius and the look, and how that fills their shaders' push block
// (shaders/noodles/raster_blocks.h).
#include "scenes/noodles/camera.h"
#include "scenes/noodles/capsule.h"
#include "scenes/noodles/palette.h"
#include "scenes/noodles/strand_layout.h"
#include "shaders/noodles/raster_blocks.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vitrine::noodles {

inline constexpr glm::vec3 kBackground{0.01f, 0.01f, 0.014f};  // the write-up's clear colour, linear

struct TubeView {
  ScreenView screen;
  float radius = 0.02f;
  Colouring colouring = Colouring::Gradient;
  bool stripe = false;
  bool multisample = true;  // four samples a pixel, averaged; else one at its centre
  bool occluders = true;    // big nests: occluders first, then the rest against a bound a tile (raster_pass.h)
};

// The camera of reverseZPerspective(kFieldOfViewY, ..., kNearPlane) * lookAtZUp(pose) as rays.
inline ScreenView screenViewOf(const CameraPose& pose, glm::vec2 pixels) {
  ScreenView view;
  view.eye = pose.eye;
  view.forward = glm::normalize(pose.target - pose.eye);
  view.right = glm::normalize(glm::cross(view.forward, glm::vec3(0.0f, 0.0f, 1.0f)));
  view.up = glm::cross(view.right, view.forward);
  view.tanHalfY = std::tan(kFieldOfViewY * 0.5f);
  view.tanHalfX = view.tanHalfY * pixels.x / std::max(pixels.y, 1.0f);
  view.nearPlane = kNearPlane;
  view.pixels = pixels;
  return view;
}

// The push block's per-frame part; the passes fill in the rest (the big list, the chunk).
inline shader::NoodlesRasterPush rasterPush(const TubeView& view, const StrandLayout& layout) {
  const ScreenView& s = view.screen;
  return {.eye = s.eye,
          .tubeRadius = view.radius,
          .right = s.right,
          .tanHalfX = s.tanHalfX,
          .up = s.up,
          .tanHalfY = s.tanHalfY,
          .forward = s.forward,
          .nearPlane = s.nearPlane,
          .pixels = s.pixels,
          .segmentsPerStrand = layout.segments,
          .totalStrands = layout.strands,
          .colouring = uint32_t(view.colouring),
          .stripe = view.stripe ? 1u : 0u};
}

}  // namespace vitrine::noodles
