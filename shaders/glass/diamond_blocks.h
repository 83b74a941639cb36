// The diamond's buffers, one declaration for both sides (shaders/common/interop.h says how):
// src/scenes/glass/diamond_buffers.cpp declares them from makeDiamond's geometry (diamond.h) and
// redeclares them when the stone's size changes; diamond.glsl reads the planes, proxy.vert the hull.
#ifndef GLASS_DIAMOND_BLOCKS_H
#define GLASS_DIAMOND_BLOCKS_H
#include "../common/interop.h"

// Facets with a plane: 1 table, 8 bezels, 8 stars, 16 upper halves, 8 pavilion mains, 16 lower halves.
#define GLASS_DIAMOND_PLANES 57

VITRINE_SHARED_BEGIN
// A walk remembers the facets of its first kGlassRouteLegs legs for the next wavelength to try first, and a
// tried facet is accepted only where the exit lies inside it by kGlassEdgeMargin of the radius
// (src/scenes/glass/diamond.h: diamondExitThrough, routeFacet).
const int kGlassRouteLegs = 8;
const float kGlassEdgeMargin = 1e-5;
// The round brilliant for the shader's ray queries: the polytope of its facet planes cut by the
// girdle cylinder.
struct GlassDiamond {
  vec4 planes[GLASS_DIAMOND_PLANES];  // a facet's plane n·p = d: xyz the unit outward normal n, w the offset d
  // A facet's edge neighbours as a 64-bit mask (x the low word): bit j plane j, bit 57 the girdle
  // (DiamondGeometry::edgeNeighbours).
  uvec2 edgeNeighbours[GLASS_DIAMOND_PLANES];
  float girdleRadius;                 // the cylinder's radius: half the diameter
  float girdleHalfHeight;             // the girdle band spans z in [-this, +this]
  float tableHeight;                  // z of the table
  float culetDepth;                   // the culet is at z = -this
};

// One corner of the convex hull's triangles (78 of them, three corners each), the raster path's proxy.
struct GlassHullVertex {
  vec3 position;  // object space
  float pad;      // 0: in std430 each corner takes 16 bytes
};
VITRINE_SHARED_END

#endif
