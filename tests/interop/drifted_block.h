// A shared block whose C++ side has drifted from its shader (tests/interop/drifted_block.comp): the
// shader's std430 puts `tint` at byte 16 (a vec3 aligns to 16), C++ at byte 12. The build-time check
// (tools/block_layouts.cpp) must refuse it, naming the shader and the member.
#ifndef DRIFTED_BLOCK_H
#define DRIFTED_BLOCK_H
#include "../../shaders/common/interop.h"

VITRINE_SHARED_BEGIN
struct DriftedBlock {
  vec3 origin;
  vec3 tint;
  float weight;
};
VITRINE_SHARED_END

#endif
