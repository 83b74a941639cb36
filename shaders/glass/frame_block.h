// The glass scene's per-frame block, one declaration for both sides (shaders/common/interop.h says
// how): src/scenes/glass/frame_values.cpp fills it once a frame, shaders/glass/frame.glsl binds it as
// the read-only storage buffer F (std430; frame.glsl says why it is no uniform block) for the spectral
// passes and the resolve pass.
#ifndef GLASS_FRAME_BLOCK_H
#define GLASS_FRAME_BLOCK_H
#include "../common/interop.h"

// The most instances of a shape the scene shows at once (the diamond stands alone).
#define GLASS_MAX_INSTANCES 4

// The options that choose shade.glsl's paths, as the bits of its specialization constant 1
// (GLASS_SHADE_OPTIONS), which the host takes from this block's fields (frame_values.h: shadeOptions):
// each combination's pipelines carry only their own paths. A uniform branch costs a GPU little, but
// llvmpipe paid for every path not taken (docs/PERFORMANCE.md, glass, Decisions).
#define GLASS_SHADE_PHYSICAL 1u     // optics == 1
#define GLASS_SHADE_ENVIRONMENT 2u  // environment == 1
#define GLASS_SHADE_APPROX 4u       // approxExits == 1
#define GLASS_SHADE_SELLMEIER 8u    // sellmeier == 1

VITRINE_SHARED_BEGIN
// One instance of the shape: its place now and last frame (the motion vectors), and the pixels its
// turned proxy box covers, which the compute path tests before shading.
struct GlassInstance {
  // Its box's rectangle on screen, pixels (origin top-left, y down): min x, min y, max x, max y. One
  // vec4, first: the compute path tests it for every pixel and instance, and one 16-byte load is
  // measurably cheaper there than two 8-byte ones (H200: the cube's spectral pass 3 % faster).
  vec4 screenRect;
  vec2 centre;          // world units, this frame
  vec2 previousCentre;  // last frame's
};

// std430: each vec3 starts a 16-byte slot, which the scalar after it shares.
struct GlassFrame {
  mat4 viewProjection;    // world -> clip
  mat4 rotation;          // the shape's world -> object rotation, in the upper 3x3 (std430 pads a mat3's columns)
  mat4 previousRotation;  // last frame's, for the motion vectors
  vec3 eye;               // the camera's position, world units; orthographic: the rays start at its z
  uint orthographic;      // 1: an orthographic projection, 0: perspective
  vec2 viewWorld;         // the view's width and height, world units (1073 tall)
  vec2 viewPixels;        // its width and height, pixels
  float ior;              // n_d, the index at the helium d line
  float abbe;             // V_d
  float strength;         // seed optics: how far the exit ray leans from the view ray to the refracted one
  float photoDepth;       // how far behind the glass the photo hangs, world units
  vec3 sellmeierB;        // the material's Sellmeier law, when `sellmeier` is 1
  uint sellmeier;         // 1: the index from sellmeierB and C; 0: Cauchy from ior and abbe
  vec3 sellmeierC;        // µm^2
  float heroLambda;       // nm: approx mode's wavelength for the shared exit, this frame
  int wavelengths;        // N, stratified over 380-700 nm
  uint approxExits;       // 1: one back exit at heroLambda, shared by every wavelength; 0: each its own
  uint jitter;            // 1: the wavelengths jitter per pixel and frame; 0: stratum centres
  int optics;             // 0 seed, 1 physical
  vec3 shapeSize;         // along x, y, z, world units (shapes.glsl's GlassShapeDims::sizeEdge.xyz)
  float shapeEdge;        // the rim's rounding radius (pill, cube, plate)
  float waveAmplitude;    // the plate's waves; the other shapes have amplitude 0 and length 1
  float waveLength;
  float wavePhase;        // radians
  uint smoothCurvature;   // 1: L4 squircle rims (pill, cube, plate)
  int instanceCount;      // instances shown: 4, or 1 diamond
  int bounces;            // the diamond's internal reflections allowed
  int diamondDebug;       // 0 none, 1 wireframe, 2 facet colours, 3 TIR
  uint taa;               // 1: each pixel's ray jittered within it, per frame (the resolve reprojects)
  uint frame;             // the frame's index: decorrelates jitter between frames
  uint seed;
  uint environment;       // 1: the panorama is background, refraction and reflection; 0: the backdrop
  uint showProxy;         // 1: tint every proxy pixel pink
  float exposure;         // multiplies the panorama
  float envRotation;      // turns the panorama about the vertical, radians
  vec2 unused;            // 0: the instances start on a 16-byte boundary, as their vec4 needs in std430
  GlassInstance instances[GLASS_MAX_INSTANCES];
};
VITRINE_SHARED_END

#endif
