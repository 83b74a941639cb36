#include "scenes/glass/shapes.h"

#include "scenes/glass/diamond_rays.h"

#include <limits>

namespace vitrine::glass {
namespace {

glm::vec3 size(const ShapeDims& s) { return glm::vec3(s.sizeEdge); }

// 1 / v with zero components replaced by a tiny number, so slab tests need no special cases.
glm::vec3 inverse(glm::vec3 v) {
  return 1.0f / glm::vec3(std::fabs(v.x) < 1e-20f ? 1e-20f : v.x, std::fabs(v.y) < 1e-20f ? 1e-20f : v.y,
                          std::fabs(v.z) < 1e-20f ? 1e-20f : v.z);
}

// The stretch [t0, t1] of the ray inside the box |p| <= half.
bool boxRange(glm::vec3 ro, glm::vec3 rd, glm::vec3 half, float& t0, float& t1) {
  const glm::vec3 inv = inverse(rd);
  const glm::vec3 a = (-half - ro) * inv, b = (half - ro) * inv;
  const glm::vec3 lo = glm::min(a, b), hi = glm::max(a, b);
  t0 = glm::max(lo.x, glm::max(lo.y, lo.z));
  t1 = glm::min(hi.x, glm::min(hi.y, hi.z));
  return t0 <= t1;
}

// Exit from inside the rectangle of half size `half` with corners rounded by c (a stadium when c is half the
// height) in XY; d.xy need not be unit. The rectangle's exit, unless it lands in a corner's square, where the
// ray is in that corner's disc and leaves it at the far root.
float roundedRectExit(glm::vec2 p, glm::vec2 d, glm::vec2 half, float c) {
  if (glm::dot(d, d) < 1e-12f) return kInf;
  const glm::vec2 inv = 1.0f / glm::vec2(std::fabs(d.x) < 1e-20f ? 1e-20f : d.x, std::fabs(d.y) < 1e-20f ? 1e-20f : d.y);
  const glm::vec2 far = glm::max((-half - p) * inv, (half - p) * inv);
  const float t = glm::min(far.x, far.y);
  const glm::vec2 at = p + t * d, inner = half - c;
  if (std::fabs(at.x) <= inner.x || std::fabs(at.y) <= inner.y) return t;  // through a straight side
  const glm::vec2 o = p - glm::vec2(at.x > 0.0f ? inner.x : -inner.x, at.y > 0.0f ? inner.y : -inner.y);
  const float qa = glm::dot(d, d), qb = glm::dot(o, d), qc = glm::dot(o, o) - c * c;
  return (-qb + std::sqrt(glm::max(qb * qb - qa * qc, 0.0f))) / qa;
}

// Exit from inside the slab |z| <= half.
float slabExit(float p, float d, float half) {
  return std::fabs(d) < 1e-12f ? kInf : ((d > 0.0f ? half : -half) - p) / d;
}

// Newton on f(t) = sdf(p + t·d), from a t at or past the surface. The shapes are convex (the plate nearly so),
// and for a convex f the iterates fall monotonically onto the exit without overshooting it.
float refineExit(const ShapeDims& s, glm::vec3 p, glm::vec3 d, float t, int steps) {
  const float h = kNormalStep * shapeScale(s);
  for (int i = 0; i < steps; ++i) {
    const float f = shapeSdf(s, p + t * d);
    const float slope = (shapeSdf(s, p + (t + h) * d) - shapeSdf(s, p + (t - h) * d)) / (2.0f * h);
    if (slope < 1e-3f) break;  // grazing: a Newton step would fly off; keep what we have
    t = glm::max(t - f / slope, 0.0f);
  }
  return t;
}

// The plate's face z = h(x, y) + offset along the ray: a tangent-plane seed, then 3 Newton iterations on
// g(t) = z(t) - h(x(t), y(t)) - offset. Infinite when the face is not ahead or Newton did not settle.
float plateFaceExit(glm::vec3 p, glm::vec3 d, glm::vec4 wave, float offset, float tolerance) {
  float t = 0.0f;
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 q = p + t * d;
    const float g = q.z - plateHeight({q.x, q.y}, wave) - offset;
    const float slope = d.z - glm::dot(plateSlope({q.x, q.y}, wave), glm::vec2(d.x, d.y));
    if (std::fabs(slope) < 1e-6f) return kInf;
    t -= g / slope;
  }
  const glm::vec3 q = p + t * d;
  const bool settled = std::fabs(q.z - plateHeight({q.x, q.y}, wave) - offset) < tolerance;
  return t > 0.0f && settled ? t : kInf;
}

// The prism's five planes (unit outward normal, offset).
glm::vec4 prismPlane(glm::vec3 sz, int i) {
  const float b = 0.5f * sz.y, h = sz.z, slant = std::sqrt(h * h + b * b);
  switch (i) {
    case 0: return {1.0f, 0.0f, 0.0f, 0.5f * sz.x};
    case 1: return {-1.0f, 0.0f, 0.0f, 0.5f * sz.x};
    case 2: return {0.0f, 0.0f, -1.0f, 0.5f * h};
    case 3: return {0.0f, h / slant, b / slant, 0.5f * b * h / slant};
    default: return {0.0f, -h / slant, b / slant, 0.5f * b * h / slant};
  }
}

}  // namespace

