#pragma once
// What a remote client may ask for, derived from the scene registry: the scenes, each scene's
// parameters (from its schema) and actions. It gives the page its controls as JSON and judges every
// command before it reaches the inbox, so the main thread only sees commands that name things that
// exist with values their schema accepts. Immutable once made: both server threads read it.
#include "params/schema.h"
#include "remote/command.h"

#include <string>
#include <string_view>
#include <vector>

namespace vitrine::remote {

class Catalogue {
 public:
  struct Action {
    std::string name;               // "release"
    std::vector<std::string> args;  // names of its numeric arguments: {"x", "y", "z"}; empty: none
    std::string help;
  };
  struct Scene {
    std::string name;   // "kifs"
    std::string title;  // "Volumetric KIFS"
    std::string input;  // what the cursor does there
    const params::Schema* schema = nullptr;
    std::vector<Action> actions;
  };

  explicit Catalogue(std::vector<Scene> scenes);
  static Catalogue fromRegistry();  // every scene of sceneRegistry()

  const std::vector<Scene>& scenes() const { return scenes_; }
  const Scene* findScene(std::string_view name) const;
  const Action* findAction(std::string_view scene, std::string_view name) const;

  // Empty when the command may be applied, else why not ("kifs: unknown parameter 'stepp'",
  // "kifs.step=12: expected a whole number from 1 to 9"). Set values are judged by the schema's own
  // parser on a scratch struct of defaults, so they get the same range checks as --set. Cross-parameter
  // checks need the live scene; the host runs them when it applies.
  std::string check(const RemoteCommand& command) const;

  // The page's description of every scene, parameter and action (see docs/REMOTE.md).
  const std::string& json() const { return json_; }

 private:
  std::vector<Scene> scenes_;
  std::string json_;
};

// Limits on what any message may carry, shared by the parsers and the check.
inline constexpr size_t kMaxNameLength = 64;    // a scene, parameter or action name
inline constexpr size_t kMaxValueLength = 256;  // a parameter's value text
inline constexpr size_t kMaxActionArgs = 8;

}  // namespace vitrine::remote
