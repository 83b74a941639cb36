// The gallery's pure logic: fixed steps from real time, the pointer turned into scene input, and the
// time it showed frames for.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "host/cursor_tracker.h"
#include "host/gallery/fixed_step.h"
#include "host/ui/menu.h"
#include "host/gallery/shown_time.h"
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
  for (const char* key : {"Tab", "F1, ?", "P", ".", "[  ]", "\\", "F5", "V", "M", "F11", "F12", "L", "Esc"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
}

// The closing frame rate counts the time frames were shown: spells minimised after the first frame are
// left out, and one before it (a window started minimised) was never part of the count.
TEST(ShownTime, LeavesMinimisedSpellsOut) {
  using namespace std::chrono_literals;
  const ShownTime::Clock::time_point t0{};
  ShownTime shown;
  EXPECT_EQ(shown.seconds(t0 + 5s), 0.0) << "nothing shown yet";
  shown.hidden(t0, t0 + 3s);  // before the first frame
  shown.firstShown(t0 + 4s);
  EXPECT_DOUBLE_EQ(shown.seconds(t0 + 6s), 2.0);
  shown.hidden(t0 + 6s, t0 + 66s);  // a minute minimised
  shown.hidden(t0 + 67s, t0 + 68s);
  EXPECT_DOUBLE_EQ(shown.seconds(t0 + 70s), 5.0) << "66 s since the first frame, 61 of them minimised";
}

TEST(TimeControl, PauseStepAndSpeed) {
  FixedStep steps(0.01);
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

TEST(FixedStep, TurnsRealTimeIntoWholeSteps) {
  FixedStep steps(1.0 / 60.0);
  EXPECT_EQ(steps.advance(0.0), 1);  // a fresh scene is updated before it is first drawn
  EXPECT_EQ(steps.advance(0.5 / 60.0), 0);
  EXPECT_EQ(steps.advance(0.6 / 60.0), 1);  // the halves add up
  EXPECT_EQ(steps.advance(2.0 / 60.0), 2);
  steps.restart();
  EXPECT_EQ(steps.advance(0.0), 1);
}

// Below 15 fps the simulation fell behind the clock (at most four steps a frame: at 1 fps
// neon and bloom ran at a fifteenth of their speed). While the simulation alone keeps up, every step
// that is due runs, however slow the frames.
TEST(FixedStep, FollowsTheWallClockAtOneFramePerSecond) {
  const double dt = 1.0 / 60.0;
  FixedStep steps(dt);
  TimeControl time;
  StepCost cost;
  steps.advance(0.0);
  int simulated = 0;
  for (int frame = 0; frame < 10; ++frame) {  // ten frames of a second each
    const int due = time.due(steps, 1.0, cost.affordable(1.0));
    cost.measured(due, due * 0.0002);  // a step costs 0.2 ms: the simulation keeps up easily
    simulated += due;
  }
  EXPECT_NEAR(simulated * dt, 10.0, 2 * dt) << "ten seconds of wall clock are ten seconds of simulation";
  EXPECT_FALSE(steps.behind());
  time.speed = 2.0f;  // twice as fast: two seconds of simulation a second
  EXPECT_NEAR(time.due(steps, 1.0, cost.affordable(1.0)) * dt, 2.0, 2 * dt);
}

// When a step costs more than the time it stands for, running them all would only make the next
// frame longer: the clock falls behind, and says by how much.
TEST(FixedStep, FallsBehindOnlyWhenTheSimulationCannotKeepUp) {
  const double dt = 1.0 / 60.0;
  FixedStep steps(dt);
  TimeControl time;
  StepCost cost;
  steps.advance(0.0);
  cost.measured(1, 2.0 * dt);  // each step takes twice its own time
  int simulated = 0;
  for (int frame = 0; frame < 10; ++frame) {
    const int due = time.due(steps, 1.0, cost.affordable(1.0));
    cost.measured(due, due * 2.0 * dt);
    simulated += due;
  }
  EXPECT_NEAR(simulated * dt, 5.0, 0.1) << "half the clock: as many steps as fit in the time";
  EXPECT_TRUE(steps.behind());
  EXPECT_NEAR(steps.kept(), 0.5, 0.05);
  // Cheap again: it catches up with the clock (not with the time lost) and says so no more.
  for (int frame = 0; frame < 300; ++frame) {
    const int due = time.due(steps, dt, cost.affordable(dt));
    cost.measured(due, due * 0.0001);
  }
  EXPECT_FALSE(steps.behind());
}

// A stall (a window dragged for ten seconds) is not made up: two seconds at most, and it is reported.
TEST(FixedStep, AStallIsNotMadeUp) {
  const double dt = 1.0 / 60.0;
  FixedStep steps(dt);
  TimeControl time;
  steps.advance(0.0);
  EXPECT_NEAR(time.due(steps, 10.0) * dt, TimeControl::kMaxGap, 2 * dt);
  EXPECT_TRUE(steps.behind());
}

// Time a scene's GPU simulation gave up (bloom below 2 fps) is falling behind, as dropped steps are.
TEST(FixedStep, TimeAScenesSimulationGaveUpIsFallingBehind) {
  const double dt = 1.0 / 60.0;
  FixedStep steps(dt);
  TimeControl time;
  steps.advance(0.0);
  for (int frame = 0; frame < 10; ++frame) EXPECT_EQ(time.due(steps, 1.0, INT_MAX, frame ? 0.5 : 0.0), 60);
  EXPECT_TRUE(steps.behind());
  EXPECT_NEAR(steps.kept(), 0.5, 0.05);
  for (int frame = 0; frame < 10; ++frame) time.due(steps, 1.0);
  EXPECT_FALSE(steps.behind()) << "keeping up again";
  time.due(steps, 1.0, INT_MAX, 5.0);
  EXPECT_EQ(steps.kept(), 0.0) << "more given up than passed counts as all of it, never below";
}

// The speed field accepted and showed any number ("111111114326016.00x").
TEST(TimeControl, SpeedStaysInItsRangeAndKeysStepThroughIt) {
  EXPECT_EQ(TimeControl::clampSpeed(111111114326016.0f), TimeControl::kMaxSpeed);
  EXPECT_EQ(TimeControl::clampSpeed(-3.0f), 0.0f);
  EXPECT_EQ(TimeControl::clampSpeed(std::numeric_limits<float>::quiet_NaN()), 1.0f);
  EXPECT_EQ(TimeControl::clampSpeed(std::numeric_limits<float>::infinity()), 1.0f);
  FixedStep steps(0.01);
  TimeControl time;
  time.speed = 1e9f;  // however it got there, it runs at 4x at most
  steps.advance(0.0);
  EXPECT_EQ(time.due(steps, 0.01), 4);
  EXPECT_EQ(time.speed, TimeControl::kMaxSpeed);
  time.normal();
  EXPECT_EQ(time.speed, 1.0f);
  time.faster();
  EXPECT_EQ(time.speed, 2.0f);
  time.faster(), time.faster();
  EXPECT_EQ(time.speed, 4.0f) << "faster stops at the top of the range";
  time.speed = 1.5f;
  time.slower();
  EXPECT_EQ(time.speed, 1.0f) << "from a typed value, to the next step down";
  for (int i = 0; i < 10; ++i) time.slower();
  EXPECT_EQ(time.speed, 0.0f);
  time.faster();
  EXPECT_EQ(time.speed, 0.125f);
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

// A gallery opened under a resting pointer shows its first look: the pointer is the scene's once it
// moves past the window's settling slack, presses or leaves; a script's tracker takes it at once.
TEST(CursorTracker, APointerRestingOverANewGalleryWaitsUntilItMoves) {
  const auto inside = [](float x, float y) { return Pointer{{x, y}, {200, 100}, false, false, 0.0f, true}; };
  CursorTracker gallery(/*waitForMovement=*/true);
  gallery.observe(inside(100, 50), false);
  EXPECT_FALSE(gallery.take().present);
  gallery.observe(inside(101, 51), false);  // a window settling: a pixel or so
  EXPECT_FALSE(gallery.take().present);
  gallery.observe(inside(104, 50), false);
  EXPECT_TRUE(gallery.take().present);

  CursorTracker pressed(/*waitForMovement=*/true);
  pressed.observe(inside(100, 50), false);
  pressed.observe(Pointer{{100, 50}, {200, 100}, true, true, 0.0f, true}, false);
  EXPECT_TRUE(pressed.take().present);

  CursorTracker entering(/*waitForMovement=*/true);
  entering.observe(Pointer{{0, 0}, {200, 100}, false, false, 0.0f, false}, false);
  entering.observe(inside(100, 50), false);
  EXPECT_TRUE(entering.take().present) << "a pointer that comes in from outside is moving";

  CursorTracker script;
  script.observe(inside(100, 50), false);
  EXPECT_TRUE(script.take().present);
}

}  // namespace
}  // namespace vitrine::host
