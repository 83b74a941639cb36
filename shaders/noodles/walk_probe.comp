#version 460
// Writes the chunk-local segment raster.comp's invocation i takes in the pushed walk and phase
// (raster_push.glsl's phaseSegment, through walkedStrand), so a test can hold the GLSL walk to its
// C++ mirror (src/scenes/noodles/strand_walk.h).
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster_push.glsl"

layout(local_size_x = 64) in;
layout(binding = 0, std430) writeonly buffer Segments { uint segments[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < phaseSegments()) segments[i] = phaseSegment(i);
}
