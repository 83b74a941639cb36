// The diffusion step's push block, one declaration for both sides: bloom_scene.cpp (and the GPU test
// against the CPU reference) fills it, diffuse.comp reads it (shaders/common/interop.h says how).
#ifndef BLOOM_DIFFUSE_PUSH_H
#define BLOOM_DIFFUSE_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
const uint kBloomDiffuseColumn = 8;   // voxels along z one diffusion invocation walks

// One pass: a stage of a super step (bloom_math.h: StageWeights, stageVoxel).
struct BloomDiffusePush {
  vec3 source;       // the vapour source's centre, voxel coordinates
  float diffusion;   // D, voxels^2 / s
  float decay;       // per second
  float dt;          // the stage's weight times its super step, seconds
  float sigma;       // the source's radius, voxels
  float sourceRate;  // per second at the source's centre; 0: no source
  float keep;        // the weight of the voxel's value
  float older;       // the weight of the stage before's; 0: not read
  uint last;         // 1: a super step's last stage, which clamps
  uint side;         // the lattice's side n (n^3 voxels)
};

// A new lattice's contents (fill.comp): `fill` inside the crystal; outside stays the host's zeros.
struct BloomFillPush {
  float fill;
  uint side;
};

// resample.comp: the side of the lattice it writes.
struct BloomResamplePush {
  uint side;
};
VITRINE_SHARED_END

#endif
