// The push blocks of the glass scene's screen passes, one declaration for both sides
// (shaders/common/interop.h says how): compose_pass.cpp, resolve_pass.cpp and post_pass.cpp fill them,
// compose.comp, resolve.comp and post.comp read them.
#ifndef GLASS_PASS_PUSH_H
#define GLASS_PASS_PUSH_H
#include "../common/interop.h"

// GlassComposePush::source
#define GLASS_SOURCE_GRADIENT 0
#define GLASS_SOURCE_CHECKER 1
#define GLASS_SOURCE_PHOTO 2

VITRINE_SHARED_BEGIN
// The backdrop: what to draw, and the page's paper under its text.
struct GlassComposePush {
  vec2 photoScale;   // the part of the photo the view shows, in uv (the photo covers the view)
  int source;        // GLASS_SOURCE_*
  uint paper;        // 1: the page's paper over the source, between paperLeft and paperRight
  float paperLeft;   // pixels
  float paperRight;
};

// How this frame joins the history.
struct GlassResolvePush {
  float alpha;        // the new frame's weight
  uint historyValid;  // 1: the history holds last frame
  uint reproject;     // 1: read the history where the surface was last frame; 0: where it is (the world stands)
};

// The accumulated picture to the output.
struct GlassPostPush {
  uint fxaa;         // 1: FXAA after the tone map
  uint filmicCurve;  // 1: physical optics' filmic roll-off; 0: the seed's clip at 1
};
VITRINE_SHARED_END

#endif
