// The integrate pass's push block, one declaration for both sides: integrate_pass.cpp fills it,
// integrate.comp reads it (shaders/common/interop.h says how one header serves GLSL and C++). The tangent
// and the frames are not here: they specialise the pipeline, as the field and the integrator do for
// integrate.comp (integrate_strands.glsl).
// std430: each vec3 starts a 16-byte slot, which the 4-byte member after it shares.
#ifndef NOODLES_INTEGRATE_PUSH_H
#define NOODLES_INTEGRATE_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct NoodlesIntegratePush {
  vec3 offsetY;            // second noise potential's offset, drift included
  float spacing;           // between neighbouring strand starts
  vec3 offsetZ;            // third noise potential's offset, drift included
  float step;              // the integration step
  uvec3 grid;              // strands along x, y, z
  uint segmentsPerStrand;
  float noiseScale;
  float lift;              // uniform upward flow added to the field
  uint firstStrand;        // the chunk's first strand
  uint chunkStrands;       // strands in this chunk
  uint fieldKind;          // FIELD_CURL or FIELD_BITANGENT: integrate_baked.comp's (integrate.comp's is specialised)
  uint integrator;         // INTEGRATOR_EULER or INTEGRATOR_RK4: likewise
  uint invocationsPerRow;  // workgroups in x times their size, when the dispatch needs a second dimension
  uint pad0;               // the next vec3 starts a 16-byte slot
  vec3 bakeOrigin;          // integrate_baked.comp: world position of the baked flow's first texel centre
  float bakeInverseSpacing; // texels per world unit
  vec3 bakeLastTexel;       // the last texel's index along x, y, z
  float bakeRange;          // the volume's unorm 0..1 stands for -range..range
};

// bake.comp: the noise part of the flow (curl or bitangent, no lift) at every texel centre.
struct NoodlesBakePush {
  vec3 offsetY;  // as above
  float noiseScale;
  vec3 offsetZ;
  uint pad;      // the field specialises the pipeline (bake.comp); the next vec3 starts a 16-byte slot
  vec3 origin;  // world position of texel (0, 0, 0)'s centre
  float spacing;
  float range;  // a component v is stored as v / (2 range) + 0.5 (kBakeRange in field_bake.h)
};
VITRINE_SHARED_END

#endif
