#include "scenes/glass/frame_values.h"

#include "scenes/glass/materials.h"
#include "scenes/glass/optics.h"
#include "scenes/glass/scene_shape.h"
#include "scenes/glass/world_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace vitrine::glass {

FrameBlock frameBlock(const Settings& settings, const FrameMoment& moment, const Instances& instances) {
  const Settings& s = settings;
  const glm::vec2 view = viewSize(moment.extent);
  FrameBlock b{};
  const bool ortho = s.projection == Projection::Orthographic;
  const float camZ = 0.5f * view.y / std::tan(glm::radians(s.fov) * 0.5f);
  const glm::vec3 eye{0.0f, 0.0f, camZ};
  const glm::mat4 look = glm::lookAtRH(eye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  glm::mat4 projection = ortho ? glm::orthoRH_ZO(-0.5f * view.x, 0.5f * view.x, -0.5f * view.y, 0.5f * view.y, 1.0f,
                                                 camZ + 4000.0f)
                               : glm::perspectiveRH_ZO(glm::radians(s.fov), view.x / view.y, 1.0f, camZ + 4000.0f);
  projection[1][1] *= -1.0f;  // Vulkan's y points down
  b.viewProjection = projection * look;
  b.camera = {eye, ortho ? 1.0f : 0.0f};
  b.view = {view.x, view.y, float(moment.extent.width), float(moment.extent.height)};
  b.glass = {s.ior, s.abbe, s.strength, s.depth};
  const int n = moment.zHeld ? 3 : sampleCount(s);
  const bool jitter = s.jitter && !moment.zHeld;
  b.spectral = {n, s.mode == RefractionMode::Approx ? 1 : 0, jitter ? 1 : 0, s.optics == Optics::Physical ? 1 : 0};
  b.spectralExtra = {heroLambda(uint32_t(moment.frame), moment.seed, jitter), 0.0f, 0.0f, 0.0f};
  if (s.dispersion == Dispersion::Sellmeier && s.material > 0)
    if (const auto& coefficients = kMaterials[size_t(s.material - 1)].sellmeier) {
      b.spectralExtra.z = 1.0f;
      b.sellmeierB = {coefficients->B[0], coefficients->B[1], coefficients->B[2], 0.0f};
      b.sellmeierC = {coefficients->C[0], coefficients->C[1], coefficients->C[2], 0.0f};
    }
  b.shape = {int(s.shape), instanceCount(s.shape), s.bounces, int(s.diamondDebug)};
  b.frameInfo = {int(moment.frame), int(moment.seed), int(s.aa), s.environment ? 1 : 0};
  b.environment = {s.exposure, s.envRotation, 0.0f, s.showProxy ? 1.0f : 0.0f};
  const ShapeDims d = shapeDims(s, moment.time);
  b.shapeSize = d.sizeEdge;
  b.shapeWave = d.wave;
  b.rotation = glm::mat4(shapeRotation(s, moment.time));  // the upper 3x3, padded as std140 wants
  b.previousRotation = glm::mat4(shapeRotation(s, moment.previousTime));
  const auto& at = instances.all();
  for (int i = 0; i < kMaxInstances; ++i) b.centres[i] = {at[i].centre, at[i].previous};
  // Each instance's pixels: its turned proxy box's corners projected, as the raster path's proxy covers.
  const glm::vec3 half = shapeHalfExtent(d) + 1.0f;
  const glm::mat3 toWorld = glm::transpose(glm::mat3(b.rotation));
  const glm::vec2 pixels{float(moment.extent.width), float(moment.extent.height)};
  for (int i = 0; i < kMaxInstances; ++i) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 local = half * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      const glm::vec4 clip = b.viewProjection * glm::vec4(glm::vec3(at[i].centre, 0.0f) + toWorld * local, 1.0f);
      const glm::vec2 pixel = (glm::vec2(clip) / std::max(clip.w, 1e-3f) * 0.5f + 0.5f) * pixels;
      lo = glm::min(lo, pixel);
      hi = glm::max(hi, pixel);
    }
    b.rects[i] = {lo, hi};
  }
  return b;
}

}  // namespace vitrine::glass
