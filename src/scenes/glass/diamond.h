#pragma once
// The round brilliant diamond: its 57 facet planes derived from Tolkowsky-ideal proportions and a tight
// convex hull for the rasterised proxy. The ray-polytope queries are in diamond_rays.h, the interior bounce
// walk (the sparkle) in diamond_walk.h; shaders/glass/diamond.glsl mirrors them, reading the planes from a
// storage buffer filled with diamondBlock, so the host and the GPU use the same numbers.
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
#include <string>
#include <vector>

namespace vitrine::glass {

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

// How far inside a facet, as a share of the girdle radius, a point must lie to count as on it and off its
// edges: the edge neighbours are found with it, and diamondExitThrough (diamond_rays.h) trusts a guess only past it.
inline const float kEdgeMargin = shader::kGlassEdgeMargin;

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

}  // namespace vitrine::glass
