#version 460
// The flash guard, second pass, one invocation: from the measured areas, whether this frame's general
// and red transitions may be shown without more than three flashes of either kind in the second ending
// now (flash_guard_math.h's admit, for each kind), and the counts cleared for the next frame.
#extension GL_GOOGLE_include_directive : require
#include "flash_guard_blocks.h"
#include "flash_guard.glsl"
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer FlashGuard { HostFlashGuardState guard; };
layout(push_constant) uniform Push { HostFlashDecidePush pc; };

// One kind's ages grow by dt; its `wanted` transitions are admitted when the second ending now would
// hold no more than kMaxTransitions with them, taking the oldest slots.
bool admit(inout float ages[kRing], int wanted) {
  int inWindow = 0;
  for (int i = 0; i < kRing; ++i) {
    ages[i] = min(ages[i] + pc.dt, kNever);
    inWindow += ages[i] <= kWindow + kWindowSlack ? 1 : 0;
  }
  if (wanted == 0) return true;
  if (inWindow + wanted > kMaxTransitions) return false;
  for (int n = 0; n < wanted; ++n) {
    int oldest = 0;
    for (int i = 1; i < kRing; ++i)
      if (ages[i] > ages[oldest]) oldest = i;
    ages[oldest] = 0.0;
  }
  return true;
}

void main() {
  if (pc.reset != 0u) {
    for (int i = 0; i < kRing; ++i) {
      guard.generalAges[i] = kNever;
      guard.redAges[i] = kNever;
    }
    guard.showGeneral = 1u;
    guard.showRed = 1u;
    guard.limitedFrames = 0u;
  } else {
    float generalAges[kRing] = guard.generalAges;
    float redAges[kRing] = guard.redAges;
    bool general = admit(generalAges, frameTransitions(guard.generalRising, guard.generalFalling, pc.area));
    bool red = admit(redAges, frameTransitions(guard.redRising, guard.redFalling, pc.area));
    guard.generalAges = generalAges;
    guard.redAges = redAges;
    guard.showGeneral = general ? 1u : 0u;
    guard.showRed = red ? 1u : 0u;
    if (!general || !red) guard.limitedFrames += 1u;
  }
  guard.generalRising = 0u;
  guard.generalFalling = 0u;
  guard.redRising = 0u;
  guard.redFalling = 0u;
}
