// The bloom chain's two filters (dual filtering, as in Jimenez's "Next generation post processing in
// Call of Duty: Advanced Warfare", 2014), shared by bloom_down.comp, bloom_up.comp and composite.comp.
#ifndef NEON_BLOOM_GLSL
#define NEON_BLOOM_GLSL

// Halves the resolution. `uv` is an output pixel's centre, which lies on a corner between four source
// texels, so every bilinear tap below averages a 2x2 block: 13 taps cover a 6x6 footprint. Five
// overlapping 4x4 boxes are weighted 1/2 (the centre one) and 1/8 each (the four corner ones): wide
// enough that a one-pixel neon line never falls between taps and shimmers as it moves, which a plain
// 2x2 box would let it do.
vec3 downsample13(sampler2D source, vec2 uv, vec2 texel, float lod) {
  vec3 a = textureLod(source, uv + texel * vec2(-2.0, -2.0), lod).rgb;
  vec3 b = textureLod(source, uv + texel * vec2(0.0, -2.0), lod).rgb;
  vec3 c = textureLod(source, uv + texel * vec2(2.0, -2.0), lod).rgb;
  vec3 d = textureLod(source, uv + texel * vec2(-1.0, -1.0), lod).rgb;
  vec3 e = textureLod(source, uv + texel * vec2(1.0, -1.0), lod).rgb;
  vec3 f = textureLod(source, uv + texel * vec2(-2.0, 0.0), lod).rgb;
  vec3 g = textureLod(source, uv, lod).rgb;
  vec3 h = textureLod(source, uv + texel * vec2(2.0, 0.0), lod).rgb;
  vec3 i = textureLod(source, uv + texel * vec2(-1.0, 1.0), lod).rgb;
  vec3 j = textureLod(source, uv + texel * vec2(1.0, 1.0), lod).rgb;
  vec3 k = textureLod(source, uv + texel * vec2(-2.0, 2.0), lod).rgb;
  vec3 l = textureLod(source, uv + texel * vec2(0.0, 2.0), lod).rgb;
  vec3 m = textureLod(source, uv + texel * vec2(2.0, 2.0), lod).rgb;
  // Each corner box has four taps, so its 1/8 becomes 1/32 a tap (and taps shared by two or four boxes
  // add up); the centre box's 1/2 becomes 1/8 a tap.
  return (d + e + i + j) * 0.125 + (a + c + k + m) * 0.03125 + (b + f + h + l) * 0.0625 + g * 0.125;
}

// Doubles the resolution smoothly: a 3x3 tent (1 2 1 / 2 4 2 / 1 2 1, over 16) of bilinear taps
// `offset` apart (in uv). With offset = one output texel each tap lands between source texels and the
// result has no blocks, whatever the source's size.
vec3 upsampleTent(sampler2D source, vec2 uv, vec2 offset, float lod) {
  const vec2 dx = vec2(offset.x, 0.0), dy = vec2(0.0, offset.y);
  vec3 sum = textureLod(source, uv, lod).rgb * 4.0;
  sum += (textureLod(source, uv - dx, lod).rgb + textureLod(source, uv + dx, lod).rgb) * 2.0;
  sum += (textureLod(source, uv - dy, lod).rgb + textureLod(source, uv + dy, lod).rgb) * 2.0;
  sum += textureLod(source, uv - dx - dy, lod).rgb + textureLod(source, uv + dx - dy, lod).rgb;
  sum += textureLod(source, uv - dx + dy, lod).rgb + textureLod(source, uv + dx + dy, lod).rgb;
  return sum * (1.0 / 16.0);
}

#endif
