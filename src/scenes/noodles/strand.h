#pragma once
// The CPU reference for one strand, exactly what shaders/noodles/integrate.comp does for it: start on
// the seed grid, follow the flow for `segments` steps, and write a packed node (position + frame)
// at the start and after every step. The GPU test compares the two.
#include "maths/flow_field.h"
#include "scenes/noodles/frames.h"
#include "scenes/noodles/integrate.h"
#include "scenes/noodles/packing.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>

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
  bool operator==(const StrandSettings&) const = default;
};

// Strand s starts at its grid point; the grid is centred on the origin.
inline glm::vec3 strandStart(const StrandSettings& s, uint32_t strand) {
  const glm::uvec3 index{strand % s.grid.x, (strand / s.grid.x) % s.grid.y, strand / (s.grid.x * s.grid.y)};
  return (glm::vec3(index) - (glm::vec3(s.grid) - 1.0f) * 0.5f) * s.spacing;
}

// Writes segments + 1 nodes into `nodes`.
inline void integrateStrand(const StrandSettings& s, uint32_t strand, std::span<PackedNode> nodes) {
  const auto field = [&](glm::vec3 p) { return flowVelocity(p, s.field); };
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
