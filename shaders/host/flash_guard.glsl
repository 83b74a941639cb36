// The flash guard's arithmetic, mirroring src/host/flash_guard_math.h line for line (the unit tests
// check that file; the constants and their reasons are there).
#ifndef HOST_FLASH_GUARD_GLSL
#define HOST_FLASH_GUARD_GLSL

const float kGeneralStep = 0.1;
const float kDarkerBelow = 0.8;
const float kRedShare = 0.8;
const float kRedScale = 320.0;
const float kRedStep = 20.0;
const int kMaxTransitions = 6;
const int kRing = 8;
const float kWindow = 1.0;
const float kWindowSlack = 1e-3;
const float kNever = 1e9;

float flashLuminance(vec3 linear) { return dot(clamp(linear, 0.0, 1.0), vec3(0.2126, 0.7152, 0.0722)); }

int generalTransition(vec3 before, vec3 after) {
  float a = flashLuminance(before), b = flashLuminance(after);
  if (abs(b - a) < kGeneralStep || min(a, b) >= kDarkerBelow) return 0;
  return b > a ? 1 : -1;
}

bool saturatedRed(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  float sum = c.r + c.g + c.b;
  return sum > 0.0 && c.r >= kRedShare * sum;
}

float redValue(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return max(0.0, c.r - c.g - c.b) * kRedScale;
}

int redTransition(vec3 before, vec3 after) {
  if (!saturatedRed(before) && !saturatedRed(after)) return 0;
  float change = redValue(after) - redValue(before);
  if (abs(change) <= kRedStep) return 0;
  return change > 0.0 ? 1 : -1;
}

int frameTransitions(uint rising, uint falling, uint area) {
  return (rising >= area ? 1 : 0) + (falling >= area ? 1 : 0);
}

#endif
