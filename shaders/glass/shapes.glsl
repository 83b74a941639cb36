// The glass scene's shapes: distance fields, front hits and analytic back exits in object space; mirrors
// src/scenes/glass/shapes.h function for function. Includes glass/diamond.glsl, so define DIAMOND_BINDING first.
// The rotations are not here: the host computes them (cubeRotation & co.) and passes the matrices.
#ifndef GLASS_SHAPES_GLSL
#define GLASS_SHAPES_GLSL

#include "glass/diamond.glsl"
#include "glass/shape_dims.h"

const int SHAPE_PILL = 0;
const int SHAPE_PRISM = 1;
const int SHAPE_CUBE = 2;
const int SHAPE_PLATE = 3;
const int SHAPE_DIAMOND = 4;

const int MARCH_STEPS = 64;        // front sphere trace budget
const float HIT_TOLERANCE = 1e-3;  // front trace stops within this × scale of the surface
const float NORMAL_STEP = 1e-4;    // central-difference step × scale (normals, Newton slopes)
const float SHAPE_FAR = 1e30;
const float TWO_PI = 6.28318530718;

float shapeScale(GlassShapeDims s) { return max(s.sizeEdge.x, max(s.sizeEdge.y, s.sizeEdge.z)); }

// Smooth curvature: L4 squircle rims, their radius compensated so that they cut as much off the corner's
// diagonal as a circle of the edge radius (shapes.h derives k).
const float SQUIRCLE_COMPENSATION = 1.8408964;
float rimRadius(float edge, float room, bool squircle) { return min(squircle ? edge * SQUIRCLE_COMPENSATION : edge, room); }
float lengthL4(vec2 v) {
  vec2 s = v * v;
  return sqrt(sqrt(dot(s, s)));
}
float lengthL4(vec3 v) {
  vec3 s = v * v;
  return sqrt(sqrt(dot(s, s)));
}

float sdRoundedRect(vec2 p, vec2 halfSize, float c) {
  vec2 q = abs(p) - (halfSize - c);
  return length(max(q, 0.0)) + min(max(q.x, q.y), 0.0) - c;
}

// A rounded rectangle in XY (corners min(edge, H/2, L/2)) through the thickness; rim r = min(edge, T/2, H/2),
// or an L4 rim of the compensated radius when smooth.
float sdPill(vec3 p, vec3 size, float edge, bool squircle) {
  vec2 halfSize = 0.5 * size.xy;
  float corner = min(edge, min(halfSize.x, halfSize.y));
  float r = rimRadius(edge, min(0.5 * size.z, halfSize.y), squircle);
  float outline = sdRoundedRect(p.xy, halfSize, corner);
  vec2 w = vec2(outline + r, abs(p.z) - (0.5 * size.z - r));
  vec2 o = max(w, 0.0);
  return min(max(w.x, w.y), 0.0) + (squircle ? lengthL4(o) : length(o)) - r;
}

// Exact distance to an isosceles triangle in YZ (base size.y at z = -size.z/2, apex up), extruded along x.
float sdPrism(vec3 p, vec3 size) {
  float b = 0.5 * size.y, h = size.z;
  vec2 q = vec2(abs(p.y), p.z);
  vec2 corner = vec2(b, -0.5 * h), slant = vec2(-b, h);
  vec2 toBase = q - vec2(clamp(q.x, 0.0, b), -0.5 * h);
  vec2 fromCorner = q - corner;
  vec2 toSlant = fromCorner - slant * clamp(dot(fromCorner, slant) / dot(slant, slant), 0.0, 1.0);
  bool inside = q.y > -0.5 * h && slant.x * fromCorner.y - slant.y * fromCorner.x > 0.0;
  float section = sqrt(min(dot(toBase, toBase), dot(toSlant, toSlant))) * (inside ? -1.0 : 1.0);
  vec2 w = vec2(section, abs(p.x) - 0.5 * size.x);
  return min(max(w.x, w.y), 0.0) + length(max(w, 0.0));
}

