#pragma once
// The round brilliant diamond: its 57 facet planes derived from Tolkowsky-ideal proportions, a tight convex
// hull for the rasterised proxy, the ray-polytope intersections and the interior bounce walk (the sparkle).
// shaders/glass/diamond.glsl mirrors the functions below; the shader reads the planes from a storage buffer
// filled with diamondBlock, so the host and the GPU use the same numbers.
//
// Object space: the stone's axis is z, the table on top (+z), the girdle band centred on z = 0.
// Facet indices: 0 table, 1-8 bezels, 9-16 stars, 17-32 upper girdle halves, 33-40 pavilion mains,
// 41-56 lower girdle halves; kGirdleFacet (57) is the girdle cylinder, which is no plane.
#include "shaders/glass/diamond_blocks.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace vitrine::glass {

inline constexpr float kInf = std::numeric_limits<float>::infinity();  // no hit, or no bound

inline constexpr int kDiamondPlanes = GLASS_DIAMOND_PLANES;
inline constexpr int kGirdleFacet = 57;

// The proportions (angles are facet inclinations to the girdle plane, in degrees).
inline constexpr float kTableRatio = 0.53f;       // table corner-to-corner width / girdle diameter
inline constexpr float kCrownAngle = 34.5f;       // bezels
inline constexpr float kPavilionAngle = 40.75f;   // pavilion mains
inline constexpr float kStarAngle = 22.0f;
inline constexpr float kUpperHalfAngle = 39.9f;
inline constexpr float kLowerHalfAngle = 42.0f;
inline constexpr float kGirdleRatio = 0.02f;      // girdle band thickness / diameter

enum class FacetKind { Table, Bezel, Star, UpperHalf, PavilionMain, LowerHalf, Girdle };

// Index k of each array runs with azimuth: mains (bezels, pavilion mains) sit at k·45°, stars at k·45° + 22.5°.
struct DiamondVertices {
  std::array<glm::vec3, 8> table;           // table octagon corners, at the mains' azimuths
  std::array<glm::vec3, 8> star;            // star points: where star k, bezels k and k+1 and two upper halves meet
  std::array<glm::vec3, 8> girdleTopMain;   // bezel k's bottom corner, on the girdle's top circle
  std::array<glm::vec3, 8> girdleTopStar;   // where the upper halves of pair k meet the girdle cylinder
  std::array<glm::vec3, 8> girdleBottomMain;  // pavilion main k's top corner
  std::array<glm::vec3, 8> girdleBottomStar;  // where the lower halves of pair k meet the girdle
  std::array<glm::vec3, 8> lowerTip;        // where mains k, k+1 and the lower halves of pair k meet
  glm::vec3 culet{};                        // the pointed bottom, where the eight mains meet
};

struct DiamondGeometry {
  float diameter = 0.0f;
  float girdleRadius = 0.0f;      // diameter / 2
  float girdleHalfHeight = 0.0f;  // the girdle band spans z in [-this, +this]
  float tableHeight = 0.0f;       // z of the table plane
  float culetDepth = 0.0f;        // the culet is at z = -culetDepth
  std::array<glm::vec4, kDiamondPlanes> planes{};  // xyz: unit outward normal n, w: offset d (n·p = d on the facet)
  // Bit j of facet i: plane j bounds facet i along an edge (bit kGirdleFacet: the girdle does), so a point of
  // plane i inside these alone is on the facet. diamondExitThrough tests a guessed exit with them.
  std::array<uint64_t, kDiamondPlanes> edgeNeighbours{};
  std::array<FacetKind, kDiamondPlanes> kinds{};
  std::array<std::string, kDiamondPlanes> names;
  DiamondVertices vertices;
};

DiamondGeometry makeDiamond(float diameter);
// makeDiamond's result for the last diameter asked on this thread: what shapeSdf & co. use on the CPU.
const DiamondGeometry& cachedDiamond(float diameter);

// The points each facet is constructed through (its corners; the upper halves' girdle corner lies on the cylinder).
std::vector<glm::vec3> diamondFacetCorners(const DiamondGeometry& g, int facet);

// The shader's DiamondPlanes block (shaders/glass/diamond_blocks.h): the 57 planes and the girdle.
shader::GlassDiamond diamondBlock(const DiamondGeometry& g);

