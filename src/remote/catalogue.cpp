#include "remote/catalogue.h"

#include "params/preset_store.h"
#include "params/schema.h"
#include "scenes/catalogue.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace vitrine::remote {
namespace {

std::string_view kindName(params::Kind kind) {
  switch (kind) {
    case params::Kind::Float: return "float";
    case params::Kind::Int: return "int";
    case params::Kind::Bool: return "bool";
    case params::Kind::Choice: return "choice";
    case params::Kind::Colour: return "colour";
    case params::Kind::Custom: return "text";  // its own syntax ("32x32x8"): the page offers a text field
  }
  return "text";
}

nlohmann::json paramJson(const params::Param& param) {
  nlohmann::json out = {
      {"key", param.key},
      {"label", param.label},
      {"help", param.help},
      {"group", param.group},
      {"kind", kindName(param.kind)},
      {"default", param.defaultText},
      {"logarithmic", param.has(params::kLogarithmic)},
      // Rebuilding GPU resources per slider step would stall the scene: the page sends on release.
      {"applyOnRelease", param.has(params::kApplyOnRelease) || param.has(params::kRebuilds)},
      {"transient", param.has(params::kTransient)},
  };
  if (param.kind == params::Kind::Float || param.kind == params::Kind::Int) {
    out["min"] = param.min;
    out["max"] = param.max;
  }
  if (param.kind == params::Kind::Choice) out["choices"] = param.choices;
  if (param.has(params::kNamesFile)) {  // a client picks among the built-in names; files are the gallery's
    out["kind"] = "choice";
    out["choices"] = param.builtIns;
    out["default"] = params::remoteView(param, param.defaultText);
  }
  return out;
}

// The scene's own presets, for the page's list (the user's are typed by name: they change while it runs).
std::vector<std::string> presetNames(const params::Schema& schema) {
  std::vector<std::string> names;
  for (const params::Preset& preset : schema.presets()) names.push_back(preset.name);
  return names;
}

std::string makeJson(const std::vector<const SceneInfo*>& scenes) {
  nlohmann::json list = nlohmann::json::array();
  for (const SceneInfo* scene : scenes) {
    nlohmann::json params = nlohmann::json::array();
    for (const auto& param : scene->schema().params()) params.push_back(paramJson(param));
    nlohmann::json actions = nlohmann::json::array();
    for (const SceneAction& action : scene->actions) {
      std::vector<std::string> args(action.args.begin(), action.args.end());
      actions.push_back({{"name", action.name}, {"args", std::move(args)}, {"help", action.help}});
    }
    list.push_back({{"name", scene->name},
                    {"title", scene->title},
                    {"input", scene->input},
                    {"params", std::move(params)},
                    {"presets", presetNames(scene->schema())},
                    {"actions", std::move(actions)}});
  }
  return nlohmann::json{{"scenes", std::move(list)}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::vector<const SceneInfo*> registryScenes() {
  std::vector<const SceneInfo*> scenes;
  for (const SceneInfo& info : sceneRegistry()) scenes.push_back(&info);
  return scenes;
}

}  // namespace

Catalogue::Catalogue() : Catalogue(registryScenes()) {}

Catalogue::Catalogue(std::vector<const SceneInfo*> scenes) : scenes_(std::move(scenes)), json_(makeJson(scenes_)) {}

const SceneInfo* Catalogue::findScene(std::string_view name) const {
  for (const SceneInfo* scene : scenes_)
    if (scene->name == name) return scene;
  return nullptr;
}

bool Catalogue::hasAction(std::string_view scene, std::string_view action) const {
  const SceneInfo* found = findScene(scene);
  return found && found->findAction(action);
}

std::string Catalogue::check(const RemoteCommand& command) const {
  using Kind = RemoteCommand::Kind;
  if (command.kind == Kind::Pointer) {
    const auto inside = [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; };
    if (!inside(command.position.x) || !inside(command.position.y))
      return "pointer: x and y are numbers from 0 to 1";
    return {};
  }
  if (command.kind == Kind::Modulation)  // the source's name was judged by the parser; a value is clamped
    return command.args.size() == 1 && std::isfinite(command.args[0]) ? "" : "mod: one finite number";
  const SceneInfo* scene = findScene(command.scene);
  if (!scene) return fmt::format("unknown scene '{}'", command.scene.substr(0, kMaxNameLength));
  const params::Schema& schema = scene->schema();
  switch (command.kind) {
    case Kind::Scene: return {};
    case Kind::Set: {
      const params::Param* param = schema.find(command.key);
      if (!param)
        return fmt::format("{}: unknown parameter '{}'", scene->name, command.key.substr(0, kMaxNameLength));
      if (command.value.size() > kMaxValueLength)
        return fmt::format("{}.{}: the value is longer than {} characters", scene->name, command.key, kMaxValueLength);
      if (std::string why = params::remoteProblem(*param, command.value); !why.empty())
        return fmt::format("{}.{}", scene->name, why);
      const auto scratch = schema.makeDefaults();
      try {
        if (std::string why = params::applyValues({&schema, scratch.get()}, {{command.key, command.value}});
            !why.empty())
          return fmt::format("{}.{}", scene->name, why);
      } catch (const std::exception& error) {  // a custom parser that throws refuses the value, nothing more
        return fmt::format("{}.{}: {}", scene->name, command.key, error.what());
      }
      return {};
    }
    case Kind::Action:
      if (command.key.size() > kMaxNameLength) return fmt::format("{}: unknown action", scene->name);
      return checkAction(*scene, ActionCall{command.key, command.args});
    case Kind::Preset:
      // A new name must be one a preset may take; whether a named one exists is the host's to say.
      if (command.key == "save")
        if (std::string why = params::presetNameProblem(command.value, schema); !why.empty())
          return fmt::format("{}: {}", scene->name, why);
      return {};
    case Kind::Pointer:
    case Kind::Modulation: break;
  }
  return {};
}

}  // namespace vitrine::remote
