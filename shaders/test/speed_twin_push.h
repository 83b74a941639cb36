// Test-only: speed_twin.vert/.frag's push block (tests/gpu/isf_piece_test.cpp, IsfPiece's speed check).
#ifndef TEST_SPEED_TWIN_PUSH_H
#define TEST_SPEED_TWIN_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct TestSpeedTwinPush {
  vec2 renderSize;  // pixels
  float time;       // seconds, ISF's TIME
  float zoom;       // the ISF file's input of that name
};
VITRINE_SHARED_END

#endif