// A convex hull around the stone for the proxy draw (78 triangles, 3.4 % more volume than the stone): the table
// octagon, the star points, one 16-gon ring around the girdle band, the lower-half tips and the culet.
// Counter-clockwise seen from outside, object space, three vertices per triangle.
std::vector<glm::vec3> diamondHullTriangles(const DiamondGeometry& g);

// --- Ray queries. The ray is in object space, d a unit direction.

// The polytope ∩ girdle cylinder as a distance bound: exact inside, a lower bound outside (max of plane terms).
float diamondSdf(const DiamondGeometry& g, glm::vec3 p);
// The outward normal of the facet whose term is largest at p (exact on a facet, no finite differences).
glm::vec3 diamondNormal(const DiamondGeometry& g, glm::vec3 p, int& facet);
// For a point on the surface, the distance along its facet to the nearest edge: the gap between the largest
// and the second-largest facet term (the girdle counts as one) over the sine of the angle between those two
// facets, the rate at which the gap grows along the first. The wireframe view draws where it is small.
float diamondEdgeDistance(const DiamondGeometry& g, glm::vec3 p);
// Front hit from outside: the last entering plane (or the girdle) before the first exiting one.
bool diamondEnter(const DiamondGeometry& g, glm::vec3 ro, glm::vec3 rd, float& t, glm::vec3& n, int& facet);
// Back exit from a point inside: the nearest plane (or girdle) the ray leaves through; n is the outward normal.
bool diamondExit(const DiamondGeometry& g, glm::vec3 p, glm::vec3 d, float& t, glm::vec3& n, int& facet);
// Whether the ray from p inside leaves through `facet` (a plane, not the girdle), tested against that facet's
// edge neighbours alone: a few planes instead of all 57. True only where the exit point lies inside the facet
// by more than kEdgeMargin of the radius, so near an edge, where rounding could pick either facet, the caller
// falls back to diamondExit. On true, t and n are diamondExit's.
inline const float kEdgeMargin = shader::kGlassEdgeMargin;
bool diamondExitThrough(const DiamondGeometry& g, glm::vec3 p, glm::vec3 d, int facet, float& t, glm::vec3& n);

// --- The interior walk: light that entered the stone, bouncing off facets until it leaves or the budget ends.
enum DiamondWalkStatus : int { kWalking = 0, kWalkDone = 1, kWalkExhausted = 2, kWalkMissed = 3 };

// The facets a walk left through, leg by leg, a byte each for its first kRouteLegs legs (0xff: none). The
// wavelengths of one pixel mostly take the same route through the stone, so each walk first tries the
// previous wavelength's facet for a leg (diamondExitThrough) and searches all 57 only where that fails.
inline constexpr int kRouteLegs = shader::kGlassRouteLegs;
inline constexpr glm::uvec2 kNoRoute{0xffffffffu, 0xffffffffu};
int routeFacet(glm::uvec2 route, int leg);  // -1: no facet known for this leg
glm::uvec2 withRouteFacet(glm::uvec2 route, int leg, int facet);

struct DiamondWalk {
  glm::vec3 p{};            // where the ray is (on a facet after the first step)
  glm::vec3 d{};            // its unit direction, inside the stone
  float throughput = 1.0f;  // the share of the entering light still inside
  int facet = -1;           // the facet the ray last met (-1 at the start)
  int bounces = 0;          // internal reflections so far
  int status = kWalking;
  int maxBounces = 6;       // internal reflections allowed (the UI's 1-32)
  glm::uvec2 route = kNoRoute;  // in: the facets to try first; out: the facets this walk left through
};

DiamondWalk diamondWalkStart(glm::vec3 p, glm::vec3 d, float throughput, int maxBounces, glm::uvec2 route = kNoRoute);

// One leg of the walk: finds the next exit and splits the light there. eta = n_diamond / n_air at this
// wavelength. Seed mode (physical = false): leaves whole if it can refract out, else reflects whole (TIR).
// Physical mode: the exact Fresnel share R reflects on, 1 - R leaves. exitWeight is the light leaving now,
// along exitDir (a valid unit vector even when exitWeight is 0, so env(exitDir) never sees a NaN).
// Returns false once nothing more will leave: then status says why and throughput holds what is left inside.
bool diamondStep(const DiamondGeometry& g, DiamondWalk& w, float eta, bool physical, glm::vec3& exitDir,
                 float& exitWeight);

}  // namespace vitrine::glass
