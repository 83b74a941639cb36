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
// by every steer) instead of letting it swim, and its chain records the pen's path, a point every
// 0.6 m (kPenSpacingSquared). A drawn chain is a pen's, while it draws and after: let go, it keeps the shape
// of the whole stroke where it was drawn and fades over kDrawnFadeSeconds.
inline constexpr uint32_t kHeadSteered = shader::NEON_HEAD_STEERED;
inline constexpr uint32_t kHeadDrawn = shader::NEON_HEAD_DRAWN;
inline const float kPenSpacingSquared = shader::NEON_PEN_SPACING_SQUARED;  // (0.6 m)^2
inline constexpr float kDrawnFadeSeconds = 2.0f;
// Below this life a tube's gas dims, smoothly to nothing at 0 (the tube shader's fade); a drawn tube
// let go starts here, so it fades from full brightness over kDrawnFadeSeconds.
inline const float kFadeLife = shader::NEON_FADE_LIFE;

// A free head leaves its release point at this speed, m/s, in a direction of its own on top of the
// flow: the tube sweeps, and it has length even in a still field (field_strength 0).
inline constexpr float kLaunchSpeed = 3.5f;
// Heads are launched across the facade: each toward a point of its own on the release plane, within
// kLaunchHalfWidth and kLaunchHalfHeight of the facade's middle (x, y), so a tube released near an edge
// sweeps over the building rather than off the frame, and the tubes cross all over it, not in one spot.
inline constexpr float kLaunchTowardX = 0.0f, kLaunchTowardY = 9.0f;
inline constexpr float kLaunchHalfWidth = 14.0f, kLaunchHalfHeight = 7.0f;

// The launch velocity: in the facade's plane (the tube reads side-on), its aim from the release serial.
// Computed once, here on the CPU, and handed to the GPU in HeadState::launch: a GPU's own sin and cos
// differ from the C library's in the last bits, and the chain pass is to integrate exactly what
// its C++ reference does, on every driver (see shaders/neon/chains.comp).
inline glm::vec3 launchVelocity(uint32_t serial, glm::vec3 origin) {
  const auto spread = [serial](uint32_t axis) {  // -1 .. 1
    return maths::hash01(glm::uvec3(serial, 0x6e656f6eu, axis)) * 2.0f - 1.0f;
  };
  const float aimX = kLaunchTowardX + spread(7u) * kLaunchHalfWidth;
  const float aimY = kLaunchTowardY + spread(8u) * kLaunchHalfHeight;
  const float angle = std::atan2(aimY - origin.y, aimX - origin.x);
  return glm::vec3(std::cos(angle), std::sin(angle), 0.0f) * kLaunchSpeed;
}

inline ChainState chainState(const HeadState& head) { return ChainState(head.state); }
inline bool steered(const HeadState& head) { return (head.flags & kHeadSteered) != 0u; }
inline bool drawn(const HeadState& head) { return (head.flags & kHeadDrawn) != 0u; }

}  // namespace vitrine::neon
