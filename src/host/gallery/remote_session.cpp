#include "host/gallery/remote_session.h"

namespace vitrine::host {

void RemoteSession::listen(const std::string& bind, const std::vector<std::string>& allow, params::PresetStore* presets) {
  link_.emplace(bind, allow);
  link_->setPresets(presets);
}

RemoteApplied RemoteSession::apply(SceneRenderer& renderer, double time, double frameMs, std::optional<double> ownGpuMs) {
  if (!link_) return {};
  RemoteApplied applied = link_->apply(renderer, nullptr, time, frameMs);
  if (ownGpuMs)
    for (auto& value : link_->applyWaiting(renderer, *ownGpuMs)) applied.values.push_back(std::move(value));
  for (const auto& value : applied.values) clientSet(renderer.info().name, value.first);
  actions_.insert(actions_.end(), applied.actions.begin(), applied.actions.end());
  return applied;
}

void RemoteSession::userSet(std::string_view scene, const PanelEdit& edit) {
  const auto keys = clientKeys_.find(scene);
  if (keys == clientKeys_.end()) return;
  if (edit.what == PanelEdit::What::Values)
    for (const auto& kv : edit.values) keys->second.erase(kv.first);
  else
    keys->second.clear();
}

std::set<std::string> RemoteSession::notTheUsers(std::string_view scene) const {
  const auto keys = clientKeys_.find(scene);
  if (saves_ || keys == clientKeys_.end()) return {};
  return keys->second;
}

}  // namespace vitrine::host
