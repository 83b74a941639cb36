#version 460
// Test-only: the native twin of tests/isf/speed_field.fs. The quad as a 4-vertex strip, as the ISF
// runner draws it, with ISF's normalised coordinate (0,0 at the bottom left) interpolated the same way.
layout(location = 0) out vec2 normCoord;

void main() {
  const vec2 corner = vec2(gl_VertexIndex & 1, gl_VertexIndex >> 1);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
  normCoord = vec2(corner.x, 1.0 - corner.y);  // Vulkan's y points down; ISF's up
}
