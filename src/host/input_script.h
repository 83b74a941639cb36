#pragma once
// Scripted input for headless runs (--input FILE): a person's mouse and keys written down with the
// simulation time at which they happen, replayed frame-exactly and independent of real time.
//
// One event per line, "SECONDS VERB ARGS"; '#' starts a comment; blank lines are allowed:
//   move X Y      cursor to (X, Y) in normalised output coordinates, origin top-left, each in 0..1
//   leave         the cursor leaves the view (until the next move)
//   down / up     left button pressed / released
//   wheel STEPS   scroll, a finite number of steps, negative scrolls the other way
//   key NAME      a key press: a-z, 0-9, f1-f12, space, enter, escape, tab, backspace, left, right,
//                 up, down, minus, equal, comma, period, slash, semicolon, apostrophe, grave,
//                 backslash, left_bracket, right_bracket (case-insensitive)
//   hold NAME     the key goes down and stays down (glass' Z) until
//   release NAME  it comes up
//   action NAME [NUMBERS]  one of the scene's own actions (vitrine --list-params lists them), e.g.
//                 "2.0 action release 0 6 -4" releases a neon tube at x=0, y=6, z=-4
// Times are finite, >= 0 and never decrease down the file. The cursor stays where the last move put it
// (at the centre of the output before the first move).
#include <vulkan/vulkan.h>

#include <cstddef>
#include <filesystem>
#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "host/cursor_tracker.h"
#include "frame/frame_input.h"

namespace vitrine::host {

struct InputEvent {
  enum class Kind { Move, Down, Up, Wheel, Key, Leave, Hold, Release, Action };
  double time = 0.0;
  Kind kind = Kind::Move;
  glm::vec2 position{0.0f};  // Move: normalised, 0..1
  float wheel = 0.0f;        // Wheel: steps
  int key = 0;               // Key: a GLFW key code
  ActionCall action;         // Action: checked against the scene when the run starts
  size_t line = 0;           // where it was written, 1-based, for errors found later (a scene's actions)
};

struct InputScript {
  std::vector<InputEvent> events;  // in file order, so times never decrease
  std::string name;                // what errors call the script: "NAME:LINE: reason"
};

// Throws vitrine::Error "NAME:LINE: reason" for the first malformed line; `name` labels the text. A
// UTF-8 byte-order mark at the start is skipped (editors on Windows write one); words quoted in an
// error have their non-printable bytes written as \xNN.
InputScript parseInputScript(std::string_view text, std::string_view name);

// Reads and parses a script file. Refuses what is not a regular file, or is over 1 MiB. `text`, when
// given, receives the file's bytes (a recording's manifest keeps their fingerprint).
InputScript loadInputScript(const std::filesystem::path& path, std::string* text = nullptr);

// "NAME:LINE: reason" for an event of `script`: how errors found after parsing name their line.
std::string whereInScript(const InputScript& script, const InputEvent& event, std::string_view reason);

// The GLFW key code for a key name of the script format, any case; nullopt when there is none.
std::optional<int> keyFromName(std::string_view name);

struct StepInput {
  CursorInput cursor;
  std::vector<int> keysPressed;  // GLFW key codes, in file order
  std::vector<int> keysHeld;     // keys down at the end of the step (hold ... release)
  std::vector<ActionCall> actions;  // in file order
};

// Replays a script one fixed simulation step at a time.
//
// The rule: an event at time t belongs to the first step whose time is >= t, so "0.5 down" is seen by
// the step at 0.5 s and by none before it. Step times built by adding up a fixed step carry rounding
// error, so "reaching" t allows 1 µs of slack, far below any step. Events before the first step all
// land in it; steps are expected in increasing time.
//
// The cursor goes through the same CursorTracker as a real mouse, never on the menu. Each event is
// observed as though a frame were drawn right after it, so several events in one step apply in file
// order and lose nothing: a press and release within one step still drags by the movement between them.
class InputPlayer {
 public:
  explicit InputPlayer(InputScript script);

  // The input of the step that shows `stepTime`, on an output of `outputPixels`.
  StepInput step(double stepTime, VkExtent2D outputPixels);

  // True once every event has been applied; false at the end of a run means the script ran past it.
  bool finished() const { return next_ == script_.events.size(); }

 private:
  void observe(VkExtent2D outputPixels, bool pressed, float wheel);

  InputScript script_;
  size_t next_ = 0;
  glm::vec2 position_{0.5f};
  bool inside_ = false;  // over the view: from the first move until a leave
  bool held_ = false;
  std::vector<int> keysHeld_;
  CursorTracker tracker_;
};

}  // namespace vitrine::host
