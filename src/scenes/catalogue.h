#pragma once
// What the scenes are, with no GPU in it: each scene's name, title, number key, parameter schema, help
// line and actions (SceneInfo, declared with the scene's schema in its settings.h), the registry of
// them in menu order, and every lookup by name. What reads names and values from outside (the command
// line, live input's mappings, remote control, the settings file and presets, the fuzz targets)
// includes this and links the scenes' settings.cpp files, not their GPU code; the scenes themselves
// are scenes/scene.h.
#include "frame/frame_input.h"
#include "params/schema.h"

#include <span>
#include <string>
#include <string_view>

namespace vitrine {

// A scene's own verb that remote control (OSC, the web page) and input scripts can trigger, declared
// once with the scene: neon's "release x y z", glass's "shuffle". Arguments are numbers.
struct SceneAction {
  std::string_view name;
  std::span<const std::string_view> args;  // their names, in order; the count is the arity
  std::string_view help;
};

struct SceneInfo {
  std::string_view name;   // "kifs": used on the command line
  std::string_view title;  // "Volumetric KIFS": shown in the menu
  int key;                 // number key 1..9 in the gallery; 0: none (a piece found at run time)
  // A built-in scene's parameter declarations, no instance or GPU needed; null for a piece found at
  // run time, whose schema is `runtimeSchema`. Read both through schema().
  const params::Schema& (*builtInSchema)();
  std::string_view input;  // for the help card: what the drag and the scene's own keys do
  std::span<const SceneAction> actions = {};  // what remote control and scripts may trigger
  // A piece found at run time (an ISF file): its parameters, made from the file; replaced in place
  // when the file is edited (the schema it replaces stays alive: a running scene may hold it).
  const params::Schema* runtimeSchema = nullptr;

  const params::Schema& schema() const { return runtimeSchema ? *runtimeSchema : builtInSchema(); }
  bool builtIn() const { return runtimeSchema == nullptr; }

  const SceneAction* findAction(std::string_view actionName) const {
    for (const auto& action : actions)
      if (action.name == actionName) return &action;
    return nullptr;
  }
};

// "" when `call` names one of the scene's actions with its arity and finite arguments; else why not.
std::string checkAction(const SceneInfo& info, const ActionCall& call);

// Every scene, in menu order: the built-in ones, generated from the list in cmake/Scenes.cmake (each
// NAME::kSceneInfo), then the pieces found at run time (ISF files: --isf, the pieces folders).
std::span<const SceneInfo> sceneRegistry();
std::span<const SceneInfo> builtInScenes();  // the generated table alone
// Adds a piece found at run time after every scene there is; throws Error for a name taken or more
// than kMaxRuntimeScenes. Entries never move (a SceneInfo pointer stays good), but a span of the
// registry taken before does not see the addition. Returns the entry, which its owner may update in
// place later, on the thread that reads the registry (a piece's file edited: schema, actions, help).
inline constexpr size_t kMaxRuntimeScenes = 256;
SceneInfo& addRuntimeScene(const SceneInfo& info);
const SceneInfo* findScene(std::string_view name);
// The scene's parameter schema; null when no scene has that name (the settings file, presets).
const params::Schema* findSchema(std::string_view scene);
// What to say of a scene name no scene has (`where`: e.g. " in --set nope.grid=32"): the scenes there
// are, and the one meant when the name begins only that one ("nood": noodles).
std::string unknownScene(std::string_view name, std::string_view where = {});

}  // namespace vitrine
