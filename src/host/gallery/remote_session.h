#pragma once
// The gallery's remote play (--remote): the link to the clients (host/remote_link.h), what they sent for
// the next steps, and which values of each scene a client set rather than the user. Those stay out of
// the settings file unless --remote-saves: the values saved before are kept for them. Without --remote
// the session is off and its calls do nothing, except the bookkeeping of the user's own edits.
#include "host/ui/param_panel.h"
#include "host/remote_link.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vitrine::host {

class RemoteSession {
 public:
  // Off; `saves` (--remote-saves): what clients set is saved like the user's edits.
  explicit RemoteSession(bool saves = false) : saves_(saves) {}
  // On: listens on `bind` with --remote-allow's `allow` (RemoteLink); clients' preset commands go to
  // `presets`. Throws vitrine::Error.
  void listen(const std::string& bind, const std::vector<std::string>& allow, params::PresetStore* presets);
  bool on() const { return link_.has_value(); }
  uint16_t port() const { return link_ ? link_->port() : 0; }

  // Once a frame, before its steps: what clients sent since the last frame, applied to `renderer`'s
  // scene at `frameMs` a frame (the freeze guard). Values sent while that scene was hidden are applied
  // once `ownGpuMs` is given, the GPU time of that scene's own frames: judged by what it costs, not by
  // the scene shown before. The keys applied become clients' keys of the scene; the actions wait for
  // the next step (takeActions).
  RemoteApplied apply(SceneRenderer& renderer, double time, double frameMs, std::optional<double> ownGpuMs);
  std::vector<ActionCall> takeActions() { return std::exchange(actions_, {}); }
  // Presets for the scene showing wait for the next bar while `waits`; `onBar`: this frame begins one.
  void setBar(bool waits, bool onBar) {
    if (link_) link_->setBar(waits, onBar);
  }
  // The phone's touch over an output of `framebuffer` pixels, while a phone drives it.
  std::optional<Pointer> pointer(VkExtent2D framebuffer) { return link_ ? link_->pointer(framebuffer) : std::nullopt; }
  // Tells every page what the scene showing is and its values (a few times a second at most, unless `now`).
  void publish(SceneRenderer& renderer, bool now = false) {
    if (link_) link_->publish(renderer, now);
  }
  void setRig(std::vector<rig::RigLine> lines) {
    if (link_) link_->setRig(std::move(lines));
  }
  void setMappings(std::vector<std::string> lines) {
    if (link_) link_->setMappings(std::move(lines));
  }
  std::string status() const { return link_ ? link_->status() : std::string(); }  // for the menu; empty when off

  // A client set `key` of `scene`.
  void clientSet(std::string_view scene, const std::string& key) { clientKeys_[std::string(scene)].insert(key); }
  // The user edited `scene` in the panel: the values it sets are the user's again (a preset or a reset:
  // all of them).
  void userSet(std::string_view scene, const PanelEdit& edit);
  // The keys of `scene` whose values now are not the user's to save: those a client set, unless --remote-saves.
  std::set<std::string> notTheUsers(std::string_view scene) const;

 private:
  std::optional<RemoteLink> link_;
  bool saves_;
  std::map<std::string, std::set<std::string>, std::less<>> clientKeys_;  // per scene
  std::vector<ActionCall> actions_;  // for the next step
};

}  // namespace vitrine::host
