#version 460
// Zeroes the tubes' target once the frame is done with it, so the next frame's tubes add onto nothing:
// a clear in compute, where the H100's graphics part would spend more on it than on the tubes.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba16f) uniform writeonly image2D target;

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(p, imageSize(target)))) imageStore(target, p, vec4(0.0));
}