float sdRoundedBox(vec3 p, vec3 halfSize, float r, bool squircle) {
  vec3 q = abs(p) - (halfSize - r);
  vec3 o = max(q, 0.0);
  return (squircle ? lengthL4(o) : length(o)) + min(max(q.x, max(q.y, q.z)), 0.0) - r;
}

float sdCube(vec3 p, vec4 sizeEdge, bool squircle) {
  vec3 halfSize = 0.5 * sizeEdge.xyz;
  return sdRoundedBox(p, halfSize, rimRadius(sizeEdge.w, min(halfSize.x, min(halfSize.y, halfSize.z)), squircle), squircle);
}

float plateHeight(vec2 xy, vec4 wave) {
  float k = TWO_PI / wave.y;
  return wave.x * sin(k * xy.x + wave.z) * sin(k * xy.y + wave.z);
}

vec2 plateSlope(vec2 xy, vec4 wave) {
  float k = TWO_PI / wave.y;
  float sx = sin(k * xy.x + wave.z), sy = sin(k * xy.y + wave.z);
  return wave.x * k * vec2(cos(k * xy.x + wave.z) * sy, sx * cos(k * xy.y + wave.z));
}

// The sheared box's largest Jacobian singular value for slopes up to A·k: dividing by it keeps a Lipschitz-1 bound.
float plateLipschitz(vec4 wave) {
  float s = abs(wave.x) * TWO_PI / wave.y;
  return sqrt(1.0 + 0.5 * s * s + s * sqrt(1.0 + 0.25 * s * s));
}

float sdPlate(vec3 p, vec4 sizeEdge, vec4 wave) {
  vec3 halfSize = 0.5 * sizeEdge.xyz;
  bool squircle = wave.w > 0.5;
  float r = rimRadius(sizeEdge.w, min(halfSize.z, min(halfSize.x, halfSize.y)), squircle);
  vec3 q = vec3(p.xy, p.z - plateHeight(p.xy, wave));
  return sdRoundedBox(q, halfSize, r, squircle) / plateLipschitz(wave);
}

float shapeSdf(GlassShapeDims s, vec3 p) {
  if (s.kind == SHAPE_PILL) return sdPill(p, s.sizeEdge.xyz, s.sizeEdge.w, s.wave.w > 0.5);
  if (s.kind == SHAPE_PRISM) return sdPrism(p, s.sizeEdge.xyz);
  if (s.kind == SHAPE_CUBE) return sdCube(p, s.sizeEdge, s.wave.w > 0.5);
  if (s.kind == SHAPE_PLATE) return sdPlate(p, s.sizeEdge, s.wave);
  return diamondSdf(p);
}

// Outward unit normal: central differences; the diamond's exact facet normal.
vec3 shapeNormal(GlassShapeDims s, vec3 p) {
  if (s.kind == SHAPE_DIAMOND) {
    int facet;
    return diamondNormal(p, facet);
  }
  float h = NORMAL_STEP * shapeScale(s);
  vec3 g = vec3(shapeSdf(s, p + vec3(h, 0.0, 0.0)) - shapeSdf(s, p - vec3(h, 0.0, 0.0)),
                shapeSdf(s, p + vec3(0.0, h, 0.0)) - shapeSdf(s, p - vec3(0.0, h, 0.0)),
                shapeSdf(s, p + vec3(0.0, 0.0, h)) - shapeSdf(s, p - vec3(0.0, 0.0, h)));
  float size = length(g);
  return size > 1e-20 ? g / size : vec3(0.0, 0.0, 1.0);  // the centre has no preferred normal
}

// Half size of the object-space box around the shape: the proxy box.
vec3 shapeHalfExtent(GlassShapeDims s) {
  vec3 halfSize = 0.5 * s.sizeEdge.xyz;
  if (s.kind == SHAPE_PILL) return vec3(max(halfSize.x, halfSize.y), halfSize.y, halfSize.z);
  if (s.kind == SHAPE_PLATE) return vec3(halfSize.xy, halfSize.z + abs(s.wave.x));
  if (s.kind == SHAPE_DIAMOND)
    return vec3(diamond.girdleRadius, diamond.girdleRadius, max(diamond.tableHeight, diamond.culetDepth));
  return halfSize;
}

