// The round brilliant's ray queries, interior walk and debug colours; mirrors src/scenes/glass/diamond.h.
// The facet planes are not constants here: the host fills the DiamondPlanes block (glass/diamond_blocks.h)
// with diamondBlock (makeDiamond's planes for the stone's diameter), so the CPU reference and the GPU
// cannot drift apart.
// Define DIAMOND_BINDING, the block's binding in set 0, before including this file.
#ifndef GLASS_DIAMOND_GLSL
#define GLASS_DIAMOND_GLSL

#ifndef DIAMOND_BINDING
#error "define DIAMOND_BINDING (the binding of the diamond's planes in set 0) before including glass/diamond.glsl"
#endif

#include "glass/diamond_blocks.h"
#include "glass/optics.glsl"

// Facets: 0 table, 1-8 bezels, 9-16 stars, 17-32 upper halves, 33-40 pavilion mains, 41-56 lower halves.
const int DIAMOND_PLANES = GLASS_DIAMOND_PLANES;
const int GIRDLE_FACET = 57;

const int WALK_WALKING = 0;
const int WALK_DONE = 1;
const int WALK_EXHAUSTED = 2;
const int WALK_MISSED = 3;

const float DIAMOND_FAR = 1e30;
const uvec2 NO_ROUTE = uvec2(0xffffffffu);

layout(std430, set = 0, binding = DIAMOND_BINDING) readonly buffer DiamondPlanes { GlassDiamond diamond; };

// The polytope ∩ girdle cylinder: exact inside, a lower bound outside.
float diamondSdf(vec3 p) {
  float d = length(p.xy) - diamond.girdleRadius;
  for (int i = 0; i < DIAMOND_PLANES; ++i) d = max(d, dot(diamond.planes[i].xyz, p) - diamond.planes[i].w);
  return d;
}

// The outward normal of the facet whose term is largest at p: exact, no finite differences.
vec3 diamondNormal(vec3 p, out int facet) {
  float best = length(p.xy) - diamond.girdleRadius;
  facet = GIRDLE_FACET;
  for (int i = 0; i < DIAMOND_PLANES; ++i) {
    float d = dot(diamond.planes[i].xyz, p) - diamond.planes[i].w;
    if (d > best) {
      best = d;
      facet = i;
    }
  }
  return facet == GIRDLE_FACET ? normalize(vec3(p.xy, 0.0)) : diamond.planes[facet].xyz;
}

// For a point on the stone's surface, the distance along its facet to the nearest edge (the wireframe
// view): the gap between the largest and second-largest facet terms, over the sine of the angle
// between those two facets, since the second term grows at that rate along the first facet.
float diamondEdgeDistance(vec3 p) {
  float first = length(p.xy) - diamond.girdleRadius, second = -DIAMOND_FAR;
  vec3 n1 = vec3(normalize(p.xy + vec2(1e-20)), 0.0), n2 = n1;
  for (int i = 0; i < DIAMOND_PLANES; ++i) {
    float d = dot(diamond.planes[i].xyz, p) - diamond.planes[i].w;
    if (d > first) {
      second = first;
      n2 = n1;
      first = d;
      n1 = diamond.planes[i].xyz;
    } else if (d > second) {
      second = d;
      n2 = diamond.planes[i].xyz;
    }
  }
  return (first - second) / max(length(cross(n1, n2)), 1e-3);
}

