#pragma once
// The CPU reference for one strand, exactly what shaders/noodles/integrate.comp (and, with the flow
// baked, integrate_baked.comp) does for it: start on the seed grid, follow the flow for `segments`
// steps, and write a packed node (position + frame) at the start and after every step. The GPU test
// compares the two.
#include "maths/flow_field.h"
#include "scenes/noodles/field_bake.h"
#include "scenes/noodles/frames.h"
#include "scenes/noodles/integrate.h"
#include "scenes/noodles/packing.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace vitrine::noodles {

struct StrandSettings {
  glm::uvec3 grid{16, 16, 16};  // strands along x, y, z
  uint32_t segments = 64;
  float spacing = 0.3f;         // between neighbouring strand starts
  float step = 0.05f;
  maths::FieldSettings field;
  Integrator integrator = Integrator::Euler;
  TangentMode tangent = TangentMode::Raw;
  FrameMethod frames = FrameMethod::RotationMinimizing;
  FieldBake bake;  // none: every step evaluates the noise
  bool operator==(const StrandSettings&) const = default;
};

// Strand s starts at its grid point; the grid is centred on the origin.
inline glm::vec3 strandStart(const StrandSettings& s, uint32_t strand) {
  const glm::uvec3 index{strand % s.grid.x, (strand / s.grid.x) % s.grid.y, strand / (s.grid.x * s.grid.y)};
  return (glm::vec3(index) - (glm::vec3(s.grid) - 1.0f) * 0.5f) * s.spacing;
}

// Field evaluations an integration of every strand takes: one a node, three more a step for RK4.
inline double fieldEvaluations(const StrandSettings& s) {
  const double strands = double(s.grid.x) * s.grid.y * s.grid.z;
  return strands * (double(s.segments) * (s.integrator == Integrator::Rk4 ? 4.0 : 1.0) + 1.0);
}

// The bake for these strands: the seed grid's box grown by a strand's length (a unit-speed strand
// cannot leave it; a raw one leaves it in about one case in a thousand, and takes the exact field
// there), and by the lift's climb along z where strands follow the raw field.
inline FieldBake planFieldBake(const StrandSettings& s, FieldSource source) {
  const glm::vec3 half = (glm::vec3(s.grid) - 1.0f) * 0.5f * s.spacing;
  const float length = float(s.segments) * s.step;
  glm::vec3 lo = -half - length, hi = half + length;
  if (s.tangent == TangentMode::Raw) {
    lo.z += std::min(s.field.lift, 0.0f) * length;
    hi.z += std::max(s.field.lift, 0.0f) * length;
  }
  return planFieldBake(lo, hi, s.field.noiseScale, fieldEvaluations(s), source);
}

// What bake.comp writes: the noise part of the flow (no lift) at every texel centre, x fastest,
// rounded as the volume holds it (bakedComponent).
inline std::vector<glm::vec3> bakeField(const FieldBake& bake, maths::FieldSettings field) {
  field.lift = 0.0f;
  std::vector<glm::vec3> texels;
  texels.reserve(bake.count());
  for (uint32_t z = 0; z < bake.texels.z; ++z)
    for (uint32_t y = 0; y < bake.texels.y; ++y)
      for (uint32_t x = 0; x < bake.texels.x; ++x) {
        const glm::vec3 v = flowVelocity(bake.origin + glm::vec3(x, y, z) * bake.spacing, field);
        texels.push_back({bakedComponent(v.x), bakedComponent(v.y), bakedComponent(v.z)});
      }
  return texels;
}

// The flow a strand follows at p: the bake's sample plus the lift inside the baked volume (when
// `baked` holds its texels), the exact field elsewhere.
inline glm::vec3 strandVelocity(const StrandSettings& s, std::span<const glm::vec3> baked, glm::vec3 p) {
  if (!baked.empty() && insideBake(s.bake, p)) return sampleBake(s.bake, baked, p) + glm::vec3(0.0f, 0.0f, s.field.lift);
  return flowVelocity(p, s.field);
}

// Writes segments + 1 nodes into `nodes`; `baked` is bakeField(s.bake, s.field) when s.bake is baked.
inline void integrateStrand(const StrandSettings& s, uint32_t strand, std::span<PackedNode> nodes,
                            std::span<const glm::vec3> baked = {}) {
  const auto field = [&](glm::vec3 p) { return strandVelocity(s, baked, p); };
  glm::vec3 p = strandStart(s, strand);
  glm::vec3 v = field(p);
  Frame frame = upVectorFrame(directionOf(v, kWorldUp));
  nodes[0] = packNode(p, frame);
  for (uint32_t k = 1; k <= s.segments; ++k) {
    const glm::vec3 next = advance(p, travel(v, s.tangent), s.step, s.integrator, s.tangent, field);
    v = field(next);
    const glm::vec3 tangent = directionOf(v, frame.tangent);
    frame = s.frames == FrameMethod::Up ? upVectorFrame(tangent) : transportFrame(frame, p, next, tangent);
    p = next;
    nodes[k] = packNode(p, frame);
  }
}

}  // namespace vitrine::noodles
