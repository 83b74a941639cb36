#pragma once
// How one output (a window, a projector) shows the rendered frame, in plain C++ that
// shaders/host/present.comp mirrors: the region of the frame it shows (one half each for a projector
// pair), turned by a quarter turn or two and mirrored (a projector hung upside down, a rear-projection
// screen), pinned so the picture's four corners land where the operator dragged them (keystone on a
// wall the projector does not face square-on), with its edges faded where it overlaps a neighbour's.
//
// Coordinates are 0..1 across the output (x right, y down, as on the screen). The present pass runs
// backwards, from each output pixel to what it shows: unpin() takes the pixel into the picture's own
// square (nothing outside it: black), edgeWeight() fades it, toSource() finds the frame's texel.
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <optional>
#include <string>

namespace vitrine::maths {

// Soft edge blending for overlapping projectors (after Paul Bourke's projector blending): over `width`
// of the picture at an edge (0: none), the light falls to zero along a curve of exponent `curve` (1:
// linear; 2, the default, meets its neighbour's in an S), corrected for the projector's `gamma`, so that
// two overlapping ramps sum to even light on the wall.
struct EdgeBlend {
  float left = 0.0f, top = 0.0f, right = 0.0f, bottom = 0.0f;  // fractions of the picture, 0..0.5
  float curve = 2.0f;                                           // 1..8
  float gamma = 2.2f;                                           // 1..3
  bool operator==(const EdgeBlend&) const = default;
};

struct OutputWarp {
  glm::vec4 region{0.0f, 0.0f, 1.0f, 1.0f};  // the frame's part shown: left, top, right, bottom, 0..1
  int quarterTurns = 0;                      // 0..3: the picture turned clockwise by 90° each
  bool mirror = false;                       // flipped left to right (after the turn)
  // Where the picture's top-left, top-right, bottom-right and bottom-left corners land on the output.
  std::array<glm::vec2, 4> corners{glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(1.0f, 1.0f),
                                   glm::vec2(0.0f, 1.0f)};
  EdgeBlend blend;
  bool operator==(const OutputWarp&) const = default;
  // Shows the whole frame square-on with no blending: the present pass's plain path, bit for bit.
  bool isIdentity() const { return *this == OutputWarp{}; }
};

// "" when the warp can be shown; else why not: corners that do not make a convex quadrilateral in
// order (crossed, or three in a line), a region of no area or outside 0..1, blend widths past half.
std::string checkWarp(const OutputWarp& warp);

// The projective map from the picture's square (0..1) onto the pinned quadrilateral: the unit square's
// corners go to warp.corners in order (a homography; glm's column-major mat3, applied to (x, y, 1)).
glm::mat3 pinMatrix(const std::array<glm::vec2, 4>& corners);

// What the present pass is given: the inverse of pinMatrix, and the affine map from the picture's square
// to the frame (the turn, the mirror and the region), as the two rows of a 2x3 matrix.
struct WarpMatrices {
  glm::mat3 unpin{1.0f};
  glm::vec3 sourceU{1.0f, 0.0f, 0.0f}, sourceV{0.0f, 1.0f, 0.0f};
};
WarpMatrices warpMatrices(const OutputWarp& warp);

// An output position in the picture's square, or nothing where the pinned picture does not reach.
inline std::optional<glm::vec2> unpin(const WarpMatrices& m, glm::vec2 output) {
  const glm::vec3 q = m.unpin * glm::vec3(output, 1.0f);
  if (!(q.z > 0.0f)) return std::nullopt;
  const glm::vec2 p(q.x / q.z, q.y / q.z);
  if (p.x < 0.0f || p.y < 0.0f || p.x > 1.0f || p.y > 1.0f) return std::nullopt;
  return p;
}

// The frame position (0..1) a point of the picture's square shows.
inline glm::vec2 toSource(const WarpMatrices& m, glm::vec2 picture) {
  const glm::vec3 p(picture, 1.0f);
  return {glm::dot(m.sourceU, p), glm::dot(m.sourceV, p)};
}

// One edge's ramp at distance `d` from it, over `width`: 0 at the edge, 1 from `width` in.
inline float edgeRamp(float d, float width, float curve, float gamma) {
  if (!(width > 0.0f)) return 1.0f;
  const float x = glm::clamp(d / width, 0.0f, 1.0f);
  const float s = x < 0.5f ? 0.5f * glm::pow(2.0f * x, curve) : 1.0f - 0.5f * glm::pow(2.0f * (1.0f - x), curve);
  return glm::pow(s, 1.0f / gamma);
}

// The light a point of the picture's square keeps: the product of the four edges' ramps.
inline float edgeWeight(const EdgeBlend& b, glm::vec2 picture) {
  return edgeRamp(picture.x, b.left, b.curve, b.gamma) * edgeRamp(1.0f - picture.x, b.right, b.curve, b.gamma) *
         edgeRamp(picture.y, b.top, b.curve, b.gamma) * edgeRamp(1.0f - picture.y, b.bottom, b.curve, b.gamma);
}

}  // namespace vitrine::maths
