// The merge pass's push block, one declaration for both sides: neon_scene.cpp fills it, merge.comp
// reads it.
#ifndef NEON_MERGE_PUSH_H
#define NEON_MERGE_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct NeonMergePush {
  vec4 colours[3];  // the three neon colours, linear rgb (w unused): indexed by the nearest tube's colour
};
VITRINE_SHARED_END

#endif
