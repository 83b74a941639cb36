#version 460
// Type over the target (src/text/text_pass.cpp): one workgroup per 16x16 tile that some draw's box
// touches; each pixel blends, in order, every draw of the tile's mask. Coverage comes from the glyphs'
// signed distance fields with an edge of fixed width in target pixels (the pixels per em are known),
// a glow is additive light outside the outline. Pixels nothing reaches are not written.
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, rgba16f) uniform image2D target;
layout(binding = 1) uniform sampler2D atlas;

struct Draw {
  vec4 color;    // linear rgb, alpha * opacity (straight)
  vec4 glow;     // rgb * opacity, radius in pixels (0: none)
  vec4 place;    // origin in pixels, pixels per em, glyphs revealed
  ivec4 box;     // x0, y0, x1, y1
  uvec4 glyphs;  // first, count
  vec4 edge;     // half edge width in pixels
};
struct Glyph {
  vec4 rect;  // em from the origin: min, max
  vec4 uv;    // atlas: min, max
};
layout(std430, binding = 2) readonly buffer Draws { Draw draws[]; };
layout(std430, binding = 3) readonly buffer Glyphs { Glyph glyphs[]; };
layout(std430, binding = 4) readonly buffer Tiles { uvec4 tiles[]; };  // x | y << 16, draw mask, first draw

layout(push_constant) uniform Push {
  uint firstTile;
  uint tileCount;
  float sdfEdge;    // texel value on the outline
  float emPerUnit;  // em of signed distance per unit of texel value
} pc;

void main() {
  if (gl_WorkGroupID.x >= pc.tileCount) return;
  uvec4 tile = tiles[pc.firstTile + gl_WorkGroupID.x];
  ivec2 pixel = ivec2(tile.x & 0xffffu, tile.x >> 16) * 16 + ivec2(gl_LocalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(target)))) return;
  vec2 p = vec2(pixel) + 0.5;

  vec4 dst = vec4(0.0);
  bool loaded = false;
  uint mask = tile.y;
  while (mask != 0u) {
    int bit = findLSB(mask);
    mask &= mask - 1u;
    Draw d = draws[tile.z + uint(bit)];
    if (any(lessThan(pixel, d.box.xy)) || any(greaterThanEqual(pixel, d.box.zw))) continue;
    vec2 em = (p - d.place.xy) / d.place.z;
    float pxPerUnit = pc.emPerUnit * d.place.z;
    float fill = 0.0, glow = 0.0;
    for (uint i = 0u; i < d.glyphs.y; ++i) {
      float shown = clamp(d.place.w - float(i), 0.0, 1.0);
      if (shown <= 0.0) break;  // glyphs are revealed in order
      Glyph g = glyphs[d.glyphs.x + i];
      if (any(lessThan(em, g.rect.xy)) || any(greaterThanEqual(em, g.rect.zw))) continue;
      vec2 uv = mix(g.uv.xy, g.uv.zw, (em - g.rect.xy) / (g.rect.zw - g.rect.xy));
      float dist = (textureLod(atlas, uv, 0.0).r - pc.sdfEdge) * pxPerUnit;  // pixels, + inside
      fill = max(fill, shown * smoothstep(-d.edge.x, d.edge.x, dist));
      if (d.glow.w > 0.0) {
        float t = clamp(-dist / d.glow.w, 0.0, 1.0);
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
    dst.rgb += d.glow.rgb * glow;
    dst.rgb = mix(dst.rgb, d.color.rgb, alpha);
    dst.a = alpha + dst.a * (1.0 - alpha);
  }
  if (loaded) imageStore(target, pixel, dst);
}
