// This frame's shape, from the frame block (src/scenes/glass/frame_block.h) into shapes.glsl's terms.
#ifndef GLASS_INSTANCE_GLSL
#define GLASS_INSTANCE_GLSL
#define DIAMOND_BINDING 3
#include "glass/frame.glsl"
#include "glass/shapes.glsl"

ShapeDims glassDims() { return ShapeDims(F.shapeSize, F.shapeWave, F.shape.x, 0, 0, 0); }

#endif
