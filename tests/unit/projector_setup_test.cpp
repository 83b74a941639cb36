// Projector setup: corners taken by a press near them, dragged, nudged by the arrows; a fold refused;
// Enter keeps the pin and Esc puts back the one setup started with; F7 moves on to the next output.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include "host/present/projector_setup.h"

namespace vitrine::host {
namespace {

constexpr VkExtent2D kProjectorOutput{1000, 500};

Pointer at(glm::vec2 pixels, bool held, bool pressed = false) { return {pixels, kProjectorOutput, held, pressed, 0.0f, true}; }

TEST(ProjectorSetup, APressNearACornerTakesItAndDraggingMovesIt) {
  ProjectorSetup setup;
  maths::OutputWarp warp;
  setup.start(warp);
  setup.pointer(at({500.0f, 250.0f}, true, true), warp);  // the middle: no corner within reach
  EXPECT_FALSE(setup.held());
  setup.pointer(at({990.0f, 490.0f}, true, true), warp);  // near the bottom-right corner
  ASSERT_EQ(setup.held(), 2);
  setup.pointer(at({900.0f, 450.0f}, true), warp);
  EXPECT_FLOAT_EQ(warp.corners[2].x, 0.9f);
  EXPECT_FLOAT_EQ(warp.corners[2].y, 0.9f);
  setup.pointer(at({800.0f, 400.0f}, false), warp);  // released: it stays where it was let go
  EXPECT_FALSE(setup.held());
  EXPECT_FLOAT_EQ(warp.corners[2].x, 0.9f);
}

// A slow frame can hold a drag's last moves and its release: the corner goes where the button was
// let go, not where it was when the frame began, nor where the cursor went after.
TEST(ProjectorSetup, AReleaseInTheSameFrameAsTheLastMoveKeepsThatMove) {
  ProjectorSetup setup;
  maths::OutputWarp warp;
  setup.start(warp);
  setup.pointer(at({990.0f, 490.0f}, true, true), warp);
  ASSERT_EQ(setup.held(), 2);
  setup.pointer(at({920.0f, 460.0f}, true), warp);
  Pointer last = at({700.0f, 300.0f}, false);  // moved on to 900, 450, let go, then away
  last.releasedAt = glm::vec2(900.0f, 450.0f);
  setup.pointer(last, warp);
  EXPECT_FALSE(setup.held());
  EXPECT_FLOAT_EQ(warp.corners[2].x, 0.9f);
  EXPECT_FLOAT_EQ(warp.corners[2].y, 0.9f);
}

TEST(ProjectorSetup, AFoldIsNotTaken) {
  ProjectorSetup setup;
  maths::OutputWarp warp;
  setup.start(warp);
  setup.pointer(at({0.0f, 0.0f}, true, true), warp);  // the top-left corner...
  setup.pointer(at({1000.0f, 500.0f}, true), warp);   // ...dragged past the bottom-right: a fold
  EXPECT_EQ(warp.corners[0], glm::vec2(0.0f));
  EXPECT_EQ(maths::checkWarp(warp), "");
}

TEST(ProjectorSetup, ArrowsNudgeAndEnterKeepsAndEscapeUndoes) {
  ProjectorSetup setup;
  maths::OutputWarp warp;
  EXPECT_EQ(setup.key(GLFW_KEY_LEFT, false, kProjectorOutput, warp), ProjectorSetup::Key::Ignored);  // not in setup
  setup.start(warp);
  EXPECT_EQ(setup.key(GLFW_KEY_TAB, false, kProjectorOutput, warp), ProjectorSetup::Key::Used);  // the top-right corner
  setup.key(GLFW_KEY_LEFT, false, kProjectorOutput, warp);
  setup.key(GLFW_KEY_DOWN, true, kProjectorOutput, warp);
  EXPECT_FLOAT_EQ(warp.corners[1].x, 0.999f);
  EXPECT_FLOAT_EQ(warp.corners[1].y, 0.02f);
  maths::OutputWarp kept = warp;
  EXPECT_EQ(setup.key(GLFW_KEY_ENTER, false, kProjectorOutput, warp), ProjectorSetup::Key::Kept);
  EXPECT_FALSE(setup.active());
  EXPECT_EQ(warp, kept);
  setup.start(warp);
  setup.key(GLFW_KEY_RIGHT, true, kProjectorOutput, warp);
  EXPECT_EQ(setup.key(GLFW_KEY_ESCAPE, false, kProjectorOutput, warp), ProjectorSetup::Key::Undone);
  EXPECT_EQ(warp, kept);
}

// F7 in setup keeps this output's pin and hands over to the next output's, which starts at its own.
TEST(ProjectorSetup, F7KeepsThisPinForTheNextOutput) {
  ProjectorSetup setup;
  maths::OutputWarp main, second;
  second.mirror = true;
  setup.start(main);
  setup.key(GLFW_KEY_RIGHT, false, kProjectorOutput, main);
  const maths::OutputWarp kept = main;
  EXPECT_EQ(setup.key(GLFW_KEY_F7, false, kProjectorOutput, main), ProjectorSetup::Key::Next);
  EXPECT_FALSE(setup.active());
  setup.start(second);
  setup.key(GLFW_KEY_DOWN, false, kProjectorOutput, second);
  EXPECT_EQ(setup.key(GLFW_KEY_ESCAPE, false, kProjectorOutput, second), ProjectorSetup::Key::Undone);
  EXPECT_TRUE(second.mirror);
  EXPECT_EQ(second.corners[0], glm::vec2(0.0f));  // undone to its own start, not the main pin
  EXPECT_EQ(main, kept);
}

// A corner dragged onto the output's own corner lands exactly on it (the last pixel is 999 of 1000,
// not the edge), and Backspace puts every corner back where an unwarped picture has them.
TEST(ProjectorSetup, CornersSnapToTheEdgesAndBackspaceUnwarps) {
  ProjectorSetup setup;
  maths::OutputWarp warp;
  setup.start(warp);
  setup.pointer(at({990.0f, 490.0f}, true, true), warp);
  ASSERT_EQ(setup.held(), 2);
  setup.pointer(at({800.0f, 400.0f}, true), warp);
  setup.pointer(at({999.0f, 499.0f}, true), warp);
  setup.pointer(at({999.0f, 499.0f}, false), warp);
  EXPECT_EQ(warp.corners[2], glm::vec2(1.0f, 1.0f));
  setup.pointer(at({1.0f, 1.0f}, true, true), warp);
  setup.pointer(at({100.0f, 60.0f}, false), warp);
  setup.pointer(at({990.0f, 10.0f}, true, true), warp);
  setup.pointer(at({900.0f, 50.0f}, false), warp);
  ASSERT_NE(warp, maths::OutputWarp{});
  warp.quarterTurns = 1;  // only the corners go back
  EXPECT_EQ(setup.key(GLFW_KEY_BACKSPACE, false, kProjectorOutput, warp), ProjectorSetup::Key::Used);
  EXPECT_EQ(warp.corners, maths::OutputWarp{}.corners);
  EXPECT_EQ(warp.quarterTurns, 1);
  EXPECT_TRUE(setup.active());
}

}  // namespace
}  // namespace vitrine::host
