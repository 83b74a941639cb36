#include "scenes/glass/frame_values.h"

#include "scenes/glass/materials.h"
#include "scenes/glass/optics.h"
#include "scenes/glass/scene_shape.h"
#include "scenes/glass/world_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace vitrine::glass {

shader::GlassFrame frameBlock(const Settings& settings, const FrameMoment& moment, const Instances& instances) {
  const Settings& s = settings;
  const glm::vec2 view = viewSize(moment.extent);
  shader::GlassFrame b{};
  const bool ortho = s.projection == Projection::Orthographic;
  const float camZ = 0.5f * view.y / std::tan(glm::radians(s.fov) * 0.5f);
  const glm::vec3 eye{0.0f, 0.0f, camZ};
  const glm::mat4 look = glm::lookAtRH(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  glm::mat4 projection = ortho ? glm::orthoRH_ZO(-0.5f * view.x, 0.5f * view.x, -0.5f * view.y, 0.5f * view.y, 1.0f,
                                                 camZ + 4000.0f)
                               : glm::perspectiveRH_ZO(glm::radians(s.fov), view.x / view.y, 1.0f, camZ + 4000.0f);
  projection[1][1] *= -1.0f;  // Vulkan's y points down
  b.viewProjection = projection * look;
  b.eye = eye;
  b.orthographic = ortho ? 1u : 0u;
  b.viewWorld = view;
  b.viewPixels = {float(moment.extent.width), float(moment.extent.height)};

  b.ior = s.ior;
  b.abbe = s.abbe / s.spread;  // Cauchy's dispersion term goes as 1 / V_d
  b.strength = s.strength;
  b.photoDepth = s.depth;
  if (s.dispersion == Dispersion::Sellmeier && s.material > 0)
    if (const auto& coefficients = kMaterials[size_t(s.material - 1)].sellmeier) {
      b.sellmeier = 1u;
      b.sellmeierB = {coefficients->B[0], coefficients->B[1], coefficients->B[2]};
      b.sellmeierC = {coefficients->C[0], coefficients->C[1], coefficients->C[2]};
    }
  const bool jitter = s.jitter && !moment.zHeld;
  b.heroLambda = heroLambda(uint32_t(moment.frame), moment.seed, jitter);
  b.wavelengths = moment.zHeld ? 3 : tierWavelengths(sampleCount(s), moment.tier, jitter);
  b.approxExits = s.mode == RefractionMode::Approx ? 1u : 0u;
  b.jitter = jitter ? 1u : 0u;
  b.optics = s.optics == Optics::Physical ? 1 : 0;

  const ShapeDims d = shapeDims(s, moment.time);
  b.shapeSize = glm::vec3(d.sizeEdge);
  b.shapeEdge = d.sizeEdge.w;
  b.waveAmplitude = d.wave.x;
  b.waveLength = d.wave.y;
  b.wavePhase = d.wave.z;
  b.smoothCurvature = d.wave.w > 0.5f ? 1u : 0u;
  b.instanceCount = instanceCount(s.shape);
  b.bounces = s.bounces;
  b.diamondDebug = int(s.diamondDebug);
  b.taa = s.aa == Antialiasing::Taa ? 1u : 0u;

  b.frame = uint32_t(moment.frame);
  b.seed = moment.seed;
  b.environment = s.environment ? 1u : 0u;
  b.showProxy = s.showProxy ? 1u : 0u;
  b.exposure = s.exposure;
  b.envRotation = s.envRotation;
  b.rotation = glm::mat4(shapeRotation(s, moment.time));  // the upper 3x3, padded as std430 wants
  b.previousRotation = glm::mat4(shapeRotation(s, moment.previousTime));

  // Each instance's pixels: its turned proxy box's corners projected, as the raster path's proxy covers.
  const auto& at = instances.all();
  const glm::vec3 half = shapeHalfExtent(d) + 1.0f;
  const glm::mat3 toWorld = glm::transpose(glm::mat3(b.rotation));
  for (int i = 0; i < kMaxInstances; ++i) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local = half * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      const glm::vec4 clip = b.viewProjection * glm::vec4(glm::vec3(at[i].centre, 0.0f) + toWorld * local, 1.0f);
      const glm::vec2 pixel = (glm::vec2(clip) / std::max(clip.w, 1e-3f) * 0.5f + 0.5f) * b.viewPixels;
      lo = glm::min(lo, pixel);
      hi = glm::max(hi, pixel);
    }
    b.instances[i] = {glm::vec4(lo, hi), at[i].centre, at[i].previous};
  }
  return b;
}

uint32_t shadeOptions(const shader::GlassFrame& block) {
  return (block.optics == 1 ? GLASS_SHADE_PHYSICAL : 0u) | (block.environment != 0u ? GLASS_SHADE_ENVIRONMENT : 0u) |
         (block.approxExits != 0u ? GLASS_SHADE_APPROX : 0u) | (block.sellmeier != 0u ? GLASS_SHADE_SELLMEIER : 0u);
}

}  // namespace vitrine::glass
