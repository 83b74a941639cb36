#pragma once
// The glass scene's shapes in plain C++: signed distances, front hits, analytic back exits and the rotations
// that animate them. shaders/glass/shapes.glsl mirrors it function for function (same names and arguments).
//
// Everything works in object space: the shape centred at the origin, in world units (the view is 1073 units
// tall). A shape's rotation R maps world to object, p_obj = R·(p_world - centre); the shader moves rays into
// object space once, so nothing here sees the rotation.
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

// One shape's dimensions, laid out for std140 and std430 alike (48 bytes; GLSL struct ShapeDims).
struct ShapeDims {
  glm::vec4 sizeEdge{};  // xyz: the size along x, y, z; w: the edge rounding radius (pill, cube, plate)
  glm::vec4 wave{};      // plate: amplitude, wavelength, phase (radians); w: 1 gives the pill a squircle rim
  int kind = 0;          // a ShapeKind
  int pad[3] = {};
};
static_assert(sizeof(ShapeDims) == 48 && offsetof(ShapeDims, wave) == 16 && offsetof(ShapeDims, kind) == 32);

// Pill: a stadium in XY (length along x >= height along y, round ends of radius height/2), thickness along z.
inline ShapeDims pillDims(glm::vec3 size, float edge, bool squircle = false) {
  return {{size, edge}, {0.0f, 1.0f, 0.0f, squircle ? 1.0f : 0.0f}, int(ShapeKind::Pill)};
}
// Prism: length along x; an isosceles triangle in YZ, base width size.y at z = -size.z/2, apex at +size.z/2.
inline ShapeDims prismDims(glm::vec3 size) { return {{size, 0.0f}, {0.0f, 1.0f, 0.0f, 0.0f}, int(ShapeKind::Prism)}; }
inline ShapeDims cubeDims(float side, float edge) {
  return {{side, side, side, edge}, {0.0f, 1.0f, 0.0f, 0.0f}, int(ShapeKind::Cube)};
}
// Plate: size.x × size.y, thickness size.z, riding the wave z = amplitude·sin(kx + phase)·sin(ky + phase).
inline ShapeDims plateDims(glm::vec3 size, float edge, float amplitude, float wavelength, float phase) {
  return {{size, edge}, {amplitude, wavelength, phase, 0.0f}, int(ShapeKind::Plate)};
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

// A stadium slab with its rim rounded by r = min(edge, T/2, H/2): the preset's edge 100 with T = 62 clamps to
// 31, a half-round rim. The squircle rim measures the rounding in the L4 norm: flatter faces, a tighter turn.
// Exact for the round rim; the L4 rim stays a bound (|grad| <= 1 since the L6 norm never exceeds the L4 norm).
inline float sdPill(glm::vec3 p, glm::vec3 size, float edge, bool squircle) {
  const float endRadius = 0.5f * size.y;
  const float r = glm::min(edge, glm::min(0.5f * size.z, endRadius));
  const float straight = glm::max(0.5f * size.x - endRadius, 0.0f);  // half the length between the end centres
  const float stadium = glm::length(glm::vec2(glm::max(std::fabs(p.x) - straight, 0.0f), p.y)) - endRadius;
  const glm::vec2 w{stadium + r, std::fabs(p.z) - (0.5f * size.z - r)};
  const glm::vec2 out = glm::max(w, 0.0f);
  const float rim = squircle ? std::sqrt(std::sqrt(out.x * out.x * out.x * out.x + out.y * out.y * out.y * out.y))
                             : glm::length(out);
  return glm::min(glm::max(w.x, w.y), 0.0f) + rim - r;
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

// A box of half size `half` with edges rounded by r (r <= the smallest half size).
inline float sdRoundedBox(glm::vec3 p, glm::vec3 half, float r) {
  const glm::vec3 q = glm::abs(p) - (half - r);
  return glm::length(glm::max(q, 0.0f)) + glm::min(glm::max(q.x, glm::max(q.y, q.z)), 0.0f) - r;
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
  const float r = glm::min(sizeEdge.w, glm::min(half.z, glm::min(half.x, half.y)));
  const glm::vec3 q{p.x, p.y, p.z - plateHeight({p.x, p.y}, wave)};
  return sdRoundedBox(q, half, r) / plateLipschitz(wave);
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
