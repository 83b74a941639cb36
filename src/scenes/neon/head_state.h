#pragma once
// What the CPU particle engine tells the GPU about one chain's head each step (NeonHeadState, declared
// once for C++ and GLSL in shaders/neon/head_state.h) and the C++ helpers around it.
#include "maths/hash.h"
#include "shaders/neon/head_state.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace vitrine::neon {

// The record itself is the shader's (its layout checked against chains.comp by the build).
using HeadState = shader::NeonHeadState;
static_assert(std::is_trivially_copyable_v<HeadState>, "copied between threads and into mapped memory");

// HeadState::state.
enum class ChainState : uint32_t {
  Inactive = shader::NEON_CHAIN_INACTIVE,          // a free slot: the GPU leaves the chain where it is
  Initialising = shader::NEON_CHAIN_INITIALISING,  // the first steps after a release: the GPU places the chain
  Alive = shader::NEON_CHAIN_ALIVE,                // life falls; the head swims and the followers chase it
};

// Steps a released head spends initialising before its life starts to fall. Two, so that a renderer
// that shows the previous step's snapshot still sees one initialising state and places the chain.
inline constexpr uint32_t kInitialisingSteps = 2;

// Bits of HeadState::flags. A steered head is a pen: the GPU puts it where the CPU says (origin, moved
// by every steer) instead of letting it swim, so the chain behind it draws the pen's path as one tube.
inline constexpr uint32_t kHeadSteered = shader::NEON_HEAD_STEERED;

// A free head leaves its release point at this speed, m/s, in a direction of its own on top of the
// flow: tubes have length even in a still field (field_strength 0).
inline constexpr float kLaunchSpeed = 0.6f;

// The launch direction: in the facade's plane (the tube reads side-on), from the release serial.
// Computed once, here on the CPU, and handed to the GPU in HeadState::launch: a GPU's own sin and cos
// differ from the C library's in the last bits, and the chain pass is to integrate exactly what
// its C++ reference does, on every driver (see shaders/neon/chains.comp).
inline glm::vec3 launchVelocity(uint32_t serial) {
  const float angle = maths::hash01(glm::uvec3(serial, 0x6e656f6eu, 7u)) * 6.2831853f;
  return glm::vec3(std::cos(angle), std::sin(angle), 0.0f) * kLaunchSpeed;
}

inline ChainState chainState(const HeadState& head) { return ChainState(head.state); }
inline bool steered(const HeadState& head) { return (head.flags & kHeadSteered) != 0u; }

}  // namespace vitrine::neon
