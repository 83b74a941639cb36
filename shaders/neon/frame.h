// The neon scene's per-frame block, one declaration for both sides: src/scenes/neon/neon_scene.cpp
// fills it each frame, camera.glsl binds it as the uniform block F (std140) for the facade and the tubes.
#ifndef NEON_FRAME_H
#define NEON_FRAME_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct NeonFrame {
  mat4 viewProjection;        // reverse-Z, infinitely far
  vec3 eye;                   // the camera's position, world
  float near;                 // the projection's near distance
  vec3 right;                 // the camera's right axis times tan(fov/2) times the aspect
  float frameWidth;           // pixels
  vec3 up;                    // its up axis times tan(fov/2)
  float frameHeight;          // pixels
  vec3 forward;               // where it looks
  float focalPixels;          // the focal length, pixels
  vec3 colourA;               // the tubes' first neon colour, linear rgb
  float glow;                 // the tubes' emissive intensity
  vec3 colourB;               // the second
  float tubeRadius;           // m, at full life
  vec3 colourC;               // the third
  float exposure;             // the tubes' exposure (tubeExposure: the energy budget)
  float minTubeRadiusPixels;  // the thinnest a tube is drawn (kMinTubeRadiusPixels)
  uint chains;                // chains drawn
  uint particlesPerChain;     // particles in each
  uint boxes;                 // the facade's boxes
};
VITRINE_SHARED_END

#endif
