#pragma once
// The host's end of remote play (--remote): starts the servers, and once a frame applies what
// clients asked for on the main thread, before the next update. Shared by the gallery and headless
// runs (the latter so a browser test can drive a run with no window). A parameter for the scene that
// is showing goes through the same validation as the panel; one for another scene waits until that
// scene opens; actions and the pointer become the next step's input.
#include "host/pointer.h"
#include "host/scene_renderer.h"
#include "params/preset_store.h"
#include "remote/rate_limiter.h"
#include "remote/remote_control.h"
#include "remote/waiting_values.h"
#include "rig/rig_report.h"

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vitrine::host {

struct RemoteApplied {
  const SceneInfo* scene = nullptr;      // a client chose this scene
  std::vector<ActionCall> actions;       // for the scene showing, in order
  params::KeyValues values;              // applied to the scene showing (for the settings' bookkeeping)
  std::vector<std::string> presetsOnBar; // presets held for this bar and applied now, by name
  bool touched = false;                  // a person played the scene showing (kiosk mode holds it)
  std::vector<std::pair<std::string, float>> sources;  // live input: osc.NAME values (/vitrine/mod/NAME)
};

inline constexpr remote::RateLimit kPresetWrites{.rate = 2.0, .burst = 10.0};

class RemoteLink {
 public:
  // Listens on `bind` ("ADDR:PORT"); prints the page's address with its token. Throws vitrine::Error.
  // `allow`: --remote-allow networks ("192.168.1.0/24") whose OSC senders need no token.
  explicit RemoteLink(const std::string& bind, const std::vector<std::string>& allow = {});

  // Applies the commands that arrived since the last call to `renderer`'s scene. `frameMs`: the frame
  // time now, to refuse a change that would freeze the window (host/cost_guard.h).
  RemoteApplied apply(SceneRenderer& renderer, EventSink* events, double time, double frameMs = 0.0);
  // With --link-wait-bar: whether presets applied to the scene showing wait for the next bar, and
  // whether this frame begins one. A held preset (the latest one a client asked for) is applied by the
  // apply() of the frame that begins the bar, like the scene switches the gallery holds.
  void setBar(bool waits, bool onBar) { barWaits_ = waits, onBar_ = onBar; }
  // Applies the values clients sent for `renderer`'s scene while it was not showing (then forgets
  // them), each through the same checks as a live one: the freeze guard with `frameMs` (that scene's
  // own frame time, so called once its frames are timed), then the scene's validation. Returns those
  // applied.
  params::KeyValues applyWaiting(SceneRenderer& renderer, double frameMs);
  size_t waiting() const { return waiting_.size(); }  // values waiting for their scene, for tests
  uint16_t port() const { return control_.port(); }
  std::string pageUrl() const { return control_.pageUrl(); }
  // The phone's touch as a pointer over an output of `framebuffer` pixels, while a phone drives it.
  std::optional<Pointer> pointer(VkExtent2D framebuffer);
  // Tells every page what the scene showing is and its values (a few times a second at most).
  void publish(SceneRenderer& renderer, bool now = false);
  // The live mapping lines playing the scene showing, shown on every page from the next publish.
  void setMappings(std::vector<std::string> lines) { mappings_ = std::move(lines); }
  // The clocks and published outputs, shown on every page from the next publish.
  void setRig(std::vector<rig::RigLine> lines) { rig_ = std::move(lines); }
  // Where clients' preset commands (save, apply, delete) go; without one they are refused. Applying
  // finds the scene's own presets too.
  void setPresets(params::PresetStore* presets) { presets_ = presets; }
  // For the menu: "remote 127.0.0.1:8730: 2 pages, 1520 messages, 3 ignored".
  std::string status() const;

 private:
  std::string preset(SceneRenderer& renderer, const remote::RemoteCommand& command, RemoteApplied& applied,
                     double frameMs);
  // One console line per refusal, the first kRefusalsLogged then every hundredth: no flood reaches it.
  void logRefusal(const std::string& client, const std::string& why);
  remote::RemoteControl control_;
  params::PresetStore* presets_ = nullptr;
  remote::WaitingValues waiting_;  // bounded: last value per key, capped per client and in all
  std::optional<glm::vec2> touch_;  // the latest pointer position from a phone
  bool down_ = false, pressed_ = false;
  std::chrono::steady_clock::time_point lastTouch_{}, lastPublish_{};
  size_t refused_ = 0;  // refused here (the servers count theirs in RemoteStats)
  size_t logged_ = 0;   // refusals of either kind that reached logRefusal
  std::vector<std::string> mappings_;
  std::vector<rig::RigLine> rig_;
  // Saves and deletes write files: a few a second in all, whatever address each comes from.
  remote::TokenBucket presetWrites_{kPresetWrites};
  bool barWaits_ = false, onBar_ = true;
  std::optional<remote::RemoteCommand> heldPreset_;  // waiting for the bar; a later one replaces it
};

}  // namespace vitrine::host
