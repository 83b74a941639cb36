#include "maths/output_warp.h"

#include <fmt/format.h>
#include <glm/matrix.hpp>

#include <cmath>

namespace vitrine::maths {
namespace {

// A 3x3 matrix written as its rows, as the maths is written.
glm::mat3 rows(glm::vec3 r0, glm::vec3 r1, glm::vec3 r2) { return glm::transpose(glm::mat3(r0, r1, r2)); }

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

}  // namespace

std::string checkWarp(const OutputWarp& warp) {
  const glm::vec4& r = warp.region;
  if (!(r.x >= 0.0f && r.y >= 0.0f && r.z <= 1.0f && r.w <= 1.0f && r.x < r.z && r.y < r.w))
    return fmt::format("the region {} {} {} {} is not a part of the frame (left < right and top < bottom, all 0..1)",
                       r.x, r.y, r.z, r.w);
  if (warp.quarterTurns < 0 || warp.quarterTurns > 3) return "the turn is 0, 90, 180 or 270 degrees";
  // In order round the picture, every corner turns the same way: a convex quadrilateral, not crossed.
  float sign = 0.0f;
  for (size_t i = 0; i < 4; ++i) {
    const glm::vec2 a = warp.corners[i], b = warp.corners[(i + 1) % 4], c = warp.corners[(i + 2) % 4];
    if (!std::isfinite(a.x) || !std::isfinite(a.y)) return "a corner is not a number";
    const float turn = cross(b - a, c - b);
    if (std::abs(turn) < 1e-6f || (sign != 0.0f && turn * sign < 0.0f))
      return "the four corners, in order top-left, top-right, bottom-right, bottom-left, must make a convex shape";
    sign = turn;
  }
  const EdgeBlend& b = warp.blend;
  for (float width : {b.left, b.top, b.right, b.bottom})
    if (!(width >= 0.0f && width <= 0.5f)) return "an edge blend is 0 to 0.5 of the picture";
  if (!(b.curve >= 1.0f && b.curve <= 8.0f)) return "the blend curve is 1 to 8";
  if (!(b.gamma >= 1.0f && b.gamma <= 3.0f)) return "the blend gamma is 1 to 3";
  return {};
}

// Heckbert's square-to-quadrilateral mapping: x = (a u + b v + c) / (g u + h v + 1), y likewise.
glm::mat3 pinMatrix(const std::array<glm::vec2, 4>& q) {
  const glm::vec2 d1 = q[1] - q[2], d2 = q[3] - q[2], d3 = q[0] - q[1] + q[2] - q[3];
  const float det = cross(d1, d2);
  const float g = det != 0.0f ? cross(d3, d2) / det : 0.0f;
  const float h = det != 0.0f ? cross(d1, d3) / det : 0.0f;
  return rows({q[1].x - q[0].x + g * q[1].x, q[3].x - q[0].x + h * q[3].x, q[0].x},
              {q[1].y - q[0].y + g * q[1].y, q[3].y - q[0].y + h * q[3].y, q[0].y}, {g, h, 1.0f});
}

WarpMatrices warpMatrices(const OutputWarp& warp) {
  // Backwards from the picture to the frame: undo the mirror, then the turn, then pick the region.
  const glm::mat3 mirror = warp.mirror ? rows({-1, 0, 1}, {0, 1, 0}, {0, 0, 1}) : glm::mat3(1.0f);
  const glm::mat3 quarter = rows({0, 1, 0}, {-1, 0, 1}, {0, 0, 1});  // a clockwise turn, undone: (x, y) -> (y, 1 - x)
  glm::mat3 turn(1.0f);
  for (int i = 0; i < warp.quarterTurns; ++i) turn = quarter * turn;
  const glm::vec4& r = warp.region;
  const glm::mat3 region = rows({r.z - r.x, 0, r.x}, {0, r.w - r.y, r.y}, {0, 0, 1});
  const glm::mat3 toSource = glm::transpose(region * turn * mirror);  // its rows, as columns
  return {glm::inverse(pinMatrix(warp.corners)), toSource[0], toSource[1]};
}

}  // namespace vitrine::maths
