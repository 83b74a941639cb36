// Test-only: invert_twin.frag's push block (tests/gpu/isf_filter_test.cpp, the filter's speed check).
#ifndef TEST_INVERT_TWIN_PUSH_H
#define TEST_INVERT_TWIN_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct TestInvertTwinPush {
  float amount;  // tests/isf/filter_invert.fs's input of that name
};
VITRINE_SHARED_END

#endif
