#version 460
// The tubes onto the facade: their light added to its colour, the nearer of the two depths kept, so
// the depth of field blurs each by its own distance.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform image2D scene;  // the facade in, facade and tubes out
layout(set = 0, binding = 1, r32f) uniform image2D depth;     // the facade's in, the nearer out
layout(set = 0, binding = 2) uniform sampler2D tubes;         // the tubes' light; alpha: the nearest one's reverse-Z depth

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(scene)))) return;
  const vec4 tube = texelFetch(tubes, p, 0);
  imageStore(scene, p, imageLoad(scene, p) + vec4(tube.rgb, 0.0));
  imageStore(depth, p, vec4(max(imageLoad(depth, p).r, tube.a)));
}
