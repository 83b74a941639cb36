#pragma once
// Real time turned into whole fixed simulation steps, so a scene moves the same at any frame rate.
// After a stall only a few steps are made up: the simulation slows down for a moment rather than
// spending ever longer catching up.
#include <algorithm>
#include <utility>

namespace vitrine::host {

class FixedStep {
 public:
  FixedStep(double step, int maxCatchUp) : step_(step), maxCatchUp_(maxCatchUp) { restart(); }

  // A fresh scene gets its first step at once, so it is updated before it is first drawn.
  void restart() { accumulated_ = step_; }

  // The number of steps due once `elapsed` more seconds of real time have passed.
  int advance(double elapsed) {
    accumulated_ += elapsed;
    const int due = std::min(static_cast<int>(accumulated_ / step_), maxCatchUp_);
    accumulated_ = std::min(accumulated_ - due * step_, step_);  // what is beyond the cap is dropped
    return due;
  }

 private:
  double step_;
  int maxCatchUp_;
  double accumulated_ = 0.0;
};

// The gallery's hand on time: pause (P), one step at a time while paused (.), and a speed (0-4x)
// that scales real time before it becomes steps. Headless and record runs never see it.
struct TimeControl {
  static constexpr float kMaxSpeed = 4.0f;
  bool paused = false;
  float speed = 1.0f;
  bool stepRequested = false;  // '.' while paused: exactly one step at the next frame

  // The steps due for `elapsed` seconds of real time.
  int due(FixedStep& steps, double elapsed) {
    if (paused) return std::exchange(stepRequested, false) ? 1 : (steps.advance(0.0), 0);
    stepRequested = false;
    return steps.advance(elapsed * double(std::clamp(speed, 0.0f, kMaxSpeed)));
  }
};

}  // namespace vitrine::host
