#pragma once
// One frame of the neon tubes' particle chains, in plain C++: the reference that
// shaders/neon/chains.comp mirrors line for line. Particles are stored chain-major as vec4s
// (index = chain * particlesPerChain + k, k = 0 the head): xyz position, w the head's life, by which the
// tube renderer fades the gas. Each frame reads last frame's positions and writes this frame's, so every
// particle depends only on the previous frame and the order of the invocations cannot matter.
#include "maths/flow_field.h"
#include "shaders/neon/chain_push.h"
#include "scenes/neon/head_state.h"

#include <algorithm>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>

namespace vitrine::neon {

// The share of the gap to the particle ahead that a follower closes in one step of `dt` seconds, for
// a follower that closes `lerp60` of it in a 60 Hz step. A follower that reads the particle ahead one
// step late and closes a share a of the gap lags it by dt / a seconds on average, so a share
// proportional to dt keeps that lag - and the tube's length, the sum of its followers' lags - the same
// at every step rate: 60 Hz in the gallery, 240 Hz in `record --fps 30 --spp 8`.
inline float followerLerp(float lerp60, float dt) { return std::clamp(lerp60 * dt * 60.0f, 0.0f, 1.0f); }

struct ChainParams {
  float dt;             // seconds this step
  float lerp;           // the share of the gap to the particle ahead that a follower closes this step (followerLerp)
  float fieldStrength;  // world units per second per unit of curl
  float fieldScale;     // world -> noise coordinates
  double noiseTime;     // how far the potentials have drifted, in noise units (see maths::driftOffset)
};

// The heads swim in the noodles scene's curl noise (no lift): divergence free, so the tubes neither
// bunch into sinks nor spray out of sources. The drift is computed in double here, on the CPU.
inline maths::FieldSettings chainField(const ChainParams& p) {
  return maths::fieldAtTime(maths::FieldKind::Curl, p.fieldScale, 0.0f, p.noiseTime);
}

// |v|^2 as three products and two sums in this order, unfused: chains.comp computes the same, so both
// sides decide a pen's step alike.
inline float squaredLength(glm::vec3 v) { return v.x * v.x + v.y * v.y + v.z * v.z; }

// Particle `index`'s position next frame. `field` is chainField(p), hoisted out of the loop.
inline glm::vec4 chainParticle(std::span<const HeadState> heads, uint32_t particlesPerChain,
                               std::span<const glm::vec4> previous, uint32_t index, const maths::FieldSettings& field,
                               const ChainParams& p) {
  const HeadState& head = heads[index / particlesPerChain];
  const uint32_t k = index % particlesPerChain;
  glm::vec3 position = glm::vec3(previous[index]);
  const ChainState state = chainState(head);
  if (state == ChainState::Initialising) {
    position = head.origin;  // the whole chain collapses onto the release point
  } else if (state == ChainState::Alive && steered(head)) {
    // A pen records its path: the head is where the cursor is, and once it is 0.6 m
    // (kPenSpacingSquared) from the newest recorded point (particle 1) every point moves one place
    // down the chain and particle 1 takes the pen's position. Every particle of the chain makes the
    // same decision.
    const glm::vec3 gap = head.origin - glm::vec3(previous[index - k + 1]);
    const bool record = squaredLength(gap) >= kPenSpacingSquared;
    if (k == 0 || (k == 1 && record))
      position = head.origin;
    else if (record)
      position = glm::vec3(previous[index - 1]);
  } else if (state == ChainState::Alive && !drawn(head)) {
    if (k == 0)
      position += (maths::flowVelocity(position, field) * p.fieldStrength + head.launch) * p.dt;
    else  // chase where the particle ahead was last step
      position += (glm::vec3(previous[index - 1]) - position) * p.lerp;
  }
  // A drawn chain let go stays as it was drawn while it fades.
  // Inactive: stays put, so a recycled tube does not jump before it fades (its life is 0).
  return {position, head.life};
}

inline void stepChains(std::span<const HeadState> heads, uint32_t particlesPerChain,
                       std::span<const glm::vec4> previous, std::span<glm::vec4> next, const ChainParams& p) {
  const size_t count = heads.size() * particlesPerChain;
  if (particlesPerChain == 0 || previous.size() < count || next.size() < count)
    throw std::invalid_argument("stepChains: the position buffers hold fewer than chains x particlesPerChain");
  const maths::FieldSettings field = chainField(p);
  for (size_t i = 0; i < count; ++i) next[i] = chainParticle(heads, particlesPerChain, previous, uint32_t(i), field, p);
}

// The chain pass's push constants for one step (the block is shaders/neon/chain_push.h).
inline shader::NeonChainPush chainPush(uint32_t chainCount, uint32_t particlesPerChain, const ChainParams& p) {
  const maths::FieldSettings field = chainField(p);
  return {field.offsetY, p.dt, field.offsetZ, p.lerp, chainCount, particlesPerChain, p.fieldStrength, field.noiseScale};
}

// Workgroups of `groupSize` invocations (the pass's local size) for `particles` invocations. One row
// while it fits the 65535 groups every device allows in x; beyond that (65536 chains of 64 particles
// in groups of 64 need 65536 groups) rows are stacked in y, and the shader numbers invocations row by
// row, skipping the overhang.
inline glm::uvec2 chainGroups(uint64_t particles, uint32_t groupSize) {
  constexpr uint64_t kMaxGroups = 65535;
  const uint64_t groups = (particles + groupSize - 1) / groupSize;
  const uint64_t rows = (groups + kMaxGroups - 1) / kMaxGroups;
  if (rows == 0) return {0u, 0u};
  return {uint32_t((groups + rows - 1) / rows), uint32_t(rows)};
}

}  // namespace vitrine::neon
