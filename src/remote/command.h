#pragma once
// What a remote client (a phone's page over WebSocket, an OSC controller over UDP) asks the gallery
// to do, once parsed and checked against the catalogue. Plain data: made on a server thread, carried
// through the inbox and applied by the host on the main thread before its next update.
#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace vitrine::remote {

struct RemoteCommand {
  enum class Kind {
    Scene,    // switch to `scene`
    Set,      // scene's parameter `key` = `value` (canonical text, as --set takes it)
    Action,   // scene's action `key` with `args` ("neon" "release" {x, y, z})
    Pointer,  // the current scene's cursor: `position` 0..1 from the top left, `down` while touching
    Modulation,  // live input's source osc.`key` = `args[0]` (/vitrine/mod/NAME)
    Preset,   // the user's presets of `scene`: `key` "save", "apply" or "delete", `value` the preset's name
  };
  Kind kind = Kind::Scene;
  std::string scene;
  std::string key;    // Set: the parameter; Action: the action's name
  std::string value;  // Set: the value as text
  std::vector<float> args;
  glm::vec2 position{0.5f};
  bool down = false;
  std::string client;  // who sent it ("ws 192.168.1.20:53122", "osc 127.0.0.1"): for logs
};

}  // namespace vitrine::remote
