// The push blocks of the glass scene's screen passes, one declaration for both sides
// (shaders/common/interop.h says how): compose_pass.cpp and resolve_pass.cpp fill them, compose.comp and
// resolve.comp read them; post.comp's two options are its specialization constant's bits.
#ifndef GLASS_PASS_PUSH_H
#define GLASS_PASS_PUSH_H
#include "../common/interop.h"

// GlassComposePush::source
#define GLASS_SOURCE_GRADIENT 0
#define GLASS_SOURCE_CHECKER 1
#define GLASS_SOURCE_PHOTO 2

// post.comp's specialization constant 0 (GLASS_POST_OPTIONS): each combination is its own pipeline, as
// llvmpipe pays for the paths a uniform branch does not take (docs/PERFORMANCE.md, glass, Decisions).
#define GLASS_POST_FXAA 1u    // FXAA after the tone map
#define GLASS_POST_FILMIC 2u  // physical optics' filmic roll-off; without it, the seed's clip at 1

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

VITRINE_SHARED_END

#endif
