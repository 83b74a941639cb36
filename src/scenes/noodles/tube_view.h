#pragma once
// What the tube rasteriser's passes are told about a frame: the camera as rays (capsule.h's
// ScreenView), the tube radius and the look, and the push block of their shaders.
#include "scenes/noodles/camera.h"
#include "scenes/noodles/capsule.h"
#include "scenes/noodles/palette.h"
#include "scenes/noodles/strand_layout.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace vitrine::noodles {

inline constexpr glm::vec3 kBackground{0.01f, 0.01f, 0.014f};  // the write-up's clear colour, linear

struct TubeView {
  ScreenView screen;
  float radius = 0.02f;
  Colouring colouring = Colouring::Gradient;
  bool stripe = false;
  bool multisample = true;  // four samples a pixel, averaged; else one at its centre
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

// Mirrors shaders/noodles/raster_push.glsl (std430: each vec3 shares its 16-byte slot with a float).
struct RasterPush {
  glm::vec3 eye;
  float radius;
  glm::vec3 right;
  float tanHalfX;
  glm::vec3 up;
  float tanHalfY;
  glm::vec3 forward;
  float nearPlane;
  glm::vec2 pixels;
  uint32_t samplesPerAxis;
  uint32_t segments;
  uint32_t strands;
  uint32_t colouring;
  uint32_t stripe;
  uint32_t bigCapacity;
  uint32_t firstStrand;
  uint32_t chunkStrands;
  uint32_t invocationsPerRow;
  uint32_t accumulate;
};
static_assert(offsetof(RasterPush, right) == 16 && offsetof(RasterPush, pixels) == 64 &&
              offsetof(RasterPush, firstStrand) == 96 && sizeof(RasterPush) == 112);

// The push block's per-frame part; the passes fill in the per-chunk fields.
inline RasterPush rasterPush(const TubeView& view, const StrandLayout& layout, uint32_t samplesPerAxis) {
  const ScreenView& s = view.screen;
  return {s.eye,
          view.radius,
          s.right,
          s.tanHalfX,
          s.up,
          s.tanHalfY,
          s.forward,
          s.nearPlane,
          s.pixels,
          samplesPerAxis,
          layout.segments,
          layout.strands,
          uint32_t(view.colouring),
          view.stripe ? 1u : 0u,
          0,
          0,
          0,
          0,
          0};
}

}  // namespace vitrine::noodles
