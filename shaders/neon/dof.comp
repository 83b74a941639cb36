#version 460
// Depth of field as one gather ("scatter as gather"): a pixel takes in each nearby tap whose own circle
// of confusion reaches back to it. A tap further away than the centre may reach only as far as the
// centre's own circle, so a blurred background never spreads over a sharp foreground, while a blurred
// foreground does spread over a sharp background, as it does through a lens.
// The taps lie on two fixed golden-angle spirals: half fill the pixel's own circle (at least a pixel
// wide), so a small blur is as smooth as a large one; half fill the whole maxRadius disc, counted only
// outside the first, to find foreground that reaches in from further away. Each tap stands for the
// area it samples (in pixels, the centre pixel for itself), so the two densities add up fairly, and
// spreads its light over its own circle: a thin tube out of focus becomes a wide, dim band, not a bar.
// Depth and colour are read from the same texel, so a tap is never judged by one pixel's depth while
// showing its neighbour's colour (which would outline sharp edges).
// The spirals are the same every frame (unless `spin` turns them): a still camera gives a still picture.
// Its push block is neon/dof_push.h.
#extension GL_GOOGLE_include_directive : require
#include "neon/dof_push.h"
#include "neon/look.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D colour;                   // linear HDR; read with texelFetch
layout(set = 0, binding = 1) uniform sampler2D depth;                    // r32f reverse-Z; read with texelFetch
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D target;  // same size as colour
layout(push_constant) uniform Push { NeonDofPush pc; };

float coc(float d) { return circleOfConfusion(d, pc.near, pc.focalDistance, pc.aperture, pc.maxRadius); }

const float kPi = 3.14159265;
// The pixels a circle of confusion spreads one pixel's light over: at least the pixel itself.
float spread(float circle) { return max(kPi * circle * circle, 1.0); }
ivec2 size;
vec2 centre;
float centreCoc;
vec3 sum;
float weight;

// Takes in the tap `offset` pixels from the centre, standing for `area` pixels around it.
void gather(vec2 offset, float area, float rim) {
  const ivec2 texel = clamp(ivec2(floor(centre + offset)), ivec2(0), size - 1);
  const float tapCoc = coc(texelFetch(depth, texel, 0).r);
  // Signed circles order taps by depth: a larger one lies further away than the centre.
  const float reach = tapCoc > centreCoc ? min(abs(tapCoc), abs(centreCoc)) : abs(tapCoc);
  // A soft edge `rim` pixels wide centred on the circle's rim: a tap fades in as its circle grows past
  // it, so focus pulls are smooth. One pixel for the dense spiral, so a sharp pixel (circle 0) takes in
  // nothing beyond half a pixel; the sparse one's tap spacing, so a blur's edge has no steps.
  const float w = clamp((reach - length(offset)) / rim + 0.5, 0.0, 1.0) * area / spread(tapCoc);
  sum += texelFetch(colour, texel, 0).rgb * w;
  weight += w;
}

void main() {
  size = ivec2(pc.frameSize);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  centre = vec2(p) + 0.5;
  centreCoc = coc(texelFetch(depth, p, 0).r);
  weight = 1.0 / spread(centreCoc);
  sum = texelFetch(colour, p, 0).rgb * weight;

  // Both spirals start turned by `spin` and are walked tap by tap (look.glsl: nextHeading).
  const vec2 spun = vec2(cos(pc.spin), sin(pc.spin));
  const uint inner = pc.taps / 2u, outer = pc.taps - inner;
  const float ownRadius = clamp(abs(centreCoc), 1.0, pc.maxRadius);
  const float innerArea = kPi * ownRadius * ownRadius / float(max(inner, 1u));
  vec2 heading = spun;
  for (uint i = 0u; i < inner; ++i, heading = nextHeading(heading))
    gather(heading * (spiralRadius(i, inner) * ownRadius), innerArea, 1.0);
  const float outerArea = kPi * pc.maxRadius * pc.maxRadius / float(max(outer, 1u));
  const float spacing = max(sqrt(outerArea), 1.0);
  heading = spun;
  for (uint i = 0u; i < outer; ++i, heading = nextHeading(heading)) {
    const float reach = spiralRadius(i, outer) * pc.maxRadius;
    if (reach > ownRadius) gather(heading * reach, outerArea, spacing);  // inside, the first spiral has it
  }
  imageStore(target, p, vec4(sum / weight, 1.0));
}
