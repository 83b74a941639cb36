#version 460
// The calibration card, drawn in one pass in output pixels (the card is resolution-true: lines are
// one or two pixels wide whatever the size). A grid of squares over a mid-grey field, a large circle
// and four corner circles (a projector's geometry and aspect), a centre cross, 75 % colour bars and a
// grey ramp (levels and gamma), a one-pixel border and corner markers for the pin, and the strobe
// patch that checks the flash guard. The type (the output's name and size) is drawn over it by the
// scene's text pass.
#extension GL_GOOGLE_include_directive : require
#include "calibrate/card_push.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Push { CalibrateCardPush pc; };

const vec3 kField = vec3(0.10);       // the background grey (linear), about sRGB 89
const vec3 kLine = vec3(0.75);
const vec3 kMarker = vec3(1.0, 0.55, 0.05);

// 1 within `halfWidth` pixels of 0, anti-aliased over one pixel.
float line(float distancePx, float halfWidth) { return clamp(halfWidth + 0.5 - abs(distancePx), 0.0, 1.0); }

float circle(vec2 p, vec2 centre, float radius, float halfWidth) { return line(length(p - centre) - radius, halfWidth); }

float box(vec2 p, vec2 lo, vec2 hi) { return all(greaterThanEqual(p, lo)) && all(lessThan(p, hi)) ? 1.0 : 0.0; }

// The SMPTE order at 75 %: white, yellow, cyan, green, magenta, red, blue.
vec3 bar(int i) {
  const vec3 bars[7] = vec3[7](vec3(1, 1, 1), vec3(1, 1, 0), vec3(0, 1, 1), vec3(0, 1, 0), vec3(1, 0, 1),
                               vec3(1, 0, 0), vec3(0, 0, 1));
  return bars[i] * 0.522;  // 75 % of full scale in sRGB, in linear light
}

float srgbToLinear(float c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }

void main() {
  ivec2 size = imageSize(target);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  vec2 p = vec2(pixel) + 0.5;
  vec2 s = vec2(size);
  vec2 centre = s * 0.5;
  float unit = s.y / 12.0;  // a grid square: twelve down the height, as many across as fit
  vec3 colour = kField;

  // The grid, centred so that a line crosses the middle both ways.
  vec2 g = (p - centre) / unit;
  vec2 toLine = (g - round(g)) * unit;
  colour = mix(colour, kLine, max(line(toLine.x, 0.5), line(toLine.y, 0.5)) * 0.8);

  // The big circle and the corner circles: round on the output means square pixels.
  float radius = s.y * 0.46;
  colour = mix(colour, vec3(0.02), box(p, centre - vec2(radius * 0.86, radius * 0.58), centre + vec2(radius * 0.86, radius * 0.58)));
  colour = mix(colour, vec3(0.9), circle(p, centre, radius, 1.0));
  float small = unit * 1.5;
  for (int i = 0; i < 4; ++i) {
    vec2 corner = vec2(i & 1, i >> 1);
    vec2 c = mix(vec2(unit * 2.0), s - vec2(unit * 2.0), corner);
    colour = mix(colour, vec3(0.9), circle(p, c, small, 1.0));
    colour = mix(colour, vec3(0.9), max(line(p.x - c.x, 0.5), line(p.y - c.y, 0.5)) * box(p, c - small, c + small));
  }

  // Inside the circle: colour bars above, a grey ramp (stepped over smooth) below.
  vec2 inner = vec2(radius * 0.86, radius * 0.58);
  vec2 lo = centre - inner, hi = centre + inner;
  float w = hi.x - lo.x;
  float barsBottom = lo.y + (hi.y - lo.y) * 0.42;
  if (box(p, lo, vec2(hi.x, barsBottom)) > 0.0) colour = bar(clamp(int((p.x - lo.x) / w * 7.0), 0, 6));
  float rampTop = lo.y + (hi.y - lo.y) * 0.66, stepsTop = lo.y + (hi.y - lo.y) * 0.83;
  float t = clamp((p.x - lo.x) / w, 0.0, 1.0);
  if (box(p, vec2(lo.x, rampTop), vec2(hi.x, stepsTop)) > 0.0) colour = vec3(srgbToLinear(t));
  if (box(p, vec2(lo.x, stepsTop), hi) > 0.0) colour = vec3(srgbToLinear(min(floor(t * 11.0) / 10.0, 1.0)));

  // The strobe: a quarter of the frame (half its width by half its height) around the middle.
  if (pc.strobeOn != 0u && box(p, s * 0.25, s * 0.75) > 0.0) colour = pc.strobeLit != 0u ? pc.strobeColour.rgb : vec3(0.0);

  // The centre cross, over everything but the border; short enough to end above the caption.
  float arm = unit * 0.5;
  float cross = max(line(p.x - centre.x, 1.0) * step(abs(p.y - centre.y), arm),
                    line(p.y - centre.y, 1.0) * step(abs(p.x - centre.x), arm));
  float under = dot(colour, vec3(0.2126, 0.7152, 0.0722));
  colour = mix(colour, vec3(under > 0.5 ? 0.0 : 1.0), cross);  // black over the lit strobe, else white

  // A one-pixel white border (overscan and edge blending) and corner markers for the pin: an L of
  // two pixels a grid square long, and a triangle pointing into the corner.
  vec2 fromEdge = min(p, s - p);
  if (min(fromEdge.x, fromEdge.y) < 1.0) colour = vec3(1.0);
  vec2 inCorner = fromEdge;
  float ell = (step(inCorner.x, 3.0) * step(inCorner.y, unit)) + (step(inCorner.y, 3.0) * step(inCorner.x, unit));
  float triangle = step(inCorner.x + inCorner.y, unit * 0.5) * step(6.0, inCorner.x) * step(6.0, inCorner.y);
  colour = mix(colour, kMarker, clamp(ell + triangle, 0.0, 1.0) * step(1.0, min(fromEdge.x, fromEdge.y)));

  imageStore(target, pixel, vec4(colour, 1.0));
}
