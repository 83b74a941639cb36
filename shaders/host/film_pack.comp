#version 460
// A film's frame into the bytes its encoder takes, on the sRGB curve: each channel's half-float bits
// index a table the host made with the PNG writer's own conversion (image_io's srgb8 and srgb16), so
// the bytes are exactly those the CPU made from the read-back frame, at a fraction of the bytes read
// back. Alpha is dropped: a film is opaque.
#extension GL_GOOGLE_include_directive : require
#include "film_pack_blocks.h"
layout(local_size_x = 64) in;
layout(binding = 0, rgba16f) uniform readonly image2D frame;
// Per half-float bit pattern: the 16-bit display value in the low half, the 8-bit one above it.
layout(binding = 1, std430) readonly buffer SrgbTable { uint srgb[]; };
layout(binding = 2, std430) writeonly buffer Packed { uint words[]; };
layout(push_constant) uniform Push { HostFilmPackPush pc; };

// Pixel `p` (row-major, top row first) as display values; past the last pixel, black.
uvec3 display(uint p, bool deep) {
  if (p >= pc.width * pc.height) return uvec3(0u);
  vec3 linear = imageLoad(frame, ivec2(p % pc.width, p / pc.width)).rgb;
  uvec3 bits = uvec3(packHalf2x16(vec2(linear.r, 0.0)), packHalf2x16(vec2(linear.g, 0.0)),
                     packHalf2x16(vec2(linear.b, 0.0))) & 0xffffu;
  uvec3 entry = uvec3(srgb[bits.r], srgb[bits.g], srgb[bits.b]);
  return deep ? (entry & 0xffffu) : (entry >> 16u);
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.groups) return;
  if (pc.packing == FILM_PACK_BGR0) {
    uvec3 c = display(i, false);
    words[i] = c.b | (c.g << 8u) | (c.r << 16u);
  } else if (pc.packing == FILM_PACK_RGB0) {
    uvec3 c = display(i, false);
    words[i] = c.r | (c.g << 8u) | (c.b << 16u);
  } else if (pc.packing == FILM_PACK_RGB24) {
    uvec3 a = display(i * 4u, false), b = display(i * 4u + 1u, false);
    uvec3 c = display(i * 4u + 2u, false), d = display(i * 4u + 3u, false);
    words[i * 3u] = a.r | (a.g << 8u) | (a.b << 16u) | (b.r << 24u);
    words[i * 3u + 1u] = b.g | (b.b << 8u) | (c.r << 16u) | (c.g << 24u);
    words[i * 3u + 2u] = c.b | (d.r << 8u) | (d.g << 16u) | (d.b << 24u);
  } else {
    uvec3 a = display(i * 2u, true), b = display(i * 2u + 1u, true);
    words[i * 3u] = a.r | (a.g << 16u);
    words[i * 3u + 1u] = a.b | (b.r << 16u);
    words[i * 3u + 2u] = b.g | (b.b << 16u);
  }
}
