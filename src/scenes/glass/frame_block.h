#pragma once
// The glass scene's per-frame uniform block; mirrors shaders/glass/frame.glsl (std140, vec4-packed).
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstddef>

namespace vitrine::glass {

inline constexpr int kMaxInstances = 4;

struct FrameBlock {
  glm::mat4 viewProjection;       // world -> clip
  glm::vec4 camera;               // xyz: the eye (perspective); w: 1 orthographic
  glm::vec4 view;                 // world units across and down the view, pixels across and down
  glm::vec4 glass;                // n_d, V_d, strength, photo depth
  glm::ivec4 spectral;            // N, mode (0 exact, 1 approx), jitter, optics (0 seed, 1 physical)
  glm::vec4 spectralExtra;        // hero wavelength, frame phase, sellmeier on, 0
  glm::vec4 sellmeierB;           // xyz
  glm::vec4 sellmeierC;           // xyz, µm^2
  glm::ivec4 shape;               // kind, instances, bounces, diamond debug
  glm::ivec4 frameInfo;           // frame, seed, aa (0 none, 1 fxaa, 2 taa), environment on
  glm::vec4 environment;          // exposure, rotation, backdrop mip count, show proxy
  glm::vec4 shapeSize;            // xyz size, edge
  glm::vec4 shapeWave;            // amplitude, wavelength, phase, squircle
  glm::vec4 taa;                  // sub-pixel jitter xy (pixels), 0, 0
  glm::mat4 rotation;             // world -> object, in the upper 3x3
  glm::mat4 previousRotation;
  glm::vec4 centres[kMaxInstances];  // xy: this frame's centre, zw: last frame's (world units)
  glm::vec4 rects[kMaxInstances];    // each instance's pixels on screen: x0, y0, x1, y1
};
static_assert(offsetof(FrameBlock, camera) == 64 && offsetof(FrameBlock, rotation) == 272 &&
              offsetof(FrameBlock, centres) == 400 && sizeof(FrameBlock) == 528);

}  // namespace vitrine::glass
