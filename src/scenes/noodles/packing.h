#pragma once
// The GPU record of one strand node: 16 bytes. A strand of N segments stores N + 1 nodes and a
// segment reads the two it joins, so one segment costs 16 (N + 1) / N bytes - 16.25 at N = 64.
// Nodes are stored node-major within blocks of 32 strands (nodeSlot), so neighbouring invocations of
// the integrate pass write neighbouring records.
//   x, y, z  position, float32 bits: the tubes are 0.02 wide across a nest tens of units wide, so
//            half floats (3 significant digits) would visibly kink them;
//   w        the frame as a unit quaternion, "smallest three" in 10:10:10:2 - the index of the
//            largest component (2 bits) and the other three (10 bits each, over +-1/sqrt 2, which
//            is as large as they can be). Rings come back rotated by under 0.2 degrees.
// The tangent is part of the frame, so the tube's rings need nothing else; colour comes from the
// strand index and radius from push constants. See docs/NOODLES.md. Mirrored by
// shaders/noodles/packing.glsl.
#include "scenes/noodles/frames.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace vitrine::noodles {

using PackedNode = glm::uvec4;
inline constexpr uint32_t kNodeBytes = sizeof(PackedNode);
static_assert(kNodeBytes == 16);

inline constexpr float kQuaternionRange = 0.70710678f;  // |component| <= 1/sqrt 2 unless it is the largest
inline constexpr float kQuaternionSteps = 1023.0f;

inline uint32_t packQuaternion(glm::vec4 q) {
  int largest = 0;
  for (int i = 1; i < 4; ++i)
    if (std::fabs(q[i]) > std::fabs(q[largest])) largest = i;
  if (q[largest] < 0.0f) q = -q;  // q and -q are the same rotation: make the dropped one positive
  uint32_t bits = uint32_t(largest) << 30;
  int slot = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == largest) continue;
    const float unit = glm::clamp(q[i] / kQuaternionRange * 0.5f + 0.5f, 0.0f, 1.0f);
    bits |= uint32_t(std::floor(unit * kQuaternionSteps + 0.5f)) << (10 * slot++);
  }
  return bits;
}

inline glm::vec4 unpackQuaternion(uint32_t bits) {
  const int largest = int(bits >> 30);
  glm::vec4 q(0.0f);
  float sumSquares = 0.0f;
  int slot = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == largest) continue;
    const float unit = float((bits >> (10 * slot++)) & 1023u) / kQuaternionSteps;
    q[i] = (unit * 2.0f - 1.0f) * kQuaternionRange;
    sumSquares += q[i] * q[i];
  }
  q[largest] = std::sqrt(std::max(1.0f - sumSquares, 0.0f));
  return q;
}

// Where node `node` of the chunk's strand `localStrand` lives, counted in nodes from the chunk start.
// Strands go in blocks of kNodeBlockStrands (a warp's worth; the chunk's last block may be narrower),
// node-major within a block: the integrate pass's 32 neighbouring invocations write one step's nodes
// side by side, and a block's nodes are one run of memory rather than spread over the whole chunk.
// Against node-major over the whole chunk, the raster at 10^8 segments took 5 % less on the H200
// (docs/PERFORMANCE.md).
inline constexpr uint32_t kNodeBlockStrands = 32;
inline uint64_t nodeSlot(uint32_t chunkStrands, uint32_t nodesPerStrand, uint32_t localStrand, uint32_t node) {
  const uint32_t blockStart = localStrand & ~(kNodeBlockStrands - 1u);
  const uint32_t width = std::min(kNodeBlockStrands, chunkStrands - blockStart);
  return uint64_t(blockStart) * nodesPerStrand + uint64_t(node) * width + (localStrand - blockStart);
}

inline PackedNode packNode(glm::vec3 position, const Frame& frame) {
  return {std::bit_cast<uint32_t>(position.x), std::bit_cast<uint32_t>(position.y),
          std::bit_cast<uint32_t>(position.z), packQuaternion(frameToQuaternion(frame))};
}

inline glm::vec3 nodePosition(const PackedNode& node) {
  return {std::bit_cast<float>(node.x), std::bit_cast<float>(node.y), std::bit_cast<float>(node.z)};
}

inline Frame nodeFrame(const PackedNode& node) { return quaternionToFrame(unpackQuaternion(node.w)); }

}  // namespace vitrine::noodles
