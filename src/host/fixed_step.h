#pragma once
// Real time turned into whole fixed simulation steps, so a scene moves the same at any frame rate.
// After a stall only a few steps are made up: the simulation slows down for a moment rather than
// spending ever longer catching up.
#include <algorithm>

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

}  // namespace vitrine::host
