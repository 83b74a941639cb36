#pragma once
// The tube of one strand as an indexed triangle list: one instance per strand, so the instance
// count is the strand count rather than the segment count (the H100's graphics front end spent about
// 13 ns on each of the old one-segment instances). Vertex v of an instance is ring corner
// v % kRingVertices of node v / kRingVertices; every strand of a given length uses the same indices,
// so one small index buffer serves them all. Neighbouring segments share their ring's vertices, so the
// vertex shader decodes each node about once per corner instead of twice per strip vertex.
// Mirrored by shaders/noodles/tube.vert.
#include "core/error.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace vitrine::noodles {

inline constexpr uint32_t kTubeSides = 8;
// Corner 8 sits on corner 0 again: the side coordinate the stripe reads then runs 7 -> 8 across the
// last side instead of 7 -> 0, which would interpolate through every value.
inline constexpr uint32_t kRingVertices = kTubeSides + 1;
inline constexpr uint32_t kTubeIndicesPerSegment = kTubeSides * 6;  // two triangles a side

inline uint32_t tubeVertex(uint32_t node, uint32_t corner) { return node * kRingVertices + corner; }

// Side c of segment k, as the old per-segment strip cut it (its diagonal runs from start corner c to
// end corner c + 1, so non-planar sides rasterise the same): (end c, start c, end c+1) and
// (end c+1, start c, start c+1), counter-clockwise seen from outside. All eight sides are listed;
// back-face culling drops the ones turned away.
inline std::vector<uint16_t> tubeIndices(uint32_t segments) {
  if (uint64_t(segments + 1) * kRingVertices > std::numeric_limits<uint16_t>::max())
    throw Error("noodles: too many segments a strand for 16-bit tube indices");
  std::vector<uint16_t> indices;
  indices.reserve(size_t(segments) * kTubeIndicesPerSegment);
  for (uint32_t k = 0; k < segments; ++k)
    for (uint32_t c = 0; c < kTubeSides; ++c) {
      const uint32_t s0 = tubeVertex(k, c), s1 = tubeVertex(k, c + 1);
      const uint32_t e0 = tubeVertex(k + 1, c), e1 = tubeVertex(k + 1, c + 1);
      for (uint32_t v : {e0, s0, e1, e1, s0, s1}) indices.push_back(uint16_t(v));
    }
  return indices;
}

}  // namespace vitrine::noodles
