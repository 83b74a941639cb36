#pragma once
// Real time turned into whole fixed simulation steps, so a scene moves the same at any frame rate.
// The gallery's clock follows the wall clock for as long as the simulation alone can keep up: a slow
// frame (a big window on a CPU device, 1 fps) is followed by as many steps as the time it took, only
// the drawing is skipped. Steps are given up only when running them would take longer than the time
// they stand for (the simulation itself is too slow), or after a stall of more than kMaxGap (a window
// dragged, a debugger); then the clock falls behind and says so (FixedStep::behind).
#include <algorithm>
#include <climits>
#include <cmath>
#include <iterator>
#include <utility>

namespace vitrine::host {

class FixedStep {
 public:
  explicit FixedStep(double step) : step_(step) { restart(); }

  // A fresh scene gets its first step at once, so it is updated before it is first drawn.
  void restart() {
    accumulated_ = step_;
    kept_ = 1.0;
    droppedSeconds_ = 0.0;
  }

  // The number of steps due once `elapsed` more seconds of (scaled) real time have passed, at most
  // `affordable` of them; what is beyond that is dropped, not owed, and counted as falling behind, as
  // is `lost`: time that passed but is not to be simulated at all (a stall), and `givenUp`: simulated
  // time that steps stood for but the scene's GPU simulation could not run (Scene::takeGivenUpSeconds).
  int advance(double elapsed, int affordable = INT_MAX, double lost = 0.0, double givenUp = 0.0) {
    if (!(elapsed >= 0.0)) elapsed = 0.0;
    if (!(lost >= 0.0)) lost = 0.0;
    if (!(givenUp >= 0.0)) givenUp = 0.0;
    accumulated_ += elapsed;
    const double whole = std::floor(accumulated_ / step_);
    const int due = whole >= double(INT_MAX) ? INT_MAX : int(whole);
    const int run = std::min(due, std::max(affordable, 0));
    accumulated_ -= double(due) * step_;  // the fraction of a step carries over
    const double dropped = std::min(double(due - run) * step_ + lost + givenUp, elapsed + lost);
    droppedSeconds_ = dropped;
    // The share of real time the simulation kept, smoothed over about a second of frames.
    if (const double passed = elapsed + lost; passed > 0.0) {
      const double share = std::clamp(1.0 - dropped / passed, 0.0, 1.0);
      const double weight = std::min(1.0, passed);
      kept_ += (share - kept_) * weight;
    }
    return run;
  }

  double step() const { return step_; }
  // Seconds of simulation dropped at the last advance (0 while it keeps up).
  double dropped() const { return droppedSeconds_; }
  // The share of real time the simulation has been keeping lately, 0..1 (1: it follows the clock).
  double kept() const { return kept_; }
  bool behind() const { return kept_ < 0.99; }

 private:
  double step_;
  double accumulated_ = 0.0;
  double kept_ = 1.0;
  double droppedSeconds_ = 0.0;
};

// What one simulation step costs in CPU time, smoothed, and so how many steps fit in a frame.
class StepCost {
 public:
  void measured(int steps, double seconds) {
    if (steps <= 0 || !(seconds >= 0.0)) return;
    const double each = seconds / steps;
    perStep_ = perStep_ > 0.0 ? perStep_ + (each - perStep_) * 0.2 : each;
  }
  double perStep() const { return perStep_; }
  // Steps the simulation can run in `elapsed` seconds of real time: all that are due while a step
  // costs less than the time it stands for. At least one, so a slow scene still moves.
  int affordable(double elapsed) const {
    if (perStep_ <= 0.0) return INT_MAX;
    const double fit = std::floor(elapsed / perStep_);
    return fit >= double(INT_MAX) ? INT_MAX : std::max(1, int(fit));
  }

 private:
  double perStep_ = 0.0;
};

// The gallery's hand on time: pause (P), one step at a time while paused (.), and a speed (0-4x)
// that scales real time before it becomes steps ([ slower, ] faster, \ back to 1x). Headless and
// record runs never see it.
struct TimeControl {
  static constexpr float kMaxSpeed = 4.0f;
  // A frame that took longer than this is a stall (a window dragged, a debugger), not a slow frame:
  // the time beyond it is not simulated.
  static constexpr double kMaxGap = 2.0;
  bool paused = false;
  float speed = 1.0f;
  bool stepRequested = false;  // '.' while paused: exactly one step at the next frame

  // A speed as the field and the keys may set it: within 0-4x, a value that is not a number is 1x.
  static float clampSpeed(float wanted) { return std::isfinite(wanted) ? std::clamp(wanted, 0.0f, kMaxSpeed) : 1.0f; }
  // The speeds the keys step through, halving and doubling around 1x.
  void slower() {
    float next = 0.0f;
    for (float s : kLadder) if (s < speed - 1e-4f) next = s;
    speed = next;
  }
  void faster() {
    float next = kMaxSpeed;
    for (auto it = std::rbegin(kLadder); it != std::rend(kLadder); ++it) if (*it > speed + 1e-4f) next = *it;
    speed = next;
  }
  void normal() { speed = 1.0f; }

  // The steps due for `elapsed` seconds of real time, at most `affordable` (StepCost); `givenUp` as
  // FixedStep::advance takes it.
  int due(FixedStep& steps, double elapsed, int affordable = INT_MAX, double givenUp = 0.0) {
    speed = clampSpeed(speed);
    if (paused) return std::exchange(stepRequested, false) ? 1 : (steps.advance(0.0), 0);
    stepRequested = false;
    const double scale = double(speed);
    const double offered = std::min(elapsed, kMaxGap);  // a stall: the rest of it is lost
    return steps.advance(offered * scale, affordable, (elapsed - offered) * scale, givenUp);
  }

 private:
  static constexpr float kLadder[] = {0.0f, 0.125f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f};
};

}  // namespace vitrine::host
