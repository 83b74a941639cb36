#pragma once
// What a remote client may ask for, derived from the scene registry: the scenes, each scene's
// parameters (from its schema) and actions. It gives the page its controls as JSON and judges every
// command before it reaches the inbox, so the main thread only sees commands that name things that
// exist with values their schema accepts. Immutable once made: both server threads read it.
#include "remote/command.h"

#include <string>
#include <string_view>
#include <vector>

namespace vitrine {
struct SceneInfo;  // scenes/catalogue.h: kept out of this header, which the host's loops include
}

namespace vitrine::remote {

class Catalogue {
 public:
  // Every scene of the registry (sceneRegistry()), or the given ones.
  Catalogue();
  explicit Catalogue(std::vector<const SceneInfo*> scenes);

  const std::vector<const SceneInfo*>& scenes() const { return scenes_; }
  const SceneInfo* findScene(std::string_view name) const;
  bool hasAction(std::string_view scene, std::string_view action) const;

  // Empty when the command may be applied, else why not ("kifs: unknown parameter 'stepp'",
  // "kifs.step=12: expected a whole number from 1 to 9"). Set values are judged by the schema's own
  // parser on a scratch struct of defaults, so they get the same range checks as --set; actions by the
  // scene's declaration (checkAction). Cross-parameter checks need the live scene: the host runs them
  // when it applies.
  std::string check(const RemoteCommand& command) const;

  // The page's description of every scene, parameter and action (see docs/REMOTE.md).
  const std::string& json() const { return json_; }

 private:
  std::vector<const SceneInfo*> scenes_;
  std::string json_;
};

// Limits on what any message may carry, shared by the parsers and the check.
inline constexpr size_t kMaxNameLength = 64;    // a scene, parameter or action name
inline constexpr size_t kMaxValueLength = 256;  // a parameter's value text
inline constexpr size_t kMaxActionArgs = 8;

}  // namespace vitrine::remote