// Front hit from outside: the last entering plane (or the girdle) before the first exiting one.
bool diamondEnter(vec3 ro, vec3 rd, out float t, out vec3 n, out int facet) {
  float tIn = -DIAMOND_FAR, tOut = DIAMOND_FAR;
  t = 0.0;
  n = vec3(0.0, 0.0, 1.0);
  facet = -1;
  for (int i = 0; i < DIAMOND_PLANES; ++i) {
    float along = dot(diamond.planes[i].xyz, rd), inside = diamond.planes[i].w - dot(diamond.planes[i].xyz, ro);
    if (abs(along) < 1e-8) {
      if (inside < 0.0) return false;  // parallel and outside this plane
      continue;
    }
    float s = inside / along;
    if (along < 0.0) {
      if (s > tIn) {
        tIn = s;
        facet = i;
      }
    } else {
      tOut = min(tOut, s);
    }
  }
  // The girdle cylinder: enter at the near root, leave at the far one.
  float a = dot(rd.xy, rd.xy), b = dot(ro.xy, rd.xy);
  float c = dot(ro.xy, ro.xy) - diamond.girdleRadius * diamond.girdleRadius;
  if (a < 1e-12) {
    if (c > 0.0) return false;
  } else {
    float disc = b * b - a * c;
    if (disc < 0.0) return false;
    float root = sqrt(disc);
    float tNear = (-b - root) / a, tFar = (-b + root) / a;
    if (tNear > tIn) {
      tIn = tNear;
      facet = GIRDLE_FACET;
    }
    tOut = min(tOut, tFar);
  }
  if (facet < 0 || tIn > tOut || tIn < 0.0) return false;  // missed, or the ray starts inside
  t = tIn;
  vec3 hit = ro + t * rd;
  n = facet == GIRDLE_FACET ? normalize(vec3(hit.xy, 0.0)) : diamond.planes[facet].xyz;
  return true;
}

// Back exit from inside: the nearest plane (or the girdle) the ray leaves through; n is the outward normal.
bool diamondExit(vec3 p, vec3 d, out float t, out vec3 n, out int facet) {
  t = DIAMOND_FAR;
  n = vec3(0.0, 0.0, 1.0);
  facet = -1;
  for (int i = 0; i < DIAMOND_PLANES; ++i) {
    float along = dot(diamond.planes[i].xyz, d);
    if (along <= 1e-8) continue;  // the ray does not leave through this plane
    // A point a rounding error outside the plane leaves at once (an edge hit), not behind itself.
    float s = max((diamond.planes[i].w - dot(diamond.planes[i].xyz, p)) / along, 0.0);
    if (s < t) {
      t = s;
      facet = i;
    }
  }
  // Leaving the cylinder is always at the far root, also from a point on it after a reflection there.
  float a = dot(d.xy, d.xy);
  if (a > 1e-12) {
    float b = dot(p.xy, d.xy), c = dot(p.xy, p.xy) - diamond.girdleRadius * diamond.girdleRadius;
    float s = max((-b + sqrt(max(b * b - a * c, 0.0))) / a, 0.0);
    if (s < t) {
      t = s;
      facet = GIRDLE_FACET;
    }
  }
  if (facet < 0 || !(t < DIAMOND_FAR)) return false;
  vec3 hit = p + t * d;
  n = facet == GIRDLE_FACET ? normalize(vec3(hit.xy, 0.0)) : diamond.planes[facet].xyz;
  return true;
}

// Whether the ray from p inside leaves through plane `facet`, tested against the facet's edge neighbours
// alone, and only where the exit lies inside the facet by a margin (diamond.h says why).
bool diamondExitThrough(vec3 p, vec3 d, int facet, out float t, out vec3 n) {
  const vec4 plane = diamond.planes[facet];
  n = plane.xyz;
  t = 0.0;
  const float along = dot(plane.xyz, d);
  if (along <= 1e-8) return false;
  t = max((plane.w - dot(plane.xyz, p)) / along, 0.0);
  const vec3 hit = p + t * d;
  const float margin = kGlassEdgeMargin * diamond.girdleRadius;
  uvec2 bounds = diamond.edgeNeighbours[facet];
  const uint girdleBit = 1u << (GIRDLE_FACET - 32);
  if ((bounds.y & girdleBit) != 0u && length(hit.xy) > diamond.girdleRadius - margin) return false;
  bounds.y &= ~girdleBit;
  for (int word = 0; word < 2; ++word) {
    uint bits = word == 0 ? bounds.x : bounds.y;
    while (bits != 0u) {
      const int j = findLSB(bits) + 32 * word;
      bits &= bits - 1u;
      if (dot(diamond.planes[j].xyz, hit) - diamond.planes[j].w > -margin) return false;
    }
  }
  return true;
}

// The facet a route (DiamondWalk.route) names for a leg, -1 for none; and the route with it set.
int routeFacet(uvec2 route, int leg) {
  if (leg >= kGlassRouteLegs) return -1;
  const uint facet = ((leg < 4 ? route.x : route.y) >> (8 * (leg & 3))) & 0xffu;
  return facet == 0xffu ? -1 : int(facet);
}

