// The neon scene's per-frame block; mirrors NeonFrame in src/scenes/neon/neon_scene.cpp.
#ifndef NEON_CAMERA_GLSL
#define NEON_CAMERA_GLSL

layout(std140, set = 0, binding = 0) uniform Frame {
  mat4 viewProjection;  // reverse-Z, infinitely far
  vec4 eye;             // xyz; w: the projection's near distance
  vec4 right;           // xyz: the camera's right axis times tan(fov/2) times the aspect; w: frame width
  vec4 up;              // xyz: its up axis times tan(fov/2); w: frame height
  vec4 forward;         // xyz: where it looks
  vec4 colourA;         // linear rgb; w: glow
  vec4 colourB;         // linear rgb; w: tube radius
  vec4 colourC;         // linear rgb; w: the tubes' exposure (tubeExposure: the energy budget)
  vec4 tube;            // x: the thinnest tube radius drawn, pixels; y: the focal length, pixels; zw: 0
  uvec4 counts;         // chains, particles per chain, boxes, 0
} F;

// The primary ray through a pixel (origin top-left, y down).
vec3 pixelRay(vec2 pixel) {
  const vec2 ndc = pixel / vec2(F.right.w, F.up.w) * 2.0 - 1.0;
  return normalize(F.forward.xyz + ndc.x * F.right.xyz - ndc.y * F.up.xyz);
}

#endif
