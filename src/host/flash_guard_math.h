#pragma once
// The flash guard's arithmetic in plain C++: what counts as a transition of one pixel, how large an
// area must flash for a frame to count, and the one-second window that decides whether a frame's
// transitions may be shown. The unit tests check this; shaders/host/flash_guard.glsl mirrors it line
// for line, and the measuring script of the CLI test (tests/cli/flash_count.py) applies it to the frames
// written to disk.
//
// The thresholds are WCAG 2.3.1's (Understanding Success Criterion 2.3.1, "general flash and red flash
// thresholds"): a general flash is a pair of opposing changes in relative luminance of 10 % or more of
// the maximum where the darker image is below 0.80; a red flash is a pair of opposing transitions
// involving a saturated red. Either kind is harmful when it covers a quarter of any 10 degree visual
// field and happens more than three times in any one second.
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace vitrine::host::flash {

inline constexpr float kGeneralStep = 0.1f;     // a change in relative luminance that is a transition
inline constexpr float kDarkerBelow = 0.8f;     // ... when the darker of the two is below this
inline constexpr float kRedShare = 0.8f;        // R / (R + G + B) at or above: a saturated red
inline constexpr float kRedScale = 320.0f;      // the red value is (R - G - B) x 320 ...
inline constexpr float kRedStep = 20.0f;        // ... and a change of more than 20 in it is a transition
inline constexpr int kMaxFlashes = 3;           // in any one second
inline constexpr int kMaxTransitions = 2 * kMaxFlashes;  // a flash is a pair of opposing transitions
inline constexpr int kRing = 8;                 // transitions remembered: kMaxTransitions plus one frame's two
inline constexpr float kWindow = 1.0f;          // seconds
// Ages are sums of frame steps, so one that is a second old by the clock may read 0.99999 or 1.00001:
// a transition a whole second ago still counts, which errs on the side of fewer flashes.
inline constexpr float kWindowSlack = 1e-3f;
inline constexpr float kNever = 1e9f;           // the age of a transition that never happened
// WCAG's worked figure: a quarter of a 10 degree field is 341 x 256 pixels of a 1024 x 768 screen seen
// from a typical distance (a 15-17 inch screen at 22-26 inches). The guard assumes the output fills the
// same share of the viewer's sight as that screen, so the area is the same fraction of any output.
inline constexpr double kAreaFraction = (341.0 * 256.0) / (1024.0 * 768.0);

// Relative luminance of linear sRGB primaries, of what a display can show (0..1).
inline float luminance(glm::vec3 linear) {
  return glm::dot(glm::clamp(linear, glm::vec3(0.0f), glm::vec3(1.0f)), glm::vec3(0.2126f, 0.7152f, 0.0722f));
}

// +1 a rising general transition, -1 a falling one, 0 none.
inline int generalTransition(glm::vec3 before, glm::vec3 after) {
  const float a = luminance(before), b = luminance(after);
  if (std::abs(b - a) < kGeneralStep || std::min(a, b) >= kDarkerBelow) return 0;
  return b > a ? 1 : -1;
}

inline bool saturatedRed(glm::vec3 linear) {
  const glm::vec3 c = glm::clamp(linear, glm::vec3(0.0f), glm::vec3(1.0f));
  const float sum = c.r + c.g + c.b;
  return sum > 0.0f && c.r >= kRedShare * sum;
}

inline float redValue(glm::vec3 linear) {
  const glm::vec3 c = glm::clamp(linear, glm::vec3(0.0f), glm::vec3(1.0f));
  return std::max(0.0f, c.r - c.g - c.b) * kRedScale;
}

// +1 towards red, -1 away from it, 0 none: a change of more than 20 in the red value where either
// side is a saturated red.
inline int redTransition(glm::vec3 before, glm::vec3 after) {
  if (!saturatedRed(before) && !saturatedRed(after)) return 0;
  const float change = redValue(after) - redValue(before);
  if (std::abs(change) <= kRedStep) return 0;
  return change > 0.0f ? 1 : -1;
}

// The pixels that must change together for a frame to count as a transition, for an output of w x h.
inline uint32_t flashArea(uint32_t width, uint32_t height) {
  return std::max(1u, uint32_t(std::ceil(kAreaFraction * double(width) * double(height))));
}

// How many transitions a frame makes of one kind: one for the pixels rising if they cover the area,
// one for those falling if they do.
inline int frameTransitions(uint32_t rising, uint32_t falling, uint32_t area) {
  return (rising >= area ? 1 : 0) + (falling >= area ? 1 : 0);
}

// The ages, in seconds, of the transitions of one kind shown lately (kNever: a free slot).
using Ages = std::array<float, kRing>;

inline Ages neverFlashed() {
  Ages ages;
  ages.fill(kNever);
  return ages;
}

inline int transitionsInWindow(const Ages& ages) {
  int count = 0;
  for (const float age : ages) count += age <= kWindow + kWindowSlack ? 1 : 0;
  return count;
}

// One frame of one kind, `dt` seconds after the last: the ages grow, and the frame's `wanted`
// transitions are allowed when the second ending now would hold no more than kMaxTransitions with
// them. Allowed transitions take the oldest slots. Returns whether the frame may show its change.
inline bool admit(Ages& ages, float dt, int wanted) {
  for (float& age : ages) age = std::min(age + dt, kNever);
  if (wanted == 0) return true;
  if (transitionsInWindow(ages) + wanted > kMaxTransitions) return false;
  for (int n = 0; n < wanted; ++n) *std::max_element(ages.begin(), ages.end()) = 0.0f;
  return true;
}

}  // namespace vitrine::host::flash
