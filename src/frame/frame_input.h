#pragma once
// What the host tells a scene about one fixed step: time, seed, the cursor, keys, dropped files and
// triggered actions. Plain values with no GPU in them, so input scripts and remote control can build
// them too.
#include <glm/vec2.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace vitrine {

struct CursorInput {
  glm::vec2 pixels{0.0f};      // framebuffer pixels, origin top-left (HiDPI-correct)
  glm::vec2 normalized{0.5f};  // 0..1 across the output, origin top-left
  bool dragging = false;       // left button held after a press inside the view
  glm::vec2 dragDelta{0.0f};   // normalised movement this frame while dragging
  float wheel = 0.0f;          // scroll steps this frame
  bool present = false;        // over the view and not over the menu: the cursor is "there" (bloom's vapour)
};

// One triggered action, checked against its declaration (name known, arity right, finite numbers).
struct ActionCall {
  std::string name;
  std::vector<float> args;
  bool operator==(const ActionCall&) const = default;
};

struct FrameInput {
  double time = 0.0;           // simulation seconds, advanced in fixed steps
  float dt = 1.0f / 60.0f;     // the fixed step
  uint64_t frame = 0;          // frames since the scene was created
  uint32_t seed = 0;           // --seed: makes every stochastic choice reproducible
  bool reducedMotion = false;  // --reduced-motion: freeze what moves on its own, and grain
  double lastGpuMs = 0.0;      // the previous frame's GPU time, for adaptive quality
  CursorInput cursor;
  std::vector<int> keysPressed;  // GLFW key codes pressed this frame (gallery and --input)
  std::vector<int> keysHeld;     // GLFW key codes down now (glass: Z held)
  std::vector<std::string> droppedFiles;  // paths dropped onto the window this frame (gallery only)
  std::vector<ActionCall> actions;        // the scene's own actions triggered this step, in order
  // The live sound (--audio-in, frame-exact, or the capture device) for pictures that draw it (ISF's
  // audio inputs): its newest mono samples, oldest first, and their spectrum, magnitudes 0..1 from DC
  // up (live::AudioAnalyser::recentSamples, spectrum). Empty while no sound comes in.
  std::vector<float> soundWave, soundSpectrum;

  bool pressed(int key) const { return std::find(keysPressed.begin(), keysPressed.end(), key) != keysPressed.end(); }
  bool held(int key) const { return std::find(keysHeld.begin(), keysHeld.end(), key) != keysHeld.end(); }
};

}  // namespace vitrine
