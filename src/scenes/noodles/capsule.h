#pragma once
// The maths of drawing tubes by ray casting instead of triangles: every segment is a capsule (the
// points within `radius` of the segment between its two nodes), so consecutive segments share the
// sphere round their common node and join with no gap and no bump, and a strand's ends are round.
//  - the eye ray through a sample position, and where the sample positions lie in a pixel;
//  - the ray-capsule intersection;
//  - the float -> ordered uint mapping that lets one 64-bit atomicMin keep the nearest hit;
//  - the screen box of a projected capsule, conservative, and the sample cells it covers.
// Mirrored by shaders/noodles/capsule.glsl; tests/unit/noodles_capsule_test.cpp checks it.
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace vitrine::noodles {

inline constexpr float kNoHit = -1.0f;

// Nearest t > 0 at which origin + t * direction (unit length) enters the capsule, else kNoHit; a ray
// starting inside sees nothing (a tube the camera flies through is not drawn from within).
// Float rounding must not eat the radius:
//  - the ray is first moved to where it passes the segment's middle, so no term is of the camera's
//    distance (|o|^2 ~ 10^4 against r^2 ~ 10^-4 far away);
//  - whether it meets the infinite cylinder comes from the distance between the ray's line and the
//    axis, one dot product with d x ba, not from the quadratic's discriminant qb^2 - qa qc (equal in
//    exact arithmetic): those terms are of |ba|^2 |o - a|^2, and their difference lost the radius for
//    segments a few thousand radii long (which the step and radius sliders reach), drawing rays that
//    passed outside and dropping rays that passed inside;
//  - an end sphere is met from the ray's point nearest its centre, for the same reason.
inline float capsuleHit(glm::vec3 origin, glm::vec3 direction, glm::vec3 a, glm::vec3 b, float radius) {
  const float shift = glm::dot(0.5f * (a + b) - origin, direction);
  const glm::vec3 o = origin + shift * direction;
  const glm::vec3 ba = b - a, oa = o - a, across = glm::cross(direction, ba);
  const float baba = glm::dot(ba, ba), bard = glm::dot(ba, direction), baoa = glm::dot(ba, oa);
  const float qa = glm::dot(across, across);  // baba - bard^2, without its cancellation for rays near the axis
  const float qb = baba * glm::dot(direction, oa) - baoa * bard;
  const float apart = glm::dot(oa, across);  // the two lines' distance times |d x ba|
  const float h = baba * (qa * radius * radius - apart * apart);
  if (h < 0.0f) return kNoHit;  // misses the infinite cylinder, hence both end spheres inside it
  // Where the ray enters the infinite cylinder, as a distance along the axis times |ba|; a ray along
  // the axis (qa = 0) enters at the end it meets first.
  const float side = qa > 0.0f ? (-qb - std::sqrt(h)) / qa : 0.0f;
  const float along = qa > 0.0f ? baoa + side * bard : (bard > 0.0f ? -1.0f : baba + 1.0f);
  float t = side;
  if (along <= 0.0f || along >= baba) {  // beyond an end: the sphere round that node
    const glm::vec3 oc = along <= 0.0f ? oa : o - b;
    const float nearest = -glm::dot(direction, oc);
    const glm::vec3 miss = oc + nearest * direction;  // from the centre to the ray's nearest point
    const float sh = radius * radius - glm::dot(miss, miss);
    if (sh < 0.0f) return kNoHit;
    t = nearest - std::sqrt(sh);
  }
  const float hit = t + shift;
  return hit > 0.0f ? hit : kNoHit;  // entered behind the origin: it starts inside, or all is behind
}

// The point of the segment nearest p, as a fraction of the way from a to b: where along the strand
// a hit lies (for the frames) and, with the axis point, the outward normal.
inline float alongSegment(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
  const glm::vec3 ba = b - a;
  return std::clamp(glm::dot(p - a, ba) / std::max(glm::dot(ba, ba), 1e-30f), 0.0f, 1.0f);
}

// Whether p lies strictly inside the capsule (short of its surface by a part in a thousand of the
// radius, so a point on a surface two capsules share is not "inside" either). Consecutive capsules
// overlap round their shared node: with nothing in front, the nearer capsule's hit always hides the
// overlap, but where the near plane cuts that hit away, the overlap's far surface would show as rings
// inside the tube; the raster pass drops hits inside a neighbour there.
inline bool insideCapsule(glm::vec3 p, glm::vec3 a, glm::vec3 b, float radius) {
  const glm::vec3 axis = glm::mix(a, b, alongSegment(p, a, b));
  return glm::dot(p - axis, p - axis) < radius * radius * 0.998f;
}

// Floats to uints in the same order (negatives below positives), so comparing the uints compares
// the floats: the high half of a 64-bit atomicMin key.
inline uint32_t orderedBits(float value) {
  const uint32_t bits = std::bit_cast<uint32_t>(value);
  return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

// An empty sample: every real key is smaller, so clearing the buffer to all ones empties it.
inline constexpr uint64_t kEmptyKey = ~uint64_t(0);

inline uint64_t visibilityKey(float distance, uint32_t segment) {
  return (uint64_t(orderedBits(distance)) << 32) | segment;
}

// The camera as the rasteriser sees it: eye, orthonormal basis, the tangents of the half field of
// view, the near plane (no hit nearer than it along `forward` is drawn, as with the old depth clip)
// and the image in pixels.
struct ScreenView {
  glm::vec3 eye, right, up, forward;
  float tanHalfX = 1.0f, tanHalfY = 1.0f;
  float nearPlane = 0.25f;
  glm::vec2 pixels{1.0f};
};

// The unnormalised eye ray through a position in pixels (origin top-left, y down, as Vulkan's
// framebuffer), matching reverseZPerspective + lookAtZUp.
inline glm::vec3 rayThrough(const ScreenView& view, glm::vec2 position) {
  const glm::vec2 ndc = position / view.pixels * 2.0f - 1.0f;
  return view.forward + ndc.x * view.tanHalfX * view.right - ndc.y * view.tanHalfY * view.up;
}

// Sample positions inside a pixel. One sample: the centre. Four: Vulkan's standard 4x locations
// (a rotated grid, so near-horizontal and near-vertical edges get four distinct steps), one in each
// quarter of the pixel, so sample cell (x, y) of the doubled grid holds the sample in that quarter.
inline glm::vec2 sampleOffset(uint32_t quarter, uint32_t samplesPerAxis) {
  if (samplesPerAxis == 1) return {0.5f, 0.5f};
  constexpr glm::vec2 kStandard4[4] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  return kStandard4[quarter & 3u];
}

// Sample cell (x, y) of the grid samplesPerAxis times as fine as the pixels: its sample's position
// in pixels.
inline glm::vec2 cellSamplePosition(glm::uvec2 cell, uint32_t samplesPerAxis) {
  const glm::uvec2 pixel = cell / samplesPerAxis;
  const glm::uvec2 quarter = cell - pixel * samplesPerAxis;
  return glm::vec2(pixel) + sampleOffset(quarter.y * 2u + quarter.x, samplesPerAxis);
}

// Where a point lies on the view's axes: right, up, forward (forward = depth).
inline glm::vec3 toView(const ScreenView& view, glm::vec3 p) {
  const glm::vec3 d = p - view.eye;
  return {glm::dot(d, view.right), glm::dot(d, view.up), glm::dot(d, view.forward)};
}

// The tangents of the planes through the eye that touch a sphere, along one screen axis: `side` is
// the centre's coordinate on that axis, `depth` its forward one (> radius).
inline glm::vec2 sphereSlopes(float side, float depth, float radius) {
  const float root = radius * std::sqrt(std::max(side * side + depth * depth - radius * radius, 0.0f));
  const float denominator = depth * depth - radius * radius;
  return glm::vec2(side * depth - root, side * depth + root) / denominator;
}

struct PixelBox {
  glm::vec2 min{0.0f}, max{-1.0f};
  bool empty() const { return !(min.x <= max.x && min.y <= max.y); }
};

// The pixel boxes of the capsule's two end spheres (unclipped), the segment first cut where it comes
// nearer than the near plane: hits beyond the near plane lie within `radius` of the part of the
// segment at depth >= near - radius, and perspective keeps convex sets convex, so the capsule's
// outline is the hull of its end spheres' outlines, each bounded exactly per axis by the planes
// tangent to it. Not `visible` when the capsule lies wholly nearer than the near plane; not `bounded`
// when an end sphere reaches the eye's plane (then the whole image may hold it).
struct EndBoxes {
  PixelBox a, b;
  bool visible = false, bounded = false;
};

inline EndBoxes capsuleEndBoxes(const ScreenView& view, glm::vec3 a, glm::vec3 b, float radius) {
  EndBoxes ends;
  glm::vec3 va = toView(view, a), vb = toView(view, b);
  const float nearest = view.nearPlane - radius;
  if (va.z < nearest && vb.z < nearest) return ends;
  ends.visible = true;
  if (va.z < nearest) va = glm::mix(va, vb, (nearest - va.z) / (vb.z - va.z));
  if (vb.z < nearest) vb = glm::mix(vb, va, (nearest - vb.z) / (va.z - vb.z));
  if (!(std::min(va.z, vb.z) > radius * 1.001f)) return ends;
  ends.bounded = true;
  const auto boxOf = [&](glm::vec3 v) {
    const glm::vec2 x = sphereSlopes(v.x, v.z, radius), y = sphereSlopes(v.y, v.z, radius);
    // slope / tanHalf is the NDC coordinate; y flips (framebuffer y points down).
    const glm::vec2 half = 0.5f * view.pixels;
    return PixelBox{{(x.x / view.tanHalfX + 1.0f) * half.x, (1.0f - y.y / view.tanHalfY) * half.y},
                    {(x.y / view.tanHalfX + 1.0f) * half.x, (1.0f - y.x / view.tanHalfY) * half.y}};
  };
  ends.a = boxOf(va);
  ends.b = boxOf(vb);
  return ends;
}

// A box in pixels that holds every hit of the capsule at or beyond the near plane, clipped to the
// image: its end boxes' union, the whole image when they are unbounded (the tile pass takes such big
// boxes), empty when it is off-screen or wholly nearer than the near plane.
inline PixelBox capsuleScreenBox(const ScreenView& view, const EndBoxes& ends) {
  if (!ends.visible) return {};
  const glm::vec2 image = view.pixels;
  PixelBox box{glm::vec2(0.0f), image};
  if (ends.bounded) box = {glm::min(ends.a.min, ends.b.min), glm::max(ends.a.max, ends.b.max)};
  box.min = glm::max(box.min, glm::vec2(0.0f));
  box.max = glm::min(box.max, image);
  return box;
}

inline PixelBox capsuleScreenBox(const ScreenView& view, glm::vec3 a, glm::vec3 b, float radius) {
  return capsuleScreenBox(view, capsuleEndBoxes(view, a, b, radius));
}

// The sample cells (inclusive) whose samples may lie in the box: cell x spans pixels
// [x / s, (x + 1) / s) and its sample lies inside it. min > max when there are none.
struct CellBox {
  glm::ivec2 min{0}, max{-1};
  bool empty() const { return min.x > max.x || min.y > max.y; }
  uint32_t count() const { return empty() ? 0u : uint32_t(max.x - min.x + 1) * uint32_t(max.y - min.y + 1); }
};

inline CellBox cellsOf(const PixelBox& box, uint32_t samplesPerAxis, glm::uvec2 pixels) {
  if (box.empty()) return {};
  const float s = float(samplesPerAxis);
  const glm::ivec2 last = glm::ivec2(pixels * samplesPerAxis) - 1;
  return {glm::max(glm::ivec2(glm::floor(box.min * s)), glm::ivec2(0)),
          glm::min(glm::ivec2(glm::floor(box.max * s)), last)};
}

// The columns of sample cells, within `cells`, that the hull of the end boxes reaches in the band of
// pixel rows [y0, y1] (min > max when none): the rasteriser casts only those of each row. The hull of
// two boxes is the union of the boxes between them, (1 - t) a + t b for t in [0, 1], so the band meets
// those of an interval of t, and since each box edge is linear in t the interval's ends hold the
// span's ends. A margin of kHullMargin pixels keeps rounding from dropping a cell the outline reaches.
inline constexpr float kHullMargin = 1e-3f;

inline glm::ivec2 hullColumns(const EndBoxes& ends, float y0, float y1, const CellBox& cells, uint32_t samplesPerAxis) {
  const glm::ivec2 none{0, -1};
  if (!ends.bounded) return {cells.min.x, cells.max.x};
  y0 -= kHullMargin;
  y1 += kHullMargin;
  // The band meets box(t) where its top is at most y1 and its bottom at least y0, each linear in t.
  float t0 = 0.0f, t1 = 1.0f;
  const float dTop = ends.b.min.y - ends.a.min.y, dBottom = ends.b.max.y - ends.a.max.y;
  if (dTop > 0.0f)
    t1 = std::min(t1, (y1 - ends.a.min.y) / dTop);
  else if (dTop < 0.0f)
    t0 = std::max(t0, (y1 - ends.a.min.y) / dTop);
  else if (ends.a.min.y > y1)
    return none;
  if (dBottom > 0.0f)
    t0 = std::max(t0, (y0 - ends.a.max.y) / dBottom);
  else if (dBottom < 0.0f)
    t1 = std::min(t1, (y0 - ends.a.max.y) / dBottom);
  else if (ends.a.max.y < y0)
    return none;
  if (t0 > t1) return none;
  const float left = std::min(glm::mix(ends.a.min.x, ends.b.min.x, t0), glm::mix(ends.a.min.x, ends.b.min.x, t1));
  const float right = std::max(glm::mix(ends.a.max.x, ends.b.max.x, t0), glm::mix(ends.a.max.x, ends.b.max.x, t1));
  const float s = float(samplesPerAxis);
  return {std::max(int(std::floor((left - kHullMargin) * s)), cells.min.x),
          std::min(int(std::floor((right + kHullMargin) * s)), cells.max.x)};
}

// No ray from `eye` meets the capsule nearer than this: the distance to its axis' nearest point, less
// the radius. A sample already holding a nearer hit needs no ray cast for it.
inline float nearestPossibleHit(glm::vec3 eye, glm::vec3 a, glm::vec3 b, float radius) {
  return std::max(glm::distance(eye, glm::mix(a, b, alongSegment(eye, a, b))) - radius, 0.0f);
}

// Whether a square of side x side sample cells, from firstCell, may hold a hit of the capsule (the
// rasteriser skips the tiles of a big box that cannot). Conservative: every ray of the tile turns
// from the ray through its centre by at most `angle` (the tile's half-diagonal on the image plane at
// distance 1, which the turn onto the unit sphere only shrinks), so a hit at distance t on any of them
// has a point of the centre ray within t * angle of it, and t is at most `reach`. The centre ray then
// meets the capsule fattened by reach * angle, or starts inside it.
inline bool tileMayHit(const ScreenView& view, glm::vec3 a, glm::vec3 b, float radius, glm::uvec2 firstCell,
                       uint32_t side, uint32_t samplesPerAxis) {
  const float s = float(samplesPerAxis);
  const glm::vec2 centre = (glm::vec2(firstCell) + 0.5f * float(side)) / s;
  const glm::vec2 slopePerPixel = glm::vec2(2.0f * view.tanHalfX, 2.0f * view.tanHalfY) / view.pixels;
  const float angle = glm::length(slopePerPixel * (0.5f * float(side) / s));
  const float reach = std::max(glm::distance(a, view.eye), glm::distance(b, view.eye)) + radius;
  const float fat = (radius + reach * angle) * 1.001f + 1e-6f * reach;  // rounding never turns a hit away
  if (insideCapsule(view.eye, a, b, fat)) return true;
  return capsuleHit(view.eye, glm::normalize(rayThrough(view, centre)), a, b, fat) != kNoHit;
}

}  // namespace vitrine::noodles
