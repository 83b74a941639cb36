// The text pass's blocks, one declaration for both sides: src/text/text_pass.cpp fills them, text.comp
// reads them (shaders/common/interop.h says how). Draws, glyphs and tiles are std430 arrays.
#ifndef TEXT_BLOCKS_H
#define TEXT_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct TextPassPush {
  uint firstTile;   // this dispatch's first tile in the batch's list: one workgroup a tile
  uint tileCount;
  float sdfEdge;    // the atlas's texel value on the outline
  float emPerUnit;  // em of signed distance per unit of texel value
};

// One draw of a batch.
struct TextPassDraw {
  vec4 color;         // linear rgb, alpha * opacity (straight)
  vec3 glowColor;     // rgb * opacity
  float glowRadius;   // pixels; 0: no glow
  vec2 origin;        // the layout's origin in target pixels
  float pixelsPerEm;
  float revealed;     // glyphs shown, in reading order; the one at the front fades in over its share
  ivec2 boxMin;       // the pixels this draw may change: [boxMin, boxMax)
  ivec2 boxMax;
  uint firstGlyph;    // in the glyph array
  uint glyphCount;
  float halfEdge;     // half the anti-aliased edge, in pixels
  float unused;       // std430 steps an array of draws in whole vec4s (80 bytes)
};

// One glyph of a draw's layout.
struct TextPassGlyph {
  vec2 emMin;  // its quad, in em from the draw's origin
  vec2 emMax;
  vec2 uvMin;  // its texels in the atlas
  vec2 uvMax;
};

// One 16x16 tile some draws of a batch touch: one workgroup blends them all.
struct TextPassTile {
  uint position;   // in tiles: x | y << 16
  uint drawMask;   // bit i: the batch's draw i touches the tile
  uint firstDraw;  // the batch's first draw in the draw array
};
VITRINE_SHARED_END

#endif
