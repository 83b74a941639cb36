#pragma once
// The glass scene's shapes in plain C++: signed distances, front hits, analytic back exits and the rotations
// that animate them. shaders/glass/shapes.glsl mirrors it function for function (same names and arguments).
//
// Everything works in object space: the shape centred at the origin, in world units (the view is 1073 units
// tall). A shape's rotation R maps world to object, p_obj = R·(p_world - centre); the shader moves rays into
// object space once, so nothing here sees the rotation.
#include "shaders/glass/shape_dims.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>

namespace vitrine::glass {

enum class ShapeKind : int { Pill = 0, Prism = 1, Cube = 2, Plate = 3, Diamond = 4 };

// One shape's dimensions, as the shaders take them (shaders/glass/shape_dims.h); make them with the
// functions below, which leave the padding zero.
using ShapeDims = shader::GlassShapeDims;

// Pill: a rounded rectangle in XY (length along x, height along y, corners of radius min(edge, H/2): a stadium
// once edge reaches half the height), thickness along z. smooth: the rim is an L4 squircle (below).
inline ShapeDims pillDims(glm::vec3 size, float edge, bool smooth = false) {
  return {{size, edge}, {0.0f, 1.0f, 0.0f, smooth ? 1.0f : 0.0f}, int(ShapeKind::Pill)};
}
// Prism: length along x; an isosceles triangle in YZ, base width size.y at z = -size.z/2, apex at +size.z/2.
inline ShapeDims prismDims(glm::vec3 size) { return {{size, 0.0f}, {0.0f, 1.0f, 0.0f, 0.0f}, int(ShapeKind::Prism)}; }
inline ShapeDims cubeDims(float side, float edge, bool smooth = false) {
  return {{side, side, side, edge}, {0.0f, 1.0f, 0.0f, smooth ? 1.0f : 0.0f}, int(ShapeKind::Cube)};
}
// Plate: size.x × size.y, thickness size.z, riding the wave z = amplitude·sin(kx + phase)·sin(ky + phase).
inline ShapeDims plateDims(glm::vec3 size, float edge, float amplitude, float wavelength, float phase,
                           bool smooth = false) {
  return {{size, edge}, {amplitude, wavelength, phase, smooth ? 1.0f : 0.0f}, int(ShapeKind::Plate)};
}
inline ShapeDims diamondDims(float diameter) {
  return {{diameter, diameter, diameter, 0.0f}, {0.0f, 1.0f, 0.0f, 0.0f}, int(ShapeKind::Diamond)};
}

// The length tolerances scale with: the largest size.
inline float shapeScale(const ShapeDims& s) { return glm::max(s.sizeEdge.x, glm::max(s.sizeEdge.y, s.sizeEdge.z)); }

inline constexpr int kMarchSteps = 64;          // front sphere trace budget
inline constexpr float kHitTolerance = 1e-3f;   // front trace stops within this × scale of the surface
inline constexpr float kNormalStep = 1e-4f;     // central-difference step × scale (normals, Newton slopes)

// --- Distance functions for the smooth shapes.

// --- Smooth curvature: the rims of pill, cube and plate rounded in the L4 norm, a squircle section
// |x|^4 + |y|^4 = R^4 whose curvature grows from zero where it meets a face instead of jumping to 1/R as a
// circle's does. At the same radius a squircle cuts less off the corner (its 45-degree point lies at
// R / 2^(1/4) from the rounding's centre, a circle's at R / sqrt(2)), so the radius is compensated: R = k·edge
// with k = (1 - 2^(-1/2)) / (1 - 2^(-1/4)) ≈ 1.841 takes exactly as much off the corner's diagonal as a circle
// of the edge radius, and then is clamped to what the shape has room for. The L4 distance is a bound:
// |grad| = (|q|_6 / |q|_4)^3 <= 1, so sphere tracing stays safe.
inline constexpr float kSquircleCompensation = 1.8408964f;
// The rim's radius: the edge (compensated when smooth), at most `room`.
inline float rimRadius(float edge, float room, bool smooth) {
  return glm::min(smooth ? edge * kSquircleCompensation : edge, room);
}
inline float lengthL4(glm::vec2 v) {
  const glm::vec2 s = v * v;
  return std::sqrt(std::sqrt(glm::dot(s, s)));
}
inline float lengthL4(glm::vec3 v) {
  const glm::vec3 s = v * v;
  return std::sqrt(std::sqrt(glm::dot(s, s)));
}

// --- Distance functions for the smooth shapes.

// The exact signed distance to a rectangle of half size `half` with corners rounded by c <= min(half).
inline float sdRoundedRect(glm::vec2 p, glm::vec2 half, float c) {
  const glm::vec2 q = glm::abs(p) - (half - c);
  return glm::length(glm::max(q, 0.0f)) + glm::min(glm::max(q.x, q.y), 0.0f) - c;
}

// The pill: its outline a rounded rectangle (corner radius min(edge, H/2, L/2)), extruded through the
// thickness, the rim rounded by r = min(edge, T/2, H/2) (the preset's edge 100 with T = 62 clamps to 31, a
// half-round rim), or smooth: an L4 rim of the compensated radius, clamped the same way.
// Exact for the round rim; the L4 rim stays a bound.
inline float sdPill(glm::vec3 p, glm::vec3 size, float edge, bool smooth) {
  const glm::vec2 half{0.5f * size.x, 0.5f * size.y};
  const float corner = glm::min(edge, glm::min(half.x, half.y));
  const float r = rimRadius(edge, glm::min(0.5f * size.z, half.y), smooth);
  const float outline = sdRoundedRect({p.x, p.y}, half, corner);
  const glm::vec2 w{outline + r, std::fabs(p.z) - (0.5f * size.z - r)};
  const glm::vec2 out = glm::max(w, 0.0f);
  return glm::min(glm::max(w.x, w.y), 0.0f) + (smooth ? lengthL4(out) : glm::length(out)) - r;
}

// The exact distance to an isosceles triangle in YZ (half base b, height h, apex up), extruded along x.
inline float sdPrism(glm::vec3 p, glm::vec3 size) {
  const float b = 0.5f * size.y, h = size.z;
  const glm::vec2 q{std::fabs(p.y), p.z};
  const glm::vec2 corner{b, -0.5f * h}, slant{-b, h};  // from the base corner to the apex
  const glm::vec2 toBase = q - glm::vec2(glm::clamp(q.x, 0.0f, b), -0.5f * h);
  const glm::vec2 fromCorner = q - corner;
  const glm::vec2 toSlant =
      fromCorner - slant * glm::clamp(glm::dot(fromCorner, slant) / glm::dot(slant, slant), 0.0f, 1.0f);
  const bool inside = q.y > -0.5f * h && slant.x * fromCorner.y - slant.y * fromCorner.x > 0.0f;
  const float section =
      std::sqrt(glm::min(glm::dot(toBase, toBase), glm::dot(toSlant, toSlant))) * (inside ? -1.0f : 1.0f);
  const glm::vec2 w{section, std::fabs(p.x) - 0.5f * size.x};
  return glm::min(glm::max(w.x, w.y), 0.0f) + glm::length(glm::max(w, 0.0f));
}

// A box of half size `half` with edges rounded by r (r <= the smallest half size), in the L4 norm when smooth.
inline float sdRoundedBox(glm::vec3 p, glm::vec3 half, float r, bool smooth = false) {
  const glm::vec3 q = glm::abs(p) - (half - r);
  const glm::vec3 out = glm::max(q, 0.0f);
  return (smooth ? lengthL4(out) : glm::length(out)) + glm::min(glm::max(q.x, glm::max(q.y, q.z)), 0.0f) - r;
}
// The cube: rim radius min(edge, half side), compensated when smooth.
inline float sdCube(glm::vec3 p, glm::vec4 sizeEdge, bool smooth) {
  const glm::vec3 half = 0.5f * glm::vec3(sizeEdge);
  return sdRoundedBox(p, half, rimRadius(sizeEdge.w, glm::min(half.x, glm::min(half.y, half.z)), smooth), smooth);
}

// The plate's mid-surface h(x, y) and its gradient.
inline float plateHeight(glm::vec2 xy, glm::vec4 wave) {
  const float k = glm::two_pi<float>() / wave.y;
  return wave.x * std::sin(k * xy.x + wave.z) * std::sin(k * xy.y + wave.z);
}
inline glm::vec2 plateSlope(glm::vec2 xy, glm::vec4 wave) {
  const float k = glm::two_pi<float>() / wave.y;
  const float sx = std::sin(k * xy.x + wave.z), sy = std::sin(k * xy.y + wave.z);
  return wave.x * k * glm::vec2(std::cos(k * xy.x + wave.z) * sy, sx * std::cos(k * xy.y + wave.z));
}

// The plate is a rounded box in sheared coordinates q = (x, y, z - h(x, y)), so both faces ride the
// mid-surface and the thickness along z stays uniform. The shear stretches distances by up to its Jacobian's
// largest singular value; with s = A·k >= |grad h| that is sqrt(1 + s²/2 + s·sqrt(1 + s²/4)), and dividing by
// it keeps the field a Lipschitz-1 bound (1.105 at the preset's slope 0.2: steps 10 % short). Dividing only the
// z term by sqrt(1 + |grad h|²), the heightfield estimate, varies with x and y and so proves no bound.
inline float plateLipschitz(glm::vec4 wave) {
  const float s = std::fabs(wave.x) * glm::two_pi<float>() / wave.y;
  return std::sqrt(1.0f + 0.5f * s * s + s * std::sqrt(1.0f + 0.25f * s * s));
}
inline float sdPlate(glm::vec3 p, glm::vec4 sizeEdge, glm::vec4 wave) {
  const glm::vec3 half = 0.5f * glm::vec3(sizeEdge);
  const bool smooth = wave.w > 0.5f;
  const float r = rimRadius(sizeEdge.w, glm::min(half.z, glm::min(half.x, half.y)), smooth);
  const glm::vec3 q{p.x, p.y, p.z - plateHeight({p.x, p.y}, wave)};
  return sdRoundedBox(q, half, r, smooth) / plateLipschitz(wave);
}

// --- Dispatch over the kinds (shapes.cpp). The diamond's planes come from makeDiamond(size.x), cached.

float shapeSdf(const ShapeDims& s, glm::vec3 p);
// Outward unit normal: central differences (step kNormalStep × scale); the diamond's exact facet normal.
glm::vec3 shapeNormal(const ShapeDims& s, glm::vec3 p);
// Half size of the object-space box around the shape (the plate's includes the wave amplitude): the proxy box.
glm::vec3 shapeHalfExtent(const ShapeDims& s);

// Front hit of a ray from outside (rd a unit vector). Pill, prism, cube, plate: sphere tracing from where the
// ray enters the bounding box, at most kMarchSteps steps, a hit once within kHitTolerance × scale. Diamond:
// analytic. facet: the diamond's entry facet (0-56 planes, 57 the girdle), -1 for the other shapes.
bool shapeEnter(const ShapeDims& s, glm::vec3 ro, glm::vec3 rd, float& t, glm::vec3& n, int& facet);

// Back exit from a point p inside along the unit direction d; n is the outward unit normal there. Analytic for
// every shape: the exit from a sharp shape holding this one, then Newton steps on the distance along the ray
// (4 for the pill and the cube, 2 for the plate's rim) to land on the rounded surface. The prism is exact
// (five planes), the plate's wavy faces use 3 Newton iterations after a tangent-plane seed, the diamond is
// a ray-polytope exit. facet as for shapeEnter.
bool shapeExit(const ShapeDims& s, glm::vec3 p, glm::vec3 d, float& t, glm::vec3& n, int& facet);

// --- Rotations (world to object) and the plate's wave phase, as functions of time in seconds.

inline constexpr float kCubeSpinZ = 0.31f;  // rad/s
inline constexpr float kCubeSpinX = 0.47f;
inline constexpr glm::vec2 kPlateWobbleAmplitude{0.35f, 0.28f};  // rad, about x and about y
inline constexpr glm::vec2 kPlateWobbleRate{0.45f, 0.33f};       // rad/s
inline constexpr float kPlateWaveRate = 0.9f;                    // rad/s of phase
inline constexpr float kDiamondSpin = 0.25f;                     // fixed views turn about the stone's axis
inline constexpr glm::vec2 kDiamondTumble{0.41f, 0.29f};         // free view: about x, then about y
inline constexpr float kDiamondTilt = 0.6f;                      // free view's tilt at t = 0

// Right-handed rotations by angle a about each axis (column-major, as GLSL's mat3).
inline glm::mat3 rotationX(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {1.0f, 0.0f, 0.0f, 0.0f, c, s, 0.0f, -s, c};
}
inline glm::mat3 rotationY(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {c, 0.0f, -s, 0.0f, 1.0f, 0.0f, s, 0.0f, c};
}
inline glm::mat3 rotationZ(float a) {
  const float c = std::cos(a), s = std::sin(a);
  return {c, s, 0.0f, -s, c, 0.0f, 0.0f, 0.0f, 1.0f};
}

inline glm::mat3 cubeRotation(float t) { return rotationZ(kCubeSpinZ * t) * rotationX(kCubeSpinX * t); }
inline glm::mat3 plateRotation(float t) {
  return rotationX(kPlateWobbleAmplitude.x * std::sin(kPlateWobbleRate.x * t)) *
         rotationY(kPlateWobbleAmplitude.y * std::sin(kPlateWobbleRate.y * t + 1.0f));
}
inline float plateWavePhase(float t) { return kPlateWaveRate * t; }

// Top: the table faces the camera (+z). Side: the table points up (+y), the girdle in profile. Bottom: the
// culet faces the camera. The fixed views turn slowly about the stone's axis so facets catch the light; pass
// t = 0 for a still stone. Free: a slow tumble about x and y.
enum class DiamondView : int { Top = 0, Side = 1, Bottom = 2, Free = 3 };
inline glm::mat3 diamondRotation(DiamondView view, float t) {
  const glm::mat3 spin = rotationZ(kDiamondSpin * t);  // about the object's axis: applied after the view turn
  switch (view) {
    case DiamondView::Top: return spin;
    case DiamondView::Side: return spin * rotationX(glm::half_pi<float>());
    case DiamondView::Bottom: return spin * rotationX(glm::pi<float>());
    case DiamondView::Free: break;
  }
  return rotationX(kDiamondTilt + kDiamondTumble.x * t) * rotationY(kDiamondTumble.y * t);
}

}  // namespace vitrine::glass
