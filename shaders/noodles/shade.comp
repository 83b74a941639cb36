#version 460
// Shades each pixel once from the visibility buffer, nothing hidden ever shaded: each of its samples
// is the segment it holds (cast again to find where its ray meets the capsule) or the background,
// and the pixel is their average. Every sample is shaded, not each segment once a pixel at one
// place (as multisampling does): the tubes are lit from above, so shading a segment at its first
// sample (the pixel's top) made the default frame 15 % brighter than shading every sample, and at
// its samples' centroid 2 to 6 % darker; the four shadings' cost: docs/PERFORMANCE.md, noodles.
// Light and palette are tube.frag's of old: Lambert plus ambient, linear output. Dispatched once per
// chunk of strands: the first writes every pixel, later ones add the samples of their own segments.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "noodles/packing.glsl"
#include "noodles/palette.glsl"
#include "noodles/raster_push.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, std430) readonly buffer Nodes { uvec4 nodes[]; };  // this chunk's nodes
layout(binding = 1, std430) readonly buffer Visibility { uint64_t keys[]; };
layout(binding = 2, rgba16f) uniform image2D target;

const vec3 LIGHT_DIRECTION = vec3(-0.5, -0.2, 1.0) / sqrt(1.29);
const vec3 AMBIENT = vec3(0.05, 0.05, 0.07);
const vec3 BACKGROUND = vec3(0.01, 0.01, 0.014);  // kBackground in src/scenes/noodles/tube_view.h
const float SIDE_ANGLE = 6.28318530718 / 8.0;

vec3 shadeSample(uint index, vec2 position) {
  uint segment = index / pc.chunkStrands;
  uint local = index - segment * pc.chunkStrands;
  uvec4 startNode = nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, segment)];
  uvec4 endNode = nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, segment + 1u)];
  vec3 a = nodePosition(startNode), b = nodePosition(endNode);
  vec3 direction = normalize(rayThrough(screenView(), position));
  float t = capsuleHit(pc.eye, direction, a, b, pc.tubeRadius);
  // The raster pass found a hit with the same code; should rounding differ here, take the point of
  // the ray nearest the segment's middle, which lies on the silhouette's edge.
  if (t == NO_HIT) t = dot(0.5 * (a + b) - pc.eye, direction);
  vec3 hit = pc.eye + t * direction;
  float along = alongSegment(hit, a, b);
  Frame startFrame = nodeFrame(startNode), endFrame = nodeFrame(endNode);
  // The normal is the exact one only on a strand's round ends. Along the strand it is taken square to
  // the node tangents blended along the segment, as the old rings' normals were: a curve drawn as
  // straight capsules then shades smoothly instead of showing each segment as a facet.
  vec3 radial = hit - mix(a, b, along);
  bool strandEnd = (segment == 0u && dot(hit - a, b - a) <= 0.0) ||
                   (segment + 1u == pc.segmentsPerStrand && dot(hit - b, b - a) >= 0.0);
  if (!strandEnd) {
    vec3 tangent = normalize(mix(startFrame.tangent, endFrame.tangent, along));
    vec3 across = radial - dot(radial, tangent) * tangent;
    if (dot(across, across) > 1e-12 * dot(radial, radial)) radial = across;
  }
  vec3 normal = normalize(radial);

  float lambert = max(dot(LIGHT_DIRECTION, normal), 0.0);
  float paint = 1.0;
  if (pc.stripe != 0u) {
    // The stripe is the side between frame angles 0 and 45 degrees from the frame's normal towards its
    // binormal, the frames blended along the segment: it spirals wherever the frames twist.
    vec3 frameNormal = mix(startFrame.normal, endFrame.normal, along);
    vec3 frameBinormal = mix(startFrame.binormal, endFrame.binormal, along);
    float angle = atan(dot(normal, frameBinormal), dot(normal, frameNormal));
    if (mod(angle / SIDE_ANGLE, 8.0) < 1.0) paint = 0.25;
  }
  return strandColour(pc.firstStrand + local, pc.totalStrands, pc.colouring) * paint * (lambert + AMBIENT);
}

vec2 samplePosition(uvec2 pixel, uint q) {
  uvec2 quarter = uvec2(q % SAMPLES_PER_AXIS, q / SAMPLES_PER_AXIS);
  return vec2(pixel) + sampleOffset(quarter.y * 2u + quarter.x, SAMPLES_PER_AXIS);
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= uint(pc.pixels.x) || pixel.y >= uint(pc.pixels.y)) return;
  uint samples = SAMPLES_PER_AXIS * SAMPLES_PER_AXIS;
  uint first = (pixel.y * uint(pc.pixels.x) + pixel.x) * samples;
  vec3 sum = vec3(0.0);
  for (uint q = 0u; q < samples; ++q) {
    uint64_t key = keys[first + q];
    if (key == ~uint64_t(0)) {
      if (pc.accumulate == 0u) sum += BACKGROUND;
      continue;
    }
    uint index = uint(key & 0xffffffffUL) - segmentId(0u);  // wraps past the chunk for earlier chunks' ids
    if (index < chunkSegments()) sum += shadeSample(index, samplePosition(pixel, q));  // else another chunk's
  }
  vec3 colour = sum / float(samples);
  if (pc.accumulate != 0u) colour += imageLoad(target, ivec2(pixel)).rgb;
  imageStore(target, ivec2(pixel), vec4(colour, 1.0));
}
