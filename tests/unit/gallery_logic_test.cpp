// The gallery's pure logic: fixed steps from real time, and the pointer turned into scene input.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "host/cursor_tracker.h"
#include "host/fixed_step.h"
#include "host/menu.h"
#include "scenes/scene.h"

namespace vitrine::host {
namespace {

// The help card lists what exists: the number keys of the registered scenes, every gallery key the
// frame loop handles, and for every scene what its drag and keys do.
TEST(Help, ListsWhatExists) {
  int lo = 10, hi = 0;
  for (const auto& info : sceneRegistry()) {
    EXPECT_FALSE(info.input.empty()) << info.name << " has no input help";
    lo = std::min(lo, info.key);
    hi = std::max(hi, info.key);
  }
  EXPECT_EQ(sceneKeyRange(), std::to_string(lo) + "-" + std::to_string(hi));
  std::vector<std::string_view> keys;
  for (const auto& [key, does] : galleryKeys()) {
    EXPECT_FALSE(does.empty()) << key;
    keys.push_back(key);
  }
  for (const char* key : {"Tab", "F1, ?", "P", ".", "F5", "V", "M", "F11", "F12", "Esc"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
}

TEST(TimeControl, PauseStepAndSpeed) {
  FixedStep steps(0.01, 4);
  TimeControl time;
  steps.advance(0.0);
  EXPECT_EQ(time.due(steps, 0.02), 2);
  time.speed = 2.0f;  // twice as fast: 0.02 s of real time is four steps
  EXPECT_EQ(time.due(steps, 0.02), 4);
  time.speed = 0.5f;
  EXPECT_EQ(time.due(steps, 0.02), 1);
  time.paused = true;
  EXPECT_EQ(time.due(steps, 1.0), 0) << "paused: real time passes, the scene does not";
  time.stepRequested = true;
  EXPECT_EQ(time.due(steps, 1.0), 1) << "one step on request";
  EXPECT_EQ(time.due(steps, 1.0), 0) << "and only one";
  time.paused = false;
  time.speed = 1.0f;
  EXPECT_EQ(time.due(steps, 0.01), 1) << "resuming does not make up the paused time";
  time.speed = 0.0f;
  EXPECT_EQ(time.due(steps, 1.0), 0) << "speed 0 holds the scene like a pause";
}

TEST(FixedStep, TurnsRealTimeIntoWholeStepsAndCapsCatchUp) {
  FixedStep steps(1.0 / 60.0, 4);
  EXPECT_EQ(steps.advance(0.0), 1);  // a fresh scene is updated before it is first drawn
  EXPECT_EQ(steps.advance(0.5 / 60.0), 0);
  EXPECT_EQ(steps.advance(0.6 / 60.0), 1);  // the halves add up
  EXPECT_EQ(steps.advance(2.0 / 60.0), 2);
  EXPECT_EQ(steps.advance(10.0), 4);  // a stall: at most four steps made up
  EXPECT_LE(steps.advance(0.0), 1);   // and the rest dropped, not owed
  steps.restart();
  EXPECT_EQ(steps.advance(0.0), 1);
}

Pointer at(float x, float y, bool held, bool pressed = false) {
  return Pointer{{x, y}, {200, 100}, held, pressed, 0.0f};
}

TEST(CursorTracker, DragsStartOnlyOutsideTheMenuAndAccumulateUntilTaken) {
  CursorTracker tracker;
  tracker.observe(at(100, 50, true, true), /*menuWantsMouse=*/true);
  tracker.observe(at(120, 50, true), false);
  EXPECT_FALSE(tracker.take().dragging);  // the press landed on the menu

  tracker.observe(at(100, 50, false), false);
  tracker.observe(at(100, 50, true, true), false);
  tracker.observe(at(120, 50, true), false);
  tracker.observe(at(140, 60, true), false);
  const CursorInput input = tracker.take();
  EXPECT_TRUE(input.dragging);
  EXPECT_FLOAT_EQ(input.dragDelta.x, 0.2f);  // 40 of 200 pixels, over two frames, taken once
  EXPECT_FLOAT_EQ(input.dragDelta.y, 0.1f);
  EXPECT_FLOAT_EQ(input.normalized.x, 0.7f);
  EXPECT_EQ(tracker.take().dragDelta, glm::vec2(0.0f));  // a second step does not repeat it

  tracker.observe(at(140, 60, false), false);
  EXPECT_FALSE(tracker.take().dragging);
}

TEST(CursorTracker, WheelGoesToTheSceneOnlyWhenTheMenuDoesNotWantIt) {
  CursorTracker tracker;
  tracker.observe(Pointer{{0, 0}, {10, 10}, false, false, 2.0f}, true);
  EXPECT_EQ(tracker.take().wheel, 0.0f);
  tracker.observe(Pointer{{0, 0}, {10, 10}, false, false, 2.0f}, false);
  tracker.observe(Pointer{{0, 0}, {10, 10}, false, false, 1.0f}, false);
  EXPECT_EQ(tracker.take().wheel, 3.0f);
}

}  // namespace
}  // namespace vitrine::host
