// One glass shape's dimensions, one declaration for both sides (shaders/common/interop.h says how):
// src/scenes/glass/shapes.h makes them for the C++ reference (its ShapeDims), shapes.glsl measures
// with them, instance.glsl builds this frame's from the frame block, and the diamond probe's test
// uploads an array of them. 48 bytes in std140 and std430 alike.
#ifndef GLASS_SHAPE_DIMS_H
#define GLASS_SHAPE_DIMS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// The packed vec4s are the maths' own arguments (shapes.glsl and shapes.h pass `wave` to the plate's
// functions whole), so they stay packed here; the frame block carries them as named fields.
struct GlassShapeDims {
  vec4 sizeEdge;  // xyz: the size along x, y, z; w: the edge rounding radius (pill, cube, plate)
  vec4 wave;      // plate: amplitude, wavelength, phase (radians); w: 1 for smooth curvature (pill, cube, plate)
  int kind;       // a ShapeKind (SHAPE_* in shapes.glsl)
  int pad0;       // 0: the struct fills three 16-byte slots in either layout
  int pad1;
  int pad2;
};
VITRINE_SHARED_END

#endif
