// The gallery's scenes: starting and switching them, the kiosk's schedule and its cross-fades.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "host/gallery_app.h"

namespace vitrine::host {
namespace {

using Clock = Gallery::Clock;

size_t registryIndex(const SceneInfo& info) { return size_t(&info - sceneRegistry().data()); }

}  // namespace

// Creates `info` in `renderer` with its remembered values, and any a client sent while it was away.
// Returns why it could not start; only kiosk mode survives that (elsewhere the error ends the run).
std::string Gallery::startScene(SceneRenderer& renderer, const SceneInfo& info) {
  try {
    renderer.setScene(info);
  } catch (const Error& e) {
    if (!kiosk_) throw;
    renderer.clear();
    return e.what();
  }
  tiers_.started(info.name);
  // Saved values that do not fit together on this device (each one was valid on its own): the ones
  // that conflict are dropped, the rest kept.
  const params::FittedValues fitted = params::applyWhatFits(
      settings_.valuesFor(info.name), [&](const params::KeyValues& values) { return renderer.applyParameters(values); });
  if (!fitted.dropped.empty())
    std::fprintf(stderr, "vitrine: settings for %.*s: dropped %s (%s); the other saved values are kept\n",
                 int(info.name.size()), info.name.data(), fmt::format("{}", fmt::join(fitted.dropped, ", ")).c_str(),
                 fitted.why.c_str());
  return {};
}

void Gallery::switchScene(const SceneInfo& info) {
  if (hasScene_ && playlist_.empty()) rememberValues();  // switching back restores them
  if (incoming_) incoming_->clear();  // a number key during a fade: that scene, no fade
  fade_ = 0.0f;
  const SceneInfo* chosen = &info;
  // The old scene is retired behind the frames still using it. In kiosk mode a scene that cannot
  // start is skipped for the next one; when none starts, the kiosk starts over (runGallery).
  for (std::string failed; !(failed = startScene(*renderer_, *chosen)).empty();) {
    std::fprintf(stderr, "vitrine: kiosk: skipping %.*s: %s\n", int(chosen->name.size()), chosen->name.data(),
                 failed.c_str());
    for (size_t entry = 0; entry < (playlist_.empty() ? sceneRegistry().size() : playlist_.size()); ++entry)
      if (&entryScene(entry) == chosen) kiosk_->failed(entry);
    const SceneInfo& next = entryScene(kiosk_->current());
    if (&next == chosen) throw Error("kiosk: no scene starts on this device");
    chosen = &next;
  }
  if (kiosk_) {
    // A playlist shows the entry showing, if it is this scene's, else the scene's first entry.
    const size_t entry = &entryScene(kiosk_->current()) == chosen ? kiosk_->current() : entryOf(*chosen);
    kiosk_->jumpTo(entry);
    startEntryPreset(*renderer_, entry);
  }
  missingAssets_ = assets_.missing();  // with what the scene could not find
  hasScene_ = true;
  ++sceneSerial_;
  passes_.clear();  // the old scene's timings are not this one's
  timedFrames_ = 0;
  costlyEdit_.reset();
  panel_.forget();
  panelError_.clear();
  if (!kiosk_) settings_.showing(chosen->name, Clock::now());  // the kiosk's cycle is not the gallery's choice
  input_.frame = 0;
  input_.time = 0.0;
  steps_.restart();
  stepCost_ = {};
  window_.setTitle(fmt::format("Vitrine — {}", chosen->title));
  nowShowing();
}

// The scene showing changed (a switch, a finished fade): its mappings, and every page told.
void Gallery::nowShowing() {
  live_->showing(renderer_->info());
  if (!remote_) return;
  remote_->setMappings(live_->mappingLines());
  remote_->publish(*renderer_, true);
}

// The scene of a kiosk entry: a playlist's line, else the registry's scene of that index.
const SceneInfo& Gallery::entryScene(size_t entry) const {
  return playlist_.empty() ? sceneRegistry()[entry] : namedScene(playlist_[entry].scene);
}

// The kiosk entry that shows `info`: its first line in a playlist (the line showing when none does).
size_t Gallery::entryOf(const SceneInfo& info) const {
  if (playlist_.empty()) return registryIndex(info);
  for (size_t entry = 0; entry < playlist_.size(); ++entry)
    if (playlist_[entry].scene == info.name) return entry;
  return kiosk_->current();
}

// A playlist line's preset over the scene's saved values, just after it started; a preset the scene
// refuses on this device (each value was checked when the playlist was read) is said and skipped.
void Gallery::startEntryPreset(SceneRenderer& renderer, size_t entry) {
  if (playlist_.empty() || playlist_[entry].preset.empty() || playlist_[entry].scene != renderer.info().name) return;
  const PlaylistEntry& line = playlist_[entry];
  FoundPreset found = findPreset(line.scene, line.preset, &presets_);
  std::string why = found.preset ? renderer.applyParameters(found.preset->values) : found.why;
  if (!why.empty())
    std::fprintf(stderr, "vitrine: kiosk: %s without preset '%s': %s\n", line.scene.c_str(), line.preset.c_str(),
                 why.c_str());
}

// Kiosk mode, once a frame: a fade begins (the incoming scene starts in the second renderer), goes
// on, or ends (the renderers swap places).
void Gallery::kioskStep(double elapsed, bool touched) {
  const KioskSchedule::Plan plan = kiosk_->advance(elapsed, touched);
  if (plan.begin) {
    const SceneInfo& info = entryScene(*plan.begin);
    if (!incoming_) {
      incoming_ = std::make_unique<SceneRenderer>(device_, programs_, assets_, kFramesInFlight);
      incoming_->setAudioSink(&audio_);
      incoming_->setEventSink(&tiers_);
      incoming_->setRealtime(true);
    }
    if (auto failed = startScene(*incoming_, info); !failed.empty()) {
      std::fprintf(stderr, "vitrine: kiosk: skipping %.*s: %s\n", int(info.name.size()), info.name.data(),
                   failed.c_str());
      kiosk_->failed(*plan.begin);
      fade_ = 0.0f;
      return;
    }
    startEntryPreset(*incoming_, *plan.begin);
    incomingInput_ = FrameInput{};
    incomingInput_.seed = input_.seed;
    incomingInput_.reducedMotion = input_.reducedMotion;
    incomingShown_ = incomingInput_;
  }
  if (plan.finish) finishFade();
  fade_ = plan.fade.value_or(0.0f);
}

void Gallery::finishFade() {
  if (!incoming_ || !incoming_->hasScene()) return;
  if (playlist_.empty()) rememberValues();
  std::swap(renderer_, incoming_);
  incoming_->clear();  // the scene that faded out
  input_ = incomingInput_;
  shown_ = incomingShown_;
  ++sceneSerial_;
  passes_.clear();
  timedFrames_ = 0;
  panel_.forget();
  panelError_.clear();
  missingAssets_ = assets_.missing();
  window_.setTitle(fmt::format("Vitrine — {}", renderer_->info().title));
  nowShowing();
}

}  // namespace vitrine::host
