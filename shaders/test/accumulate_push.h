// Test-only: accumulate.comp's push block, one declaration for the shader and the GPU tests that
// fill it (tests/gpu/frame_resources_test.cpp, crossfade_test.cpp).
#ifndef TEST_ACCUMULATE_PUSH_H
#define TEST_ACCUMULATE_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct TestAccumulatePush {
  float add;       // added to every channel
  uint useSource;  // non-zero: start from the source, sampled over the whole destination; else from 0
};
VITRINE_SHARED_END

#endif
