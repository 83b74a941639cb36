// Scripted input: the file format, its errors, and the player that turns it into per-step input.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"
#include "host/input_script.h"
#include "scenes/catalogue.h"
#include "support/temp_folder.h"

namespace vitrine::host {
namespace {

using Kind = InputEvent::Kind;
constexpr VkExtent2D kOutput{200, 100};

std::string errorOf(std::string_view text) {
  try {
    parseInputScript(text, "s.txt");
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(InputScript, ParsesEveryVerb) {
  const InputScript script =
      parseInputScript("0 move 0.25 0.75\n0.5 down\n0.5 up\n1 wheel -2.5\n1.25 key a\n", "s.txt");
  ASSERT_EQ(script.events.size(), 5u);
  EXPECT_EQ(script.events[0].kind, Kind::Move);
  EXPECT_EQ(script.events[0].position, glm::vec2(0.25f, 0.75f));
  EXPECT_EQ(script.events[1].kind, Kind::Down);
  EXPECT_EQ(script.events[1].time, 0.5);
  EXPECT_EQ(script.events[2].kind, Kind::Up);
  EXPECT_EQ(script.events[3].kind, Kind::Wheel);
  EXPECT_EQ(script.events[3].wheel, -2.5f);
  EXPECT_EQ(script.events[4].kind, Kind::Key);
  EXPECT_EQ(script.events[4].key, GLFW_KEY_A);
  EXPECT_EQ(script.events[4].time, 1.25);
}

TEST(InputScript, IgnoresCommentsBlankLinesAndSpacing) {
  const InputScript script = parseInputScript(
      "# a comment\n\n   \n\t0.5\tdown   # pressed here\r\n# 0.6 up\n  1e0 move 1 0#no space needed\n", "s.txt");
  ASSERT_EQ(script.events.size(), 2u);
  EXPECT_EQ(script.events[0].kind, Kind::Down);
  EXPECT_EQ(script.events[1].time, 1.0);
  EXPECT_EQ(script.events[1].position, glm::vec2(1.0f, 0.0f));
  EXPECT_TRUE(parseInputScript("", "s.txt").events.empty());
  EXPECT_TRUE(parseInputScript("# nothing\n", "s.txt").events.empty());
}

TEST(InputScript, KeyNamesAreCaseInsensitive) {
  EXPECT_EQ(keyFromName("a"), GLFW_KEY_A);
  EXPECT_EQ(keyFromName("Z"), GLFW_KEY_Z);
  EXPECT_EQ(keyFromName("0"), GLFW_KEY_0);
  EXPECT_EQ(keyFromName("9"), GLFW_KEY_9);
  EXPECT_EQ(keyFromName("F1"), GLFW_KEY_F1);
  EXPECT_EQ(keyFromName("f12"), GLFW_KEY_F12);
  EXPECT_EQ(keyFromName("Escape"), GLFW_KEY_ESCAPE);
  EXPECT_EQ(keyFromName("SPACE"), GLFW_KEY_SPACE);
  EXPECT_EQ(keyFromName("enter"), GLFW_KEY_ENTER);
  EXPECT_EQ(keyFromName("Tab"), GLFW_KEY_TAB);
  EXPECT_EQ(keyFromName("backspace"), GLFW_KEY_BACKSPACE);
  EXPECT_EQ(keyFromName("Left"), GLFW_KEY_LEFT);
  EXPECT_EQ(keyFromName("right"), GLFW_KEY_RIGHT);
  EXPECT_EQ(keyFromName("up"), GLFW_KEY_UP);
  EXPECT_EQ(keyFromName("down"), GLFW_KEY_DOWN);
  EXPECT_EQ(keyFromName("minus"), GLFW_KEY_MINUS);
  EXPECT_EQ(keyFromName("Left_Bracket"), GLFW_KEY_LEFT_BRACKET);
  EXPECT_EQ(keyFromName("grave"), GLFW_KEY_GRAVE_ACCENT);
  for (const char* unknown : {"", "f0", "f13", "f01", "aa", "esc", "ctrl"})
    EXPECT_FALSE(keyFromName(unknown).has_value()) << unknown;
  EXPECT_EQ(parseInputScript("0 key PERIOD\n0 key F5\n", "s.txt").events[1].key, GLFW_KEY_F5);
}

TEST(InputScript, RefusesMalformedLinesNamingFileAndLine) {
  struct Case {
    const char* text;
    const char* message;
  };
  const Case cases[] = {
      {"0 click", "s.txt:1: unknown verb 'click'; expected move, leave, down, up, wheel, key, hold, release or action"},
      {"# header\n\n0 Down", "s.txt:3: unknown verb 'Down'"},
      {"0.5", "s.txt:1: expected a verb after the time"},
      {"0 move 0.5", "s.txt:1: 'move' takes 2 arguments (X Y), got 1"},
      {"0 move 0.5 0.5 0.5", "s.txt:1: 'move' takes 2 arguments (X Y), got 3"},
      {"0 down now", "s.txt:1: 'down' takes 0 arguments, got 1"},
      {"0 up 1", "s.txt:1: 'up' takes 0 arguments, got 1"},
      {"0 wheel", "s.txt:1: 'wheel' takes 1 argument (STEPS), got 0"},
      {"0 key", "s.txt:1: 'key' takes 1 argument (NAME), got 0"},
      {"0 key a b", "s.txt:1: 'key' takes 1 argument (NAME), got 2"},
      {"soon down", "s.txt:1: time 'soon' is not a number"},
      {"0.5s down", "s.txt:1: time '0.5s' is not a number"},
      {"nan down", "s.txt:1: time 'nan' is not a finite number"},
      {"inf down", "s.txt:1: time 'inf' is not a finite number"},
      {"1e999 down", "s.txt:1: time '1e999' is not a finite number"},
      {"-1 down", "s.txt:1: time -1 is negative"},
      {"1 down\n0.5 up", "s.txt:2: time 0.5 is before the previous event's 1; times must not decrease"},
      {"0 move x 0.5", "s.txt:1: X 'x' is not a number"},
      {"0 move 0.5 -inf", "s.txt:1: Y '-inf' is not a finite number"},
      {"0 move 1.5 0.5", "s.txt:1: X 1.5 is outside 0..1"},
      {"0 move 0.5 -0.1", "s.txt:1: Y -0.1 is outside 0..1"},
      {"0 wheel lots", "s.txt:1: wheel steps 'lots' is not a number"},
      {"0 wheel nan", "s.txt:1: wheel steps 'nan' is not a finite number"},
      {"0 wheel 1e300", "s.txt:1: wheel steps 1e300 are out of range"},
      {"0 key esc", "s.txt:1: unknown key 'esc'; did you mean 'escape'? Known keys: a-z, 0-9, f1-f12, space"},
      {"0 key enterr", "s.txt:1: unknown key 'enterr'; did you mean 'enter'?"},
      {"0 key ctrl", "s.txt:1: unknown key 'ctrl'; known keys: a-z"},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf(c.text);
    EXPECT_TRUE(message.starts_with(c.message)) << c.text << "\n  gave: " << message;
  }
}

class InputScriptFiles : public test::TempFolderTest {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = folder_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  static std::string loadError(const std::filesystem::path& path) {
    try {
      loadInputScript(path);
    } catch (const Error& error) {
      return error.what();
    }
    return "(no error)";
  }
};

TEST_F(InputScriptFiles, LoadNamesTheFileInErrors) {
  const auto path = write("bad.txt", "0 down\n0.1 jump\n");
  EXPECT_EQ(loadError(path), path.string() + ":2: unknown verb 'jump'; expected move, leave, down, up, wheel, key, hold, "
                                 "release or action");
  EXPECT_EQ(loadInputScript(write("good.txt", "0 down\n")).events.size(), 1u);
}

TEST_F(InputScriptFiles, LoadRefusesFoldersDevicesMissingAndLargeFiles) {
  EXPECT_NE(loadError(folder_ / "missing.txt").find("does not exist"), std::string::npos);
  EXPECT_NE(loadError(folder_).find(", not a regular file"), std::string::npos);
  EXPECT_NE(loadError("/dev/null").find(", not a regular file"), std::string::npos);
  std::string big(1 << 20, '#');
  EXPECT_EQ(loadError(write("limit.txt", big)), "(no error)");  // exactly 1 MiB is fine
  EXPECT_NE(loadError(write("big.txt", big + "\n")).find("larger than 1 MiB"), std::string::npos);
}

TEST(InputScript, TheExampleScriptParses) {
  const auto example = std::filesystem::path(__FILE__).parent_path().parent_path() / "input" / "drag_example.txt";
  const InputScript script = loadInputScript(example);
  ASSERT_EQ(script.events.size(), 7u);
  EXPECT_EQ(script.events.back().key, GLFW_KEY_SPACE);
}

// Offscreen's clock: frame k shows start + k steps, with the step a float added up in a double.
std::vector<StepInput> play(std::string_view text, int steps, double start = 0.0) {
  InputPlayer player(parseInputScript(text, "s.txt"));
  std::vector<StepInput> out;
  FrameInput clock;
  clock.time = start;
  for (int k = 0; k < steps; ++k, clock.time += clock.dt) out.push_back(player.step(clock.time, kOutput));
  return out;
}

TEST(InputScript, PlayerAppliesAnEventAtTheFirstStepThatReachesIt) {
  const auto steps = play("0.5 key a\n", 40);
  for (int k = 0; k < 40; ++k) EXPECT_EQ(steps[k].keysPressed.size(), k == 30 ? 1u : 0u) << "step " << k;

  // The same with the step time computed exactly, or added up in doubles: rounding either way is absorbed.
  for (const bool accumulate : {false, true}) {
    InputPlayer player(parseInputScript("0.5 key a\n1 key b\n", "s.txt"));
    double time = 0.0;
    for (int k = 0; k <= 60; ++k) {
      if (!accumulate) time = k / 60.0;
      const auto keys = player.step(time, kOutput).keysPressed;
      EXPECT_EQ(keys.size(), k == 30 || k == 60 ? 1u : 0u) << "step " << k << (accumulate ? " added up" : "");
      if (accumulate) time += 1.0 / 60.0;
    }
    EXPECT_TRUE(player.finished());
  }
}

// glass' Z: a held key is pressed once, stays in keysHeld until its release, and a plain key press
// never holds.
TEST(InputScript, HeldKeysStayDownUntilReleased) {
  InputPlayer player(parseInputScript("0.1 hold z\n0.1 key a\n0.5 release z\n0.6 release q\n", "s.txt"));
  const auto first = player.step(0.1, kOutput);
  EXPECT_EQ(first.keysPressed, (std::vector<int>{GLFW_KEY_Z, GLFW_KEY_A}));
  EXPECT_EQ(first.keysHeld, std::vector<int>{GLFW_KEY_Z});
  const auto middle = player.step(0.3, kOutput);
  EXPECT_TRUE(middle.keysPressed.empty());
  EXPECT_EQ(middle.keysHeld, std::vector<int>{GLFW_KEY_Z});
  EXPECT_TRUE(player.step(0.5, kOutput).keysHeld.empty());
  EXPECT_TRUE(player.step(0.6, kOutput).keysHeld.empty());  // releasing a key that is up changes nothing
  EXPECT_TRUE(player.finished());
}

TEST(InputScript, PlayerPutsEarlyEventsInTheFirstStepAndKnowsWhenItIsDone) {
  InputPlayer player(parseInputScript("0 key a\n1 key b\n5 key c\n", "s.txt"));
  EXPECT_EQ(player.step(2.0, kOutput).keysPressed, (std::vector<int>{GLFW_KEY_A, GLFW_KEY_B}));
  EXPECT_FALSE(player.finished());
  EXPECT_TRUE(player.step(3.0, kOutput).keysPressed.empty());
  EXPECT_EQ(player.step(5.0, kOutput).keysPressed, std::vector<int>{GLFW_KEY_C});
  EXPECT_TRUE(player.finished());
}

TEST(InputScript, PlayerHoldsTheCursorBetweenLines) {
  const auto steps = play("0.1 move 0.25 0.75\n0.5 move 1 0\n", 40);
  EXPECT_EQ(steps[0].cursor.normalized, glm::vec2(0.5f));  // the centre until the first move
  EXPECT_EQ(steps[0].cursor.pixels, glm::vec2(100.0f, 50.0f));
  for (int k = 6; k < 30; ++k) {
    EXPECT_EQ(steps[k].cursor.normalized, glm::vec2(0.25f, 0.75f)) << "step " << k;
    EXPECT_EQ(steps[k].cursor.pixels, glm::vec2(50.0f, 75.0f)) << "step " << k;
    EXPECT_FALSE(steps[k].cursor.dragging);
    EXPECT_EQ(steps[k].cursor.dragDelta, glm::vec2(0.0f));  // moving without the button is no drag
  }
  EXPECT_EQ(steps[39].cursor.normalized, glm::vec2(1.0f, 0.0f));
}

TEST(InputScript, PlayerDragsLikeAMouse) {
  const auto steps = play("0 move 0.2 0.5\n0.25 down\n0.5 move 0.3 0.5\n0.75 move 0.35 0.4\n1 up\n", 70);
  glm::vec2 dragged(0.0f);
  for (int k = 0; k < 70; ++k) {
    EXPECT_EQ(steps[k].cursor.dragging, k >= 15 && k < 60) << "step " << k;
    dragged += steps[k].cursor.dragDelta;
  }
  EXPECT_NEAR(dragged.x, 0.15f, 1e-6f);
  EXPECT_NEAR(dragged.y, -0.1f, 1e-6f);
  EXPECT_NEAR(steps[30].cursor.dragDelta.x, 0.1f, 1e-6f);  // each move lands whole in its step
  EXPECT_EQ(steps[31].cursor.dragDelta, glm::vec2(0.0f));
}

TEST(InputScript, PlayerPressAndReleaseInOneStepStillDrags) {
  // A quick flick: pressed, moved and released between two steps. The tracker sees the press, so the
  // movement reaches the scene, and the drag is over by the time the step runs.
  const auto steps = play("0 move 0.5 0.5\n0.505 down\n0.505 move 0.6 0.5\n0.51 up\n", 33);
  EXPECT_NEAR(steps[31].cursor.dragDelta.x, 0.1f, 1e-6f);
  EXPECT_FALSE(steps[31].cursor.dragging);
  EXPECT_EQ(steps[32].cursor.dragDelta, glm::vec2(0.0f));
}

TEST(InputScript, PlayerSumsTheWheelPerStep) {
  const auto steps = play("0.105 wheel 1\n0.11 wheel 2.5\n0.2 wheel -1\n", 20);
  EXPECT_EQ(steps[6].cursor.wheel, 0.0f);
  EXPECT_EQ(steps[7].cursor.wheel, 3.5f);  // 0.105 and 0.11 both fall after 6/60 and by 7/60
  EXPECT_EQ(steps[8].cursor.wheel, 0.0f);
  EXPECT_EQ(steps[12].cursor.wheel, -1.0f);
  EXPECT_EQ(steps[13].cursor.wheel, 0.0f);
}

TEST(InputScript, PlayerGivesKeysInFileOrder) {
  const auto steps = play("0.2 key b\n0.2 key A\n0.2 key escape\n0.3 key 1\n", 20);
  EXPECT_EQ(steps[12].keysPressed, (std::vector<int>{GLFW_KEY_B, GLFW_KEY_A, GLFW_KEY_ESCAPE}));
  EXPECT_EQ(steps[18].keysPressed, std::vector<int>{GLFW_KEY_1});
  EXPECT_TRUE(steps[13].keysPressed.empty());
}

}  // namespace
}  // namespace vitrine::host

namespace vitrine::host {
namespace {

// A scene can tell the cursor is over the view (bloom's vapour is only there when it is): away until
// the first move, there after it, away again after `leave`, back with the next move.
TEST(InputScript, TheCursorIsPresentFromTheFirstMoveUntilItLeaves) {
  InputPlayer player(parseInputScript("0.1 move 0.5 0.5\n0.3 leave\n0.5 move 0.2 0.2\n", "s.txt"));
  EXPECT_FALSE(player.step(0.0, {200, 100}).cursor.present);
  EXPECT_TRUE(player.step(0.1, {200, 100}).cursor.present);
  EXPECT_TRUE(player.step(0.2, {200, 100}).cursor.present);
  EXPECT_FALSE(player.step(0.3, {200, 100}).cursor.present);
  EXPECT_TRUE(player.step(0.5, {200, 100}).cursor.present);
  EXPECT_NE(errorOf("0.1 leave now\n"), "(no error)");
}

TEST(InputScript, ActionsCarryTheirNumbersToTheirStep) {
  const InputScript script = parseInputScript("0.1 action release 0 6.5 -4\n0.2 action shuffle\n", "s.txt");
  ASSERT_EQ(script.events.size(), 2u);
  EXPECT_EQ(script.events[0].kind, InputEvent::Kind::Action);
  EXPECT_EQ(script.events[0].action, (ActionCall{"release", {0.0f, 6.5f, -4.0f}}));
  EXPECT_EQ(script.events[1].action, (ActionCall{"shuffle", {}}));
  InputPlayer player(script);
  EXPECT_TRUE(player.step(0.05, {64, 36}).actions.empty());
  EXPECT_EQ(player.step(0.1, {64, 36}).actions, std::vector<ActionCall>{script.events[0].action});
  EXPECT_EQ(errorOf("0 action"), "s.txt:1: 'action' takes the action's name, then its numbers");
  EXPECT_EQ(errorOf("0 action release 1 x"), "s.txt:1: action argument 'x' is not a number");
  EXPECT_EQ(errorOf("0 action release 1e300"), "s.txt:1: action argument 1e300 is out of range");
}

// Editors on Windows begin a UTF-8 file with a byte-order mark: the first line is still read.
TEST(InputScript, AcceptsAUtf8ByteOrderMark) {
  const InputScript script = parseInputScript("\xEF\xBB\xBF" "0.5 down\n1 up\n", "bom.txt");
  ASSERT_EQ(script.events.size(), 2u);
  EXPECT_EQ(script.events[0].kind, Kind::Down);
  EXPECT_DOUBLE_EQ(script.events[0].time, 0.5);
}

// Words quoted in errors come from the file: control bytes (an escape sequence that would rewrite the
// terminal, a NUL) are written as \xNN, never sent raw.
TEST(InputScript, ErrorsNeverEchoRawControlBytes) {
  EXPECT_EQ(errorOf("0 cl\x1b[2Jick"), "s.txt:1: unknown verb 'cl\\x1b[2Jick'; expected move, leave, down, up, "
                                        "wheel, key, hold, release or action");
  EXPECT_TRUE(errorOf("0 key \x07").starts_with("s.txt:1: unknown key '\\x07'; ")) << errorOf("0 key \x07");
  EXPECT_EQ(errorOf(std::string_view("\x01\x00 down", 7)), "s.txt:1: time '\\x01\\x00' is not a number");
  for (const std::string& text : {errorOf("0 \x1b]0;pwned\x07"), errorOf("0 move \x9b 0.5")})
    for (const char c : text) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << text;
}

// Unknown actions are found when the scene is known, after parsing: the error still names FILE:LINE.
TEST(InputScript, EventsKnowTheirLineForLaterErrors) {
  const InputScript script = parseInputScript("# a drag\n0.1 move 0.5 0.5\n\n0.5 action release 1 2\n", "drag.txt");
  ASSERT_EQ(script.events.size(), 2u);
  EXPECT_EQ(script.events[0].line, 2u);
  EXPECT_EQ(script.events[1].line, 4u);
  EXPECT_EQ(whereInScript(script, script.events[1], "scene kifs has no action 'release' (it has none)"),
            "drag.txt:4: scene kifs has no action 'release' (it has none)");
}

TEST(SceneActions, CheckedAgainstTheirDeclaration) {
  const SceneInfo& neon = *findScene("neon");
  EXPECT_EQ(checkAction(neon, {"release", {0.0f, 6.0f, 4.0f}}), "");
  EXPECT_EQ(checkAction(neon, {"release", {0.0f, 6.0f}}), "neon.release takes 3 numbers (x y z), not 2");
  EXPECT_EQ(checkAction(neon, {"release", {0.0f, NAN, 4.0f}}), "neon.release: arguments must be finite numbers");
  EXPECT_EQ(checkAction(neon, {"explode", {}}), "scene neon has no action 'explode' (it has release, burst)");
  EXPECT_EQ(checkAction(*findScene("kifs"), {"release", {}}), "scene kifs has no action 'release' (it has none)");
  EXPECT_EQ(checkAction(*findScene("glass"), {"shuffle", {}}), "");
  EXPECT_EQ(checkAction(neon, {"ex\x1bplode", {}}), "scene neon has no action 'ex\\x1bplode' (it has release, burst)");
}

}  // namespace
}  // namespace vitrine::host
