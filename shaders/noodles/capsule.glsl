// Ray-capsule hits, ordered depth bits, sample positions and the conservative screen box of a
// projected capsule; mirrors src/scenes/noodles/capsule.h, whose comments say why.
#ifndef NOODLES_CAPSULE_GLSL
#define NOODLES_CAPSULE_GLSL

const float NO_HIT = -1.0;

float capsuleHit(vec3 origin, vec3 direction, vec3 a, vec3 b, float radius) {
  float shift = dot(0.5 * (a + b) - origin, direction);
  vec3 o = origin + shift * direction;
  vec3 ba = b - a, oa = o - a, across = cross(direction, ba);
  float baba = dot(ba, ba), bard = dot(ba, direction), baoa = dot(ba, oa);
  float qa = dot(across, across);
  float qb = baba * dot(direction, oa) - baoa * bard;
  float apart = dot(oa, across);
  float h = baba * (qa * radius * radius - apart * apart);
  if (h < 0.0) return NO_HIT;
  float side = qa > 0.0 ? (-qb - sqrt(h)) / qa : 0.0;
  float along = qa > 0.0 ? baoa + side * bard : (bard > 0.0 ? -1.0 : baba + 1.0);
  float t = side;
  if (along <= 0.0 || along >= baba) {
    vec3 oc = along <= 0.0 ? oa : o - b;
    float nearest = -dot(direction, oc);
    vec3 miss = oc + nearest * direction;
    float sh = radius * radius - dot(miss, miss);
    if (sh < 0.0) return NO_HIT;
    t = nearest - sqrt(sh);
  }
  float hit = t + shift;
  return hit > 0.0 ? hit : NO_HIT;
}

float alongSegment(vec3 p, vec3 a, vec3 b) {
  vec3 ba = b - a;
  return clamp(dot(p - a, ba) / max(dot(ba, ba), 1e-30), 0.0, 1.0);
}

bool insideCapsule(vec3 p, vec3 a, vec3 b, float radius) {
  vec3 axis = mix(a, b, alongSegment(p, a, b));
  return dot(p - axis, p - axis) < radius * radius * 0.998;
}

