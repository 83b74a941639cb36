// An output's warp as the present pass reads it (src/maths/output_warp.h says what each part does), one
// declaration for both sides: host/scene_renderer.cpp fills it from maths::warpMatrices.
#ifndef HOST_OUTPUT_WARP_H
#define HOST_OUTPUT_WARP_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct HostOutputWarp {
  vec4 unpin0;       // rows of the pin's inverse (xyz): output position -> the picture's square
  vec4 unpin1;
  vec4 unpin2;
  vec4 sourceU;      // rows of the picture's square -> the frame (xyz): the turn, mirror and region
  vec4 sourceV;
  vec4 blendWidths;  // left, top, right, bottom, as fractions of the picture
  vec4 blendCurve;   // x: the ramp's exponent, y: the projector's gamma
};
VITRINE_SHARED_END

#endif
