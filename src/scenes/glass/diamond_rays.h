#pragma once
// Rays against the round brilliant (diamond.h): the distance bound, the facet normal, the entry from
// outside and the exit from inside, mirrored by shaders/glass/diamond.glsl. Object space; d is a unit
// direction.
#include "scenes/glass/diamond.h"

#include <glm/vec3.hpp>

#include <limits>

namespace vitrine::glass {

inline constexpr float kInf = std::numeric_limits<float>::infinity();  // no hit, or no bound

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
bool diamondExitThrough(const DiamondGeometry& g, glm::vec3 p, glm::vec3 d, int facet, float& t, glm::vec3& n);

}  // namespace vitrine::glass
