#pragma once
// What the CPU particle engine tells the GPU about one chain's head each step: where it was released,
// how much life it has left, which state it is in and the drift it was launched with. Uploaded as-is
// into a std430 storage buffer; mirrored by shaders/neon/head_state.glsl.
#include "maths/hash.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace vitrine::neon {

// info.x of a HeadState.
enum class ChainState : uint32_t {
  Inactive = 0,      // a free slot: the GPU leaves the chain where it is
  Initialising = 1,  // the first two steps after a release: the GPU places the whole chain at the origin
  Alive = 2,         // life falls; the head moves through the field and the followers chase it
};

// Steps a released head spends initialising before its life starts to fall. Two, so that a renderer
// that shows the previous step's snapshot still sees one initialising state and places the chain.
inline constexpr uint32_t kInitialisingSteps = 2;

// Bits of info.w. A steered head is a pen: the GPU puts it where the CPU says (originLife.xyz, moved by
// every steer) instead of letting it swim, so the chain behind it draws the pen's path as one tube.
inline constexpr uint32_t kHeadSteered = 1u;

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

struct HeadState {
  glm::vec4 originLife{0.0f};  // xyz: release position (world), w: life, 1 at release down to 0
  glm::uvec4 info{0u};         // x: ChainState, y: release serial (1, 2, ...), z: steps since release, w: kHead* bits
  glm::vec4 launch{0.0f};      // xyz: launchVelocity(serial), m/s, added to the flow while it swims; w: 0
};
static_assert(sizeof(HeadState) == 48 && alignof(HeadState) <= 16, "three std430 vec4s, no padding");
static_assert(std::is_trivially_copyable_v<HeadState>, "copied between threads and into mapped memory");

inline ChainState chainState(const HeadState& head) { return ChainState(head.info.x); }
inline bool steered(const HeadState& head) { return (head.info.w & kHeadSteered) != 0u; }

}  // namespace vitrine::neon
