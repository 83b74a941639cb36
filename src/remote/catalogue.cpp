#include "remote/catalogue.h"

#include "scenes/scene.h"

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
  return out;
}

std::string makeJson(const std::vector<Catalogue::Scene>& scenes) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& scene : scenes) {
    nlohmann::json params = nlohmann::json::array();
    for (const auto& param : scene.schema->params()) params.push_back(paramJson(param));
    nlohmann::json actions = nlohmann::json::array();
    for (const auto& action : scene.actions)
      actions.push_back({{"name", action.name}, {"args", action.args}, {"help", action.help}});
    list.push_back({{"name", scene.name},
                    {"title", scene.title},
                    {"input", scene.input},
                    {"params", std::move(params)},
                    {"actions", std::move(actions)}});
  }
  return nlohmann::json{{"scenes", std::move(list)}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// The registry's actions, when SceneInfo declares them (a scene without actions has none to offer).
template <typename Info> std::vector<Catalogue::Action> actionsOf(const Info& info) {
  std::vector<Catalogue::Action> actions;
  if constexpr (requires { info.actions; }) {
    for (const auto& action : info.actions) {
      Catalogue::Action copy{std::string(action.name), {}, std::string(action.help)};
      for (const auto& arg : action.args) copy.args.emplace_back(arg);
      actions.push_back(std::move(copy));
    }
  }
  return actions;
}

}  // namespace

Catalogue::Catalogue(std::vector<Scene> scenes) : scenes_(std::move(scenes)), json_(makeJson(scenes_)) {}

Catalogue Catalogue::fromRegistry() {
  std::vector<Scene> scenes;
  for (const SceneInfo& info : sceneRegistry())
    scenes.push_back({std::string(info.name), std::string(info.title), std::string(info.input), &info.schema(),
                      actionsOf(info)});
  return Catalogue(std::move(scenes));
}

const Catalogue::Scene* Catalogue::findScene(std::string_view name) const {
  for (const auto& scene : scenes_)
    if (scene.name == name) return &scene;
  return nullptr;
}

const Catalogue::Action* Catalogue::findAction(std::string_view scene, std::string_view name) const {
  const Scene* found = findScene(scene);
  if (!found) return nullptr;
  for (const auto& action : found->actions)
    if (action.name == name) return &action;
  return nullptr;
}

std::string Catalogue::check(const RemoteCommand& command) const {
  using Kind = RemoteCommand::Kind;
  if (command.kind == Kind::Pointer) {
    const auto inside = [](float v) { return std::isfinite(v) && v >= 0.0f && v <= 1.0f; };
    if (!inside(command.position.x) || !inside(command.position.y))
      return "pointer: x and y are numbers from 0 to 1";
    return {};
  }
  const Scene* scene = findScene(command.scene);
  if (!scene) return fmt::format("unknown scene '{}'", command.scene.substr(0, kMaxNameLength));
  switch (command.kind) {
    case Kind::Scene: return {};
    case Kind::Set: {
      if (!scene->schema->find(command.key))
        return fmt::format("{}: unknown parameter '{}'", scene->name, command.key.substr(0, kMaxNameLength));
      if (command.value.size() > kMaxValueLength)
        return fmt::format("{}.{}: the value is longer than {} characters", scene->name, command.key, kMaxValueLength);
      const auto scratch = scene->schema->makeDefaults();
      try {
        if (std::string why = params::applyValues({scene->schema, scratch.get()}, {{command.key, command.value}});
            !why.empty())
          return fmt::format("{}.{}", scene->name, why);
      } catch (const std::exception& error) {  // a custom parser that throws refuses the value, nothing more
        return fmt::format("{}.{}: {}", scene->name, command.key, error.what());
      }
      return {};
    }
    case Kind::Action: {
      const Action* action = findAction(command.scene, command.key);
      if (!action)
        return fmt::format("{}: unknown action '{}'", scene->name, command.key.substr(0, kMaxNameLength));
      if (command.args.size() != action->args.size())
        return fmt::format("{}/{}: expected {} argument{}, got {}", scene->name, action->name, action->args.size(),
                           action->args.size() == 1 ? "" : "s", command.args.size());
      for (const float arg : command.args)
        if (!std::isfinite(arg)) return fmt::format("{}/{}: arguments must be finite numbers", scene->name, action->name);
      return {};
    }
    case Kind::Pointer: break;
  }
  return {};
}

}  // namespace vitrine::remote
