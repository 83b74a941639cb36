// The present pass's push block, one declaration for both sides: host/scene_renderer.cpp fills it,
// present.comp reads it (shaders/common/interop.h says how).
#ifndef HOST_PRESENT_PUSH_H
#define HOST_PRESENT_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct HostPresentPush {
  uint encodeSrgb;  // non-zero: a UNORM destination shown as sRGB, so the transfer function is applied here
  float fade;       // the incoming scene's weight, 0..1
};
VITRINE_SHARED_END

#endif
