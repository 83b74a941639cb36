#version 460
// Type over the target (src/text/text_pass.cpp): one workgroup per 16x16 tile that some draw's box
// touches; each pixel blends, in order, every draw of the tile's mask. Coverage comes from the glyphs'
// signed distance fields with an edge of fixed width in target pixels (the pixels per em are known),
// a glow is additive light outside the outline. Pixels nothing reaches are not written.
#extension GL_GOOGLE_include_directive : require
#include "text_blocks.h"
layout(local_size_x = 16, local_size_y = 16) in;  // TextPass::kTile on a side

layout(binding = 0, rgba16f) uniform image2D target;
layout(binding = 1) uniform sampler2D atlas;

layout(std430, binding = 2) readonly buffer Draws { TextPassDraw draws[]; };
layout(std430, binding = 3) readonly buffer Glyphs { TextPassGlyph glyphs[]; };
layout(std430, binding = 4) readonly buffer Tiles { TextPassTile tiles[]; };

layout(push_constant) uniform Push { TextPassPush pc; };

void main() {
  if (gl_WorkGroupID.x >= pc.tileCount) return;
  TextPassTile tile = tiles[pc.firstTile + gl_WorkGroupID.x];
  ivec2 pixel = ivec2(tile.position & 0xffffu, tile.position >> 16) * 16 + ivec2(gl_LocalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(target)))) return;
  vec2 p = vec2(pixel) + 0.5;

  vec4 dst = vec4(0.0);
  bool loaded = false;
  uint mask = tile.drawMask;
  while (mask != 0u) {
    int bit = findLSB(mask);
    mask &= mask - 1u;
    TextPassDraw d = draws[tile.firstDraw + uint(bit)];
    if (any(lessThan(pixel, d.boxMin)) || any(greaterThanEqual(pixel, d.boxMax))) continue;
    vec2 em = (p - d.origin) / d.pixelsPerEm;
    float pxPerUnit = pc.emPerUnit * d.pixelsPerEm;
    float fill = 0.0, glow = 0.0;
    for (uint i = 0u; i < d.glyphCount; ++i) {
      float shown = clamp(d.revealed - float(i), 0.0, 1.0);
      if (shown <= 0.0) break;  // glyphs are revealed in order
      TextPassGlyph g = glyphs[d.firstGlyph + i];
      if (any(lessThan(em, g.emMin)) || any(greaterThanEqual(em, g.emMax))) continue;
      vec2 uv = mix(g.uvMin, g.uvMax, (em - g.emMin) / (g.emMax - g.emMin));
      float dist = (textureLod(atlas, uv, 0.0).r - pc.sdfEdge) * pxPerUnit;  // pixels, + inside
      fill = max(fill, shown * smoothstep(-d.halfEdge, d.halfEdge, dist));
      if (d.glowRadius > 0.0) {
        float t = clamp(-dist / d.glowRadius, 0.0, 1.0);
        float halo = 1.0 - t * t * (3.0 - 2.0 * t);
        glow = max(glow, shown * halo * halo);
      }
    }
    float alpha = d.color.a * fill;
    if (alpha <= 0.0 && glow <= 0.0) continue;
    if (!loaded) {
      dst = imageLoad(target, pixel);
      loaded = true;
    }
    dst.rgb += d.glowColor * glow;
    dst.rgb = mix(dst.rgb, d.color.rgb, alpha);
    dst.a = alpha + dst.a * (1.0 - alpha);
  }
  if (loaded) imageStore(target, pixel, dst);
}
