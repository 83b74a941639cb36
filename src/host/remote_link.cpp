#include "host/remote_link.h"
#include "host/plural.h"

#include <fmt/format.h>

#include <cstdio>
#include <stdexcept>

#include "core/error.h"
#include "core/printable.h"
#include "host/cost_guard.h"
#include "host/user_presets.h"

namespace vitrine::host {
namespace {

using Clock = std::chrono::steady_clock;
constexpr auto kPublishInterval = std::chrono::milliseconds(100);
// A phone that lifted its finger keeps the cursor this long, then the mouse has it back.
constexpr auto kTouchHold = std::chrono::seconds(2);
constexpr size_t kRefusalsLogged = 20;  // then every hundredth: a broken client cannot flood the console

// The page's address this process gave last, for a bind asked for again: a kiosk that starts a fresh
// gallery after a lost device keeps the same token and, where the bind let the system choose (:0), the
// same port, so phones reconnect by themselves. Should that port have been taken meanwhile, the
// system chooses again.
struct GivenAddress {
  std::string bind, token;
  uint16_t port = 0;
};
GivenAddress& lastGiven() {
  static GivenAddress given;
  return given;
}

remote::RemoteControl open(remote::RemoteConfig config, const std::string& bind) {
  const GivenAddress& last = lastGiven();
  const bool again = last.bind == bind;
  if (again) config.token = last.token;
  if (again && config.bind.port == 0 && last.port != 0) {
    remote::RemoteConfig same = config;
    same.bind.port = last.port;
    try {
      return remote::RemoteControl(std::move(same));
    } catch (const std::exception&) {
      // taken: the system chooses another below
    }
  }
  return remote::RemoteControl(std::move(config));
}

remote::RemoteControl listen(const std::string& bind, const std::vector<std::string>& allow) {
  remote::RemoteConfig config;
  // Found by OSCQuery clients over mDNS where an Avahi daemon runs; its lines come from Avahi's thread.
  config.announce = true;
  config.say = [](const std::string& line) {
    std::printf("vitrine: %s\n", line.c_str());
    std::fflush(stdout);
  };
  for (const std::string& network : allow) {
    try {
      config.oscAllow.push_back(remote::parseNetwork(network));
    } catch (const std::exception& e) {
      throw Error(fmt::format("--remote-allow {}: {}", network, e.what()));
    }
  }
  try {
    config.bind = remote::parseBind(bind);
    return open(std::move(config), bind);
  } catch (const std::exception& e) {
    throw Error(fmt::format("--remote-bind {}: {}", bind, e.what()));
  }
}

// One value from a client for the scene showing: refused when it would freeze the window (a client
// cannot be asked, so it is not applied), else applied if the scene accepts it. Why, or empty.
std::string judge(SceneRenderer& renderer, const std::pair<std::string, std::string>& value, double frameMs) {
  std::string refused = freezeWarning(renderer.costRatio({value}), frameMs);
  if (refused.empty()) refused = renderer.applyParameters({value});
  return refused;
}

// Whether a command is a person playing the scene on screen (the kiosk then holds it): a scene
// switch, a touch, or a value, action or preset for the scene showing. Not a modulation source (a
// lighting desk or a sequencer streams those all night), a value waiting for a hidden scene, or a
// preset saved or deleted.
bool playsTheShowingScene(const remote::RemoteCommand& command, std::string_view showing) {
  using Kind = remote::RemoteCommand::Kind;
  switch (command.kind) {
    case Kind::Scene:
    case Kind::Pointer: return true;
    case Kind::Set:
    case Kind::Action: return command.scene == showing;
    case Kind::Preset: return command.scene == showing && command.key != "save" && command.key != "delete";
    case Kind::Modulation: return false;
  }
  return false;
}

}  // namespace

RemoteLink::RemoteLink(const std::string& bind, const std::vector<std::string>& allow)
    : control_(listen(bind, allow)) {
  lastGiven() = {bind, control_.token(), control_.port()};
  std::printf("vitrine: remote control on %s (OSC over UDP, this page over HTTP):\n  %s\n",
              remote::formatBind(control_.bind()).c_str(), control_.pageUrl().c_str());
  std::fflush(stdout);
}

RemoteApplied RemoteLink::apply(SceneRenderer& renderer, EventSink* events, double time, double frameMs) {
  RemoteApplied applied;
  const std::string_view showing = renderer.info().name;
  if (heldPreset_ && (onBar_ || !barWaits_)) {
    const remote::RemoteCommand held = *std::exchange(heldPreset_, std::nullopt);
    if (std::string refused = preset(renderer, held, applied, frameMs); refused.empty()) {
      if (held.scene == showing) applied.presetsOnBar.push_back(held.value);  // else it waits for its scene
    } else {
      control_.tell(held.client, refused);
      logRefusal(held.client, refused);
    }
  }
  for (remote::RemoteCommand& command : control_.drain()) {
    std::string refused;
    switch (command.kind) {
      case remote::RemoteCommand::Kind::Scene:
        applied.scene = findScene(command.scene);
        break;
      case remote::RemoteCommand::Kind::Set:
        if (command.scene != showing) {  // kept (bounded) until its scene opens, judged then
          if (!waiting_.put(command.client, command.scene, command.key, command.value))
            refused = fmt::format("{}.{}: too many values waiting for scenes that are not showing", command.scene,
                                  command.key);
          break;
        }
        // Checked against the schema on a server thread; the scene's cross-parameter check runs here,
        // and a change that would freeze the window waits for someone at the panel.
        refused = judge(renderer, {command.key, command.value}, frameMs);
        if (refused.empty()) {
          applied.values.emplace_back(command.key, command.value);
          if (events) events->emit(time, showing, {"remote_set", {{"key", command.key}, {"value", command.value}}});
        }
        break;
      case remote::RemoteCommand::Kind::Action:
        if (command.scene == showing) applied.actions.push_back({command.key, command.args});
        break;
      case remote::RemoteCommand::Kind::Modulation:
        applied.sources.emplace_back("osc." + command.key, command.args[0]);
        break;
      case remote::RemoteCommand::Kind::Preset:
        if (barWaits_ && !onBar_ && command.key == "apply" && command.scene == showing) {
          heldPreset_ = command;  // judged when the bar comes, against the values then
          break;
        }
        refused = preset(renderer, command, applied, frameMs);
        if (refused.empty() && events)
          events->emit(time, showing, {"remote_preset", {{"op", command.key}, {"of", command.scene}, {"name", command.value}}});
        break;
      case remote::RemoteCommand::Kind::Pointer:
        pressed_ = pressed_ || (command.down && !down_);
        down_ = command.down;
        touch_ = command.position;
        lastTouch_ = Clock::now();
        break;
    }
    if (refused.empty()) {
      applied.touched = applied.touched || playsTheShowingScene(command, showing);
      continue;
    }
    control_.tell(command.client, refused);
    ++refused_;
    logRefusal(command.client, refused);
  }
  // What the OSC server refused before it reached here: its sender has no reply channel but the console.
  for (const remote::RemoteInbox::Refusal& refusal : control_.drainRefusals()) logRefusal(refusal.client, refusal.reason);
  if (!applied.values.empty() || applied.scene) publish(renderer, true);
  return applied;
}

// A client's preset command: save the values of the scene showing, delete one of the user's, or apply
// one (the scene's own or the user's) as one batch through the panel's checks; for a scene not showing
// its values wait like any others. Why it was refused, or empty.
std::string RemoteLink::preset(SceneRenderer& renderer, const remote::RemoteCommand& command, RemoteApplied& applied,
                               double frameMs) {
  const std::string_view showing = renderer.info().name;
  if (!presets_) return "this run keeps no presets";
  if ((command.key == "delete" || command.key == "save") && !presetWrites_.take())
    return fmt::format("too many presets saved or deleted; at most {} a second", kPresetWrites.rate);
  if (command.key == "delete") return presets_->remove(command.scene, command.value);
  if (command.key == "save") {
    if (command.scene != showing)
      return fmt::format("{} is not showing; only the values of the scene showing ({}) can be saved", command.scene, showing);
    return presets_->save({command.scene, command.value, params::snapshot(renderer.parameters(), /*includeTransient=*/false)});
  }
  FoundPreset found = findPreset(command.scene, command.value, presets_);
  if (!found.preset) return found.why;
  const params::KeyValues& values = found.preset->values;
  if (command.scene != showing) {
    for (const auto& [key, value] : values)
      if (!waiting_.put(command.client, command.scene, key, value))
        return fmt::format("{}: too many values waiting for scenes that are not showing", command.scene);
    return {};
  }
  std::string refused = freezeWarning(renderer.costRatio(values), frameMs);
  if (refused.empty()) refused = renderer.applyParameters(values);
  if (refused.empty()) applied.values.insert(applied.values.end(), values.begin(), values.end());
  return refused;
}

void RemoteLink::logRefusal(const std::string& client, const std::string& why) {
  if (++logged_ > kRefusalsLogged && logged_ % 100 != 0) return;
  // printable: a refusal may quote what a client sent (an OSC address holding an escape sequence).
  std::fprintf(stderr, "vitrine: remote %s refused: %s (%zu refused so far)\n", client.c_str(), printable(why).c_str(),
               size_t(control_.stats().refused) + refused_);
}

params::KeyValues RemoteLink::applyWaiting(SceneRenderer& renderer, double frameMs) {
  params::KeyValues applied;
  for (auto& value : waiting_.take(renderer.info().name)) {
    if (std::string refused = judge(renderer, value, frameMs); !refused.empty()) {
      ++refused_;
      std::fprintf(stderr, "vitrine: remote value for %s.%s refused: %s\n", std::string(renderer.info().name).c_str(),
                   value.first.c_str(), refused.c_str());
      continue;
    }
    applied.push_back(std::move(value));
  }
  return applied;
}

std::optional<Pointer> RemoteLink::pointer(VkExtent2D framebuffer) {
  if (!touch_ || (!down_ && Clock::now() - lastTouch_ > kTouchHold)) return std::nullopt;
  Pointer pointer;
  pointer.framebuffer = framebuffer;
  pointer.pixels = *touch_ * glm::vec2(framebuffer.width, framebuffer.height);
  pointer.leftHeld = down_;
  pointer.leftPressed = std::exchange(pressed_, false);
  pointer.inside = true;
  return pointer;
}

void RemoteLink::publish(SceneRenderer& renderer, bool now) {
  const auto at = Clock::now();
  if (!now && at - lastPublish_ < kPublishInterval) return;
  lastPublish_ = at;
  std::vector<std::string> userPresets;
  if (presets_)
    for (const params::UserPreset* preset : presets_->presetsOf(renderer.info().name)) userPresets.push_back(preset->name);
  params::KeyValues values = params::snapshot(renderer.parameters());
  const params::Schema& schema = *renderer.parameters().schema;
  for (auto& [key, value] : values) value = params::remoteView(*schema.find(key), std::move(value));
  control_.publish({std::string(renderer.info().name), std::move(values), mappings_, std::move(userPresets), rig_});
}

}  // namespace vitrine::host

namespace vitrine::host {

std::string RemoteLink::status() const {
  const remote::RemoteStatsSnapshot stats = control_.stats();
  const uint64_t ignored = stats.malformed + stats.refused + stats.rateLimited + stats.oversized + stats.unauthorised +
                           stats.dropped + stats.connectionsRefused + refused_;
  return fmt::format("remote {}: {} open, {}, {} ignored", remote::formatBind(control_.bind()),
                     counted(control_.sockets(), "page"), counted(stats.accepted, "message"), ignored);
}

}  // namespace vitrine::host
