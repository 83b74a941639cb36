// Looking scenes, their schemas and their actions up. The built-in scenes' table, builtInScenes(), is
// generated from the list of scenes in cmake/Scenes.cmake (cmake/SceneTables.cmake writes
// build/generated/scene_registry.cpp); pieces found at run time are added after them.
#include "scenes/catalogue.h"

#include "core/error.h"
#include "core/printable.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <vector>

namespace vitrine {
namespace {

// Room for every piece from the start, so an addition never moves the table: a SceneInfo pointer or
// reference taken before stays good.
std::vector<SceneInfo>& table() {
  static std::vector<SceneInfo> scenes = [] {
    const auto builtIn = builtInScenes();
    std::vector<SceneInfo> all;
    all.reserve(builtIn.size() + kMaxRuntimeScenes);
    all.assign(builtIn.begin(), builtIn.end());
    return all;
  }();
  return scenes;
}

}  // namespace

std::span<const SceneInfo> sceneRegistry() { return table(); }

SceneInfo& addRuntimeScene(const SceneInfo& info) {
  if (!info.runtimeSchema) throw Error(fmt::format("scene {}: a piece found at run time brings its schema", info.name));
  if (findScene(info.name)) throw Error(fmt::format("there is a scene named {} already", info.name));
  if (table().size() >= builtInScenes().size() + kMaxRuntimeScenes)
    throw Error(fmt::format("scene {}: at most {} pieces are shown", info.name, kMaxRuntimeScenes));
  return table().emplace_back(info);
}

std::string checkAction(const SceneInfo& info, const ActionCall& call) {
  const SceneAction* action = info.findAction(call.name);
  if (!action) {
    std::string known;
    for (const auto& a : info.actions) known += fmt::format("{}{}", known.empty() ? "" : ", ", a.name);
    return fmt::format("scene {} has no action '{}' ({})", info.name, printable(call.name),
                       known.empty() ? "it has none" : "it has " + known);
  }
  if (call.args.size() != action->args.size())
    return fmt::format("{}.{} takes {} numbers ({}), not {}", info.name, call.name, action->args.size(),
                       fmt::join(action->args, " "), call.args.size());
  for (float arg : call.args)
    if (!std::isfinite(arg)) return fmt::format("{}.{}: arguments must be finite numbers", info.name, call.name);
  return {};
}

const SceneInfo* findScene(std::string_view name) {
  for (const auto& info : sceneRegistry())
    if (info.name == name) return &info;
  return nullptr;
}

const params::Schema* findSchema(std::string_view scene) {
  const SceneInfo* info = findScene(scene);
  return info ? &info->schema() : nullptr;
}

std::string unknownScene(std::string_view name, std::string_view where) {
  std::vector<std::string_view> names, begun;
  for (const auto& info : sceneRegistry()) {
    names.push_back(info.name);
    if (!name.empty() && info.name.starts_with(name)) begun.push_back(info.name);
  }
  const std::string meant = begun.size() == 1 ? fmt::format(" (did you mean {}?)", begun.front()) : "";
  return fmt::format("Unknown scene '{}'{}{}; the scenes are {}.", printable(name), where, meant,
                     fmt::join(names, ", "));
}

}  // namespace vitrine