float shapeSdf(const ShapeDims& s, glm::vec3 p) {
  switch (ShapeKind(s.kind)) {
    case ShapeKind::Pill: return sdPill(p, size(s), s.sizeEdge.w, s.wave.w > 0.5f);
    case ShapeKind::Prism: return sdPrism(p, size(s));
    case ShapeKind::Cube: return sdCube(p, s.sizeEdge, s.wave.w > 0.5f);
    case ShapeKind::Plate: return sdPlate(p, s.sizeEdge, s.wave);
    case ShapeKind::Diamond: return diamondSdf(cachedDiamond(s.sizeEdge.x), p);
  }
  return kInf;
}

glm::vec3 shapeNormal(const ShapeDims& s, glm::vec3 p) {
  if (ShapeKind(s.kind) == ShapeKind::Diamond) {
    int facet;
    return diamondNormal(cachedDiamond(s.sizeEdge.x), p, facet);
  }
  const float h = kNormalStep * shapeScale(s);
  const glm::vec3 g{shapeSdf(s, p + glm::vec3(h, 0, 0)) - shapeSdf(s, p - glm::vec3(h, 0, 0)),
                    shapeSdf(s, p + glm::vec3(0, h, 0)) - shapeSdf(s, p - glm::vec3(0, h, 0)),
                    shapeSdf(s, p + glm::vec3(0, 0, h)) - shapeSdf(s, p - glm::vec3(0, 0, h))};
  const float length = glm::length(g);
  return length > 1e-20f ? g / length : glm::vec3(0.0f, 0.0f, 1.0f);  // the centre has no preferred normal
}

glm::vec3 shapeHalfExtent(const ShapeDims& s) {
  const glm::vec3 half = 0.5f * size(s);
  switch (ShapeKind(s.kind)) {
    case ShapeKind::Pill: return {glm::max(half.x, half.y), half.y, half.z};
    case ShapeKind::Plate: return {half.x, half.y, half.z + std::fabs(s.wave.x)};
    case ShapeKind::Diamond: {
      const DiamondGeometry& g = cachedDiamond(s.sizeEdge.x);
      return {g.girdleRadius, g.girdleRadius, glm::max(g.tableHeight, g.culetDepth)};
    }
    default: return half;
  }
}

bool shapeEnter(const ShapeDims& s, glm::vec3 ro, glm::vec3 rd, float& t, glm::vec3& n, int& facet) {
  if (ShapeKind(s.kind) == ShapeKind::Diamond) return diamondEnter(cachedDiamond(s.sizeEdge.x), ro, rd, t, n, facet);
  facet = -1;
  const float tolerance = kHitTolerance * shapeScale(s);
  float t0, t1;
  // A margin of one tolerance, so a ray touching the box still gets its last steps.
  if (!boxRange(ro, rd, shapeHalfExtent(s) + tolerance, t0, t1) || t1 < 0.0f) return false;
  t = glm::max(t0, 0.0f);
  for (int i = 0; i < kMarchSteps && t <= t1; ++i) {
    const float d = shapeSdf(s, ro + t * rd);
    if (d < tolerance) {
      n = shapeNormal(s, ro + t * rd);
      return true;
    }
    t += d;
  }
  return false;
}

bool shapeExit(const ShapeDims& s, glm::vec3 p, glm::vec3 d, float& t, glm::vec3& n, int& facet) {
  facet = -1;
  const glm::vec3 sz = size(s);
  // A sharp shape holding this one gives the seed; Newton steps land it on the rounded surface.
  float seed = kInf;
  int steps = 0;
  switch (ShapeKind(s.kind)) {
    case ShapeKind::Diamond: return diamondExit(cachedDiamond(s.sizeEdge.x), p, d, t, n, facet);
    case ShapeKind::Prism: {
      t = kInf;
      for (int i = 0; i < 5; ++i) {
        const glm::vec4 plane = prismPlane(sz, i);
        const float along = glm::dot(glm::vec3(plane), d);
        if (along <= 1e-8f) continue;
        const float ti = glm::max((plane.w - glm::dot(glm::vec3(plane), p)) / along, 0.0f);
        if (ti < t) t = ti, n = glm::vec3(plane);
      }
      return std::isfinite(t);
    }
    case ShapeKind::Pill: {
      const glm::vec2 half{0.5f * sz.x, 0.5f * sz.y};
      const float corner = glm::min(s.sizeEdge.w, glm::min(half.x, half.y));
      seed = glm::min(roundedRectExit({p.x, p.y}, {d.x, d.y}, half, corner), slabExit(p.z, d.z, 0.5f * sz.z));
      steps = s.wave.w > 0.5f ? 6 : 4;  // the L4 rim's larger radius leaves the seed further out
      break;
    }
    case ShapeKind::Cube: {
      float t0;
      boxRange(p, d, 0.5f * sz, t0, seed);
      steps = s.wave.w > 0.5f ? 6 : 4;
      break;
    }
    case ShapeKind::Plate: {  // the vertical rim or a wavy face, then onto the rounded rim
      const float tolerance = 1e-4f * shapeScale(s);
      const float side = glm::min(slabExit(p.x, d.x, 0.5f * sz.x), slabExit(p.y, d.y, 0.5f * sz.y));
      const float top = plateFaceExit(p, d, s.wave, 0.5f * sz.z, tolerance);
      const float bottom = plateFaceExit(p, d, s.wave, -0.5f * sz.z, tolerance);
      seed = glm::min(side, glm::min(top, bottom));
      steps = s.wave.w > 0.5f ? 3 : 2;
      break;
    }
  }
  if (!std::isfinite(seed)) return false;
  t = refineExit(s, p, d, seed, steps);
  n = shapeNormal(s, p + t * d);
  return true;
}

}  // namespace vitrine::glass