uvec2 withRouteFacet(uvec2 route, int leg, int facet) {
  if (leg >= kGlassRouteLegs) return route;
  const int shift = 8 * (leg & 3);
  const uint keep = ~(0xffu << shift), put = (uint(facet) & 0xffu) << shift;
  return leg < 4 ? uvec2((route.x & keep) | put, route.y) : uvec2(route.x, (route.y & keep) | put);
}

// Light inside the stone, from the front refraction on.
struct DiamondWalk {
  vec3 p;            // where the ray is (on a facet after the first step)
  vec3 d;            // its unit direction
  float throughput;  // the share of the entering light still inside
  int facet;         // the facet last met (-1 at the start)
  int bounces;       // internal reflections so far
  int status;        // WALK_*
  int maxBounces;    // internal reflections allowed (1-32)
  uvec2 route;       // in: the facets to try first, leg by leg (the previous wavelength's); out: this walk's
};

DiamondWalk diamondWalkStart(vec3 p, vec3 d, float throughput, int maxBounces, uvec2 route) {
  return DiamondWalk(p, d, throughput, -1, 0, WALK_WALKING, maxBounces, route);
}

// One leg: the next exit, and the split of the light there (eta = n_diamond / n_air at this wavelength).
// Seed mode leaves whole when it can refract, else reflects whole; physical mode leaves 1 - R (exact Fresnel)
// and reflects R. exitDir is a unit vector even at zero weight. Use as
//   while (diamondStep(w, eta, physical, dir, weight)) colour += weight * env(dir);
// after which w.status says why it ended and w.throughput is the light still inside.
bool diamondStep(inout DiamondWalk w, float eta, bool physical, out vec3 exitDir, out float exitWeight) {
  exitDir = w.d;
  exitWeight = 0.0;
  if (w.status != WALK_WALKING) return false;
  float t;
  vec3 n;
  // The last wavelength's facet for this leg first: tried on its few neighbours, it saves searching all 57.
  int facet = routeFacet(w.route, w.bounces);
  const bool followed = facet >= 0 && facet < DIAMOND_PLANES && diamondExitThrough(w.p, w.d, facet, t, n);
  if (!followed && !diamondExit(w.p, w.d, t, n, facet)) {
    w.status = WALK_MISSED;
    return false;
  }
  w.p += t * w.d;
  w.facet = facet;
  w.route = withRouteFacet(w.route, w.bounces, facet);
  // From inside to air: the normal facing the ray is -n, the index ratio 1 / eta.
  bool refracts;
  vec3 refracted = refractDir(w.d, -n, 1.0 / eta, refracts);
  vec3 reflected = reflectDir(w.d, n);
  float r = physical ? fresnelDielectric(dot(w.d, n), 1.0 / eta) : (refracts ? 0.0 : 1.0);
  exitDir = refracts ? refracted : reflected;
  exitWeight = w.throughput * (1.0 - r);
  w.throughput *= r;
  // Physical mode stops once what is left could not show; it stays in throughput, so the light still adds up.
  if (w.throughput <= (physical ? 1e-4 : 0.0)) {
    w.status = WALK_DONE;
  } else if (w.bounces >= w.maxBounces) {
    w.status = WALK_EXHAUSTED;
  } else {
    w.d = reflected;
    ++w.bounces;
    return true;
  }
  return exitWeight > 0.0;
}

// A debug colour per facet: hue by kind, alternate facets a shade darker so neighbours stand apart.
vec3 facetColour(int facet) {
  vec3 colour;
  if (facet == 0) colour = vec3(0.95, 0.95, 0.85);        // table
  else if (facet <= 8) colour = vec3(0.20, 0.45, 0.95);   // bezels
  else if (facet <= 16) colour = vec3(0.95, 0.80, 0.15);  // stars
  else if (facet <= 32) colour = vec3(0.15, 0.85, 0.80);  // upper halves
  else if (facet <= 40) colour = vec3(0.90, 0.25, 0.20);  // pavilion mains
  else if (facet <= 56) colour = vec3(0.85, 0.30, 0.85);  // lower halves
  else colour = vec3(0.5);                                 // girdle (or none)
  return (facet & 1) == 0 ? colour : 0.75 * colour;
}

#endif
