// This frame's shape, from the frame block (glass/frame_block.h) into shapes.glsl's terms.
#ifndef GLASS_INSTANCE_GLSL
#define GLASS_INSTANCE_GLSL
#define DIAMOND_BINDING 3
#include "glass/frame.glsl"
#include "glass/shapes.glsl"

// The shape is a specialization constant: each shape's pipeline keeps only its own code paths.
layout(constant_id = 0) const int GLASS_SHAPE = SHAPE_CUBE;

GlassShapeDims glassDims() {
  const vec4 wave = vec4(F.waveAmplitude, F.waveLength, F.wavePhase, float(F.smoothCurvature));
  return GlassShapeDims(vec4(F.shapeSize, F.shapeEdge), wave, GLASS_SHAPE, 0, 0, 0);
}

#endif