// 1 / v with zero components replaced by a tiny number, so slab tests need no special cases.
vec3 shapeInverse(vec3 v) { return 1.0 / mix(v, vec3(1e-20), lessThan(abs(v), vec3(1e-20))); }

// The stretch [t0, t1] of the ray inside the box |p| <= halfSize.
bool shapeBoxRange(vec3 ro, vec3 rd, vec3 halfSize, out float t0, out float t1) {
  vec3 inv = shapeInverse(rd);
  vec3 a = (-halfSize - ro) * inv, b = (halfSize - ro) * inv;
  vec3 lo = min(a, b), hi = max(a, b);
  t0 = max(lo.x, max(lo.y, lo.z));
  t1 = min(hi.x, min(hi.y, hi.z));
  return t0 <= t1;
}

// Exit from inside the rectangle of half size halfSize with corners rounded by c, in XY (d.xy need not be
// unit): the rectangle's exit, unless it lands in a corner's square: then that corner disc's far root.
float roundedRectExit(vec2 p, vec2 d, vec2 halfSize, float c) {
  if (dot(d, d) < 1e-12) return SHAPE_FAR;
  vec2 inv = 1.0 / mix(d, vec2(1e-20), lessThan(abs(d), vec2(1e-20)));
  vec2 far = max((-halfSize - p) * inv, (halfSize - p) * inv);
  float t = min(far.x, far.y);
  vec2 at = p + t * d, inner = halfSize - c;
  if (abs(at.x) <= inner.x || abs(at.y) <= inner.y) return t;  // through a straight side
  vec2 o = p - vec2(at.x > 0.0 ? inner.x : -inner.x, at.y > 0.0 ? inner.y : -inner.y);
  float qa = dot(d, d), qb = dot(o, d), qc = dot(o, o) - c * c;
  return (-qb + sqrt(max(qb * qb - qa * qc, 0.0))) / qa;
}

float slabExit(float p, float d, float halfSize) {
  return abs(d) < 1e-12 ? SHAPE_FAR : ((d > 0.0 ? halfSize : -halfSize) - p) / d;
}

// Newton on f(t) = sdf(p + t·d) from a t at or past the surface: monotone onto the exit for a convex f.
float refineExit(GlassShapeDims s, vec3 p, vec3 d, float t, int steps) {
  float h = NORMAL_STEP * shapeScale(s);
  for (int i = 0; i < steps; ++i) {
    float f = shapeSdf(s, p + t * d);
    float slope = (shapeSdf(s, p + (t + h) * d) - shapeSdf(s, p + (t - h) * d)) / (2.0 * h);
    if (slope < 1e-3) break;  // grazing: a Newton step would fly off
    t = max(t - f / slope, 0.0);
  }
  return t;
}

// The plate's face z = h(x, y) + offset along the ray: tangent-plane seed, then 3 Newton iterations.
float plateFaceExit(vec3 p, vec3 d, vec4 wave, float offset, float tolerance) {
  float t = 0.0;
  for (int i = 0; i < 4; ++i) {
    vec3 q = p + t * d;
    float g = q.z - plateHeight(q.xy, wave) - offset;
    float slope = d.z - dot(plateSlope(q.xy, wave), d.xy);
    if (abs(slope) < 1e-6) return SHAPE_FAR;
    t -= g / slope;
  }
  vec3 q = p + t * d;
  bool settled = abs(q.z - plateHeight(q.xy, wave) - offset) < tolerance;
  return t > 0.0 && settled ? t : SHAPE_FAR;
}