uint orderedBits(float value) {
  uint bits = floatBitsToUint(value);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

struct ScreenView {
  vec3 eye, right, up, forward;
  float tanHalfX, tanHalfY, nearPlane;
  vec2 pixels;
};

vec3 rayThrough(ScreenView view, vec2 position) {
  vec2 ndc = position / view.pixels * 2.0 - 1.0;
  return view.forward + ndc.x * view.tanHalfX * view.right - ndc.y * view.tanHalfY * view.up;
}

vec2 sampleOffset(uint quarter, uint samplesPerAxis) {
  if (samplesPerAxis == 1u) return vec2(0.5);
  const vec2 STANDARD_4[4] = vec2[4](vec2(0.375, 0.125), vec2(0.875, 0.375), vec2(0.125, 0.625), vec2(0.625, 0.875));
  return STANDARD_4[quarter & 3u];
}

vec2 cellSamplePosition(uvec2 cell, uint samplesPerAxis) {
  uvec2 pixel = cell / samplesPerAxis;
  uvec2 quarter = cell - pixel * samplesPerAxis;
  return vec2(pixel) + sampleOffset(quarter.y * 2u + quarter.x, samplesPerAxis);
}

vec3 toView(ScreenView view, vec3 p) {
  vec3 d = p - view.eye;
  return vec3(dot(d, view.right), dot(d, view.up), dot(d, view.forward));
}

vec2 sphereSlopes(float side, float depth, float radius) {
  float root = radius * sqrt(max(side * side + depth * depth - radius * radius, 0.0));
  return vec2(side * depth - root, side * depth + root) / (depth * depth - radius * radius);
}

// The pixel boxes of the capsule's two end spheres (xy the least corner, zw the greatest, unclipped);
// capsule.h's capsuleEndBoxes says why their hull holds the capsule's outline.
struct EndBoxes {
  vec4 a, b;
  bool visible, bounded;
};

EndBoxes capsuleEndBoxes(ScreenView view, vec3 a, vec3 b, float radius) {
  EndBoxes e = EndBoxes(vec4(0.0), vec4(0.0), false, false);
  vec3 va = toView(view, a), vb = toView(view, b);
  float nearest = view.nearPlane - radius;
  if (va.z < nearest && vb.z < nearest) return e;
  e.visible = true;
  if (va.z < nearest) va = mix(va, vb, (nearest - va.z) / (vb.z - va.z));
  if (vb.z < nearest) vb = mix(vb, va, (nearest - vb.z) / (va.z - vb.z));
  if (!(min(va.z, vb.z) > radius * 1.001)) return e;
  e.bounded = true;
  vec2 xa = sphereSlopes(va.x, va.z, radius), xb = sphereSlopes(vb.x, vb.z, radius);
  vec2 ya = sphereSlopes(va.y, va.z, radius), yb = sphereSlopes(vb.y, vb.z, radius);
  // slope / tanHalf is the NDC coordinate; y flips (framebuffer y points down).
  vec2 toPixels = 0.5 * view.pixels;
  e.a = vec4((xa.x / view.tanHalfX + 1.0) * toPixels.x, (1.0 - ya.y / view.tanHalfY) * toPixels.y,
             (xa.y / view.tanHalfX + 1.0) * toPixels.x, (1.0 - ya.x / view.tanHalfY) * toPixels.y);
  e.b = vec4((xb.x / view.tanHalfX + 1.0) * toPixels.x, (1.0 - yb.y / view.tanHalfY) * toPixels.y,
             (xb.y / view.tanHalfX + 1.0) * toPixels.x, (1.0 - yb.x / view.tanHalfY) * toPixels.y);
  return e;
}

// The sample cells (inclusive: xy the first, zw the last) that may hold a hit of the capsule;
// x > z or y > w when none do.
ivec4 capsuleCells(ScreenView view, EndBoxes e, uint samplesPerAxis) {
  const ivec4 NONE = ivec4(0, 0, -1, -1);
  if (!e.visible) return NONE;
  vec2 lo = vec2(0.0), hi = view.pixels;
  if (e.bounded) {
    lo = min(e.a.xy, e.b.xy);
    hi = max(e.a.zw, e.b.zw);
  }
  lo = max(lo, vec2(0.0));
  hi = min(hi, view.pixels);
  if (!(lo.x <= hi.x && lo.y <= hi.y)) return NONE;
  float s = float(samplesPerAxis);
  ivec2 last = ivec2(view.pixels) * int(samplesPerAxis) - 1;
  return ivec4(max(ivec2(floor(lo * s)), ivec2(0)), min(ivec2(floor(hi * s)), last));
}

// The columns of sample cells, within `cells`, that the hull of the end boxes reaches in the band of
// pixel rows [y0, y1]; x > y when none. capsule.h's hullColumns says how.
const float HULL_MARGIN = 1e-3;  // pixels: kHullMargin

ivec2 hullColumns(EndBoxes e, float y0, float y1, ivec4 cells, uint samplesPerAxis) {
  if (!e.bounded) return cells.xz;
  y0 -= HULL_MARGIN;
  y1 += HULL_MARGIN;
  // The band meets box(t) where top(t) <= y1 and bottom(t) >= y0, each linear in t.
  float t0 = 0.0, t1 = 1.0;
  float dTop = e.b.y - e.a.y, dBottom = e.b.w - e.a.w;
  if (dTop > 0.0) t1 = min(t1, (y1 - e.a.y) / dTop);
  else if (dTop < 0.0) t0 = max(t0, (y1 - e.a.y) / dTop);
  else if (e.a.y > y1) return ivec2(0, -1);
  if (dBottom > 0.0) t0 = max(t0, (y0 - e.a.w) / dBottom);
  else if (dBottom < 0.0) t1 = min(t1, (y0 - e.a.w) / dBottom);
  else if (e.a.w < y0) return ivec2(0, -1);
  if (t0 > t1) return ivec2(0, -1);
  vec4 first = mix(e.a, e.b, t0), last = mix(e.a, e.b, t1);
  float s = float(samplesPerAxis);
  return ivec2(max(int(floor((min(first.x, last.x) - HULL_MARGIN) * s)), cells.x),
               min(int(floor((max(first.z, last.z) + HULL_MARGIN) * s)), cells.z));
}

float nearestPossibleHit(vec3 eye, vec3 a, vec3 b, float radius) {
  return max(distance(eye, mix(a, b, alongSegment(eye, a, b))) - radius, 0.0);
}

bool tileMayHit(ScreenView view, vec3 a, vec3 b, float radius, uvec2 firstCell, uint side, uint samplesPerAxis) {
  float s = float(samplesPerAxis);
  vec2 centre = (vec2(firstCell) + 0.5 * float(side)) / s;
  vec2 slopePerPixel = vec2(2.0 * view.tanHalfX, 2.0 * view.tanHalfY) / view.pixels;
  float angle = length(slopePerPixel * (0.5 * float(side) / s));
  float reach = max(distance(a, view.eye), distance(b, view.eye)) + radius;
  float fat = (radius + reach * angle) * 1.001 + 1e-6 * reach;
  if (insideCapsule(view.eye, a, b, fat)) return true;
  return capsuleHit(view.eye, normalize(rayThrough(view, centre)), a, b, fat) != NO_HIT;
}

#endif
