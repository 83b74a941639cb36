// The gallery's scenes: starting and switching them, the kiosk's schedule and its cross-fades.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "host/gallery/gallery_app.h"
#include "host/live_clocks.h"
#include "live/midi_input.h"

namespace vitrine::host {
namespace {

using Clock = Gallery::Clock;

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
  startFilters(renderer, info);
  return {};
}

void Gallery::switchScene(const SceneInfo& info) {
  if (hasScene_ && remembers()) rememberValues();  // switching back restores them
  crossfade_.cancel();  // a number key during a fade: that scene, no fade
  switchFade_.reset();
  const SceneInfo* chosen = &info;
  // The old scene is retired behind the frames still using it. In kiosk mode a scene that cannot
  // start is skipped for the next one; when none starts, the kiosk starts over (runGallery).
  for (std::string failed; !(failed = startScene(*renderer_, *chosen)).empty();) {
    std::fprintf(stderr, "vitrine: kiosk: skipping %.*s: %s\n", int(chosen->name.size()), chosen->name.data(),
                 failed.c_str());
    const SceneInfo& next = kiosk_->failed(*chosen);
    if (&next == chosen) throw Error("kiosk: no scene starts on this device");
    chosen = &next;
  }
  if (kiosk_) startEntryPreset(*renderer_, kiosk_->showing(*chosen));
  missingAssets_ = assets_.missing();  // with what the scene could not find
  hasScene_ = true;
  ++sceneSerial_;
  passes_.clear();  // the old scene's timings are not this one's
  timedFrames_ = 0;
  costlyEdit_.reset();
  panel_.forget();
  filterPanel_.forget();
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
  remote_.setMappings(live_->mappingLines());
  remote_.publish(*renderer_, true);
}

// A playlist line's preset over the scene's saved values, just after it started; a preset the scene
// refuses on this device (each value was checked when the playlist was read) is said and skipped.
void Gallery::startEntryPreset(SceneRenderer& renderer, size_t entry) {
  const PlaylistEntry* line = kiosk_->presetOf(entry, renderer.info().name);
  if (!line) return;
  FoundPreset found = findPreset(line->scene, line->preset, &presets_);
  std::string why = found.preset ? renderer.applyParameters(found.preset->values) : found.why;
  if (!why.empty())
    std::fprintf(stderr, "vitrine: kiosk: %s without preset '%s': %s\n", line->scene.c_str(), line->preset.c_str(),
                 why.c_str());
}

// Kiosk mode, once a frame: a fade begins (the incoming scene starts in the second renderer), goes
// on, or ends (the renderers swap places).
void Gallery::kioskStep(double elapsed, bool touched) {
  if (chase_) chaseStep(elapsed);
  const KioskSchedule::Plan plan = kiosk_->advance(elapsed, touched, onBar_);
  if (plan.begin) {
    const SceneInfo& info = kiosk_->sceneOf(*plan.begin);
    if (!barNote_.empty())
      std::fprintf(stderr, "vitrine: link: %s: kiosk: %.*s comes in\n", barNote_.c_str(), int(info.name.size()), info.name.data());
    if (auto failed = startScene(crossfade_.incoming(), info); !failed.empty()) {
      std::fprintf(stderr, "vitrine: kiosk: skipping %.*s: %s\n", int(info.name.size()), info.name.data(),
                   failed.c_str());
      kiosk_->failed(*plan.begin);
      crossfade_.setWeight(0.0f);
      return;
    }
    startEntryPreset(crossfade_.incoming(), *plan.begin);
    crossfade_.began(input_);
    if (transition_)  // which scene came in when, for an installation's log
      std::fprintf(stderr, "vitrine: kiosk: %.*s comes in through %s\n", int(info.name.size()), info.name.data(),
                   transition_->file().filename().c_str());
  }
  if (plan.finish) finishFade();
  crossfade_.setWeight(plan.fade.value_or(0.0f));
}

bool Gallery::barLine() {
  barNote_.clear();
  if (!barWaits()) return true;
  rig::LinkClock* link = live_->link().linkClock();
  const rig::LinkReading now = link->look();
  const double before = barGate_.lastBeat().value_or(now.beat);
  const auto bar = barGate_.observe(now.beat, link->quantum());
  if (!bar) return false;
  barNote_ = fmt::format("bar {} (beat {:.4f}, link clock {:.6f} s; the frame before at beat {:.4f})", *bar, now.beat,
                         double(now.hostTime.count()) * 1e-6, before);
  return true;
}

// A playlist chased by timecode, once a frame: the line whose frame has come is cued (faded in from
// this frame's advance, or cut to from the next frame's switch); the chase's state is said when it
// changes kind (following, free-running, waiting), not every frame.
void Gallery::chaseStep(double elapsed) {
  const LiveClocks::Timecode timecode = live_->link().clocks().timecode(live::MidiInput::clockSeconds());
  const TimecodeChase::Step step = chase_->advance(timecode.position, timecode.locked, elapsed);
  if (step.cue) {
    kiosk_->cue(*step.cue, step.cut);
    if (step.cut) nextScene_ = &kiosk_->sceneOf(*step.cue);
  }
  const std::string state = chase_->status();
  const std::string kind = state.substr(0, state.find_first_of(" "));
  if (kind != chaseSaid_) {
    std::fprintf(stderr, "vitrine: kiosk: %s%s\n", timecode.source.empty() ? "" : (timecode.source + " ").c_str(),
                 state.c_str());
    chaseSaid_ = kind;
  }
}

void Gallery::finishFade() {
  if (!crossfade_.fading()) return;
  if (remembers()) rememberValues();
  crossfade_.finish(renderer_, input_, shown_);
  ++sceneSerial_;
  passes_.clear();
  timedFrames_ = 0;
  panel_.forget();
  filterPanel_.forget();
  panelError_.clear();
  missingAssets_ = assets_.missing();
  window_.setTitle(fmt::format("Vitrine — {}", renderer_->info().title));
  nowShowing();
}

}  // namespace vitrine::host