vec4 prismPlane(vec3 size, int i) {
  float b = 0.5 * size.y, h = size.z, slant = sqrt(h * h + b * b);
  if (i == 0) return vec4(1.0, 0.0, 0.0, 0.5 * size.x);
  if (i == 1) return vec4(-1.0, 0.0, 0.0, 0.5 * size.x);
  if (i == 2) return vec4(0.0, 0.0, -1.0, 0.5 * h);
  if (i == 3) return vec4(0.0, h / slant, b / slant, 0.5 * b * h / slant);
  return vec4(0.0, -h / slant, b / slant, 0.5 * b * h / slant);
}

// Front hit from outside: sphere tracing from the bounding box (analytic for the diamond). facet: the
// diamond's entry facet, -1 for the other shapes.
bool shapeEnter(GlassShapeDims s, vec3 ro, vec3 rd, out float t, out vec3 n, out int facet) {
  if (s.kind == SHAPE_DIAMOND) return diamondEnter(ro, rd, t, n, facet);
  facet = -1;
  t = 0.0;
  n = vec3(0.0, 0.0, 1.0);
  float tolerance = HIT_TOLERANCE * shapeScale(s);
  float t0, t1;
  if (!shapeBoxRange(ro, rd, shapeHalfExtent(s) + tolerance, t0, t1) || t1 < 0.0) return false;
  t = max(t0, 0.0);
  for (int i = 0; i < MARCH_STEPS && t <= t1; ++i) {
    float d = shapeSdf(s, ro + t * rd);
    if (d < tolerance) {
      n = shapeNormal(s, ro + t * rd);
      return true;
    }
    t += d;
  }
  return false;
}

// Back exit from inside along unit d, analytic for every shape; n is the outward unit normal at the exit.
bool shapeExit(GlassShapeDims s, vec3 p, vec3 d, out float t, out vec3 n, out int facet) {
  facet = -1;
  n = vec3(0.0, 0.0, 1.0);
  vec3 size = s.sizeEdge.xyz;
  if (s.kind == SHAPE_DIAMOND) return diamondExit(p, d, t, n, facet);
  if (s.kind == SHAPE_PRISM) {
    t = SHAPE_FAR;
    for (int i = 0; i < 5; ++i) {
      vec4 plane = prismPlane(size, i);
      float along = dot(plane.xyz, d);
      if (along <= 1e-8) continue;
      float ti = max((plane.w - dot(plane.xyz, p)) / along, 0.0);
      if (ti < t) {
        t = ti;
        n = plane.xyz;
      }
    }
    return t < SHAPE_FAR;
  }
  // A sharp shape holding this one gives the seed; Newton steps land it on the rounded surface.
  float seed;
  int steps;
  if (s.kind == SHAPE_PILL) {
    vec2 halfSize = 0.5 * size.xy;
    float corner = min(s.sizeEdge.w, min(halfSize.x, halfSize.y));
    seed = min(roundedRectExit(p.xy, d.xy, halfSize, corner), slabExit(p.z, d.z, 0.5 * size.z));
    steps = s.wave.w > 0.5 ? 6 : 4;  // the L4 rim's larger radius leaves the seed further out
  } else if (s.kind == SHAPE_CUBE) {
    float t0;
    shapeBoxRange(p, d, 0.5 * size, t0, seed);
    steps = s.wave.w > 0.5 ? 6 : 4;
  } else {  // plate: the vertical rim or a wavy face, then onto the rounded rim
    float tolerance = 1e-4 * shapeScale(s);
    float side = min(slabExit(p.x, d.x, 0.5 * size.x), slabExit(p.y, d.y, 0.5 * size.y));
    float top = plateFaceExit(p, d, s.wave, 0.5 * size.z, tolerance);
    float bottom = plateFaceExit(p, d, s.wave, -0.5 * size.z, tolerance);
    seed = min(side, min(top, bottom));
    steps = s.wave.w > 0.5 ? 3 : 2;
  }
  if (!(seed < SHAPE_FAR)) return false;
  t = refineExit(s, p, d, seed, steps);
  n = shapeNormal(s, p + t * d);
  return true;
}

#endif
