#include "host/live_link.h"

#include "rig/rig_report.h"

#include "app/options.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include "host/scene_renderer.h"
#include "lights/lights.h"
#include "live/audio_capture.h"
#include "live/audio_clip.h"
#include "live/audio_file_input.h"
#include "live/midi_input.h"
#include "live/smf.h"
#include "rig/rig_report.h"
#include "scenes/catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <span>
#include <utility>
#include <vector>

namespace vitrine::host {
namespace {

// A MIDI channel message as the sources it moves.
void applyMidi(const live::MidiMessage& message, live::SourceBank& sources) {
  const std::string where = fmt::format("{}.{}", message.channel(), message.data1);
  if (message.type() == 0xB0) {
    sources.set("midi.cc." + where, float(message.data2) / 127.0f);
  } else if (message.type() == 0x90 || message.type() == 0x80) {
    const bool on = message.type() == 0x90 && message.data2 > 0;  // a note-on of velocity 0 is a note-off
    sources.set("midi.note." + where, on ? float(message.data2) / 127.0f : 0.0f);
    sources.set("midi.gate." + where, on ? 1.0f : 0.0f);
  }
}

}  // namespace

void setLinkSources(const rig::LinkReading& now, std::optional<int64_t> lastBar, double quantum, live::SourceBank& sources) {
  sources.set("link.tempo", float(now.bpm / 240.0));  // 0..1 spans 0..240 beats a minute, as audio.tempo
  sources.set("link.beat", float(now.beat - std::floor(now.beat)));  // rising through each beat
  sources.set("link.phase", float(now.phase / quantum));             // rising through each bar
  sources.set("link.bar", lastBar && now.bar > *lastBar ? 1.0f : 0.0f);  // 1 for the step a bar begins on
  sources.set("link.pulse", now.beatBegan ? 1.0f : 0.0f);            // 1 for the step a beat begins on
  sources.set("link.playing", now.playing ? 1.0f : 0.0f);
}

namespace {

// --map's argument: a line when it holds '=' (a file name seldom does), else a mapping file.
std::vector<live::Mapping> mappingsOf(const LiveConfig& config) {
  std::vector<live::Mapping> mappings;
  for (const std::string& map : config.maps) {
    if (map.find('=') == std::string::npos) {
      for (live::Mapping& mapping : live::loadMappingFile(map)) mappings.push_back(std::move(mapping));
      continue;
    }
    std::string why;
    auto mapping = live::parseMapping(map, &why);
    if (!mapping) throw Error(fmt::format("--map {}: {}", map, why));
    if (mapping->scene.empty()) mapping->scene = config.runScene;
    const SceneInfo* scene = findScene(mapping->scene);
    if (!scene) throw Error(fmt::format("--map {}: {}", map, unknownScene(mapping->scene)));
    if (auto reason = live::checkMapping(*mapping, *scene); !reason.empty())
      throw Error(fmt::format("--map {}: {}", map, reason));
    mappings.push_back(std::move(*mapping));
  }
  return mappings;
}

}  // namespace

LiveLink::LiveLink(LiveConfig config) : config_(std::move(config)), commandLine_(mappingsOf(config_)) {
  if (!config_.audioFile.empty())
    audioFile_ = std::make_unique<live::AudioFileInput>(config_.audioFile, config_.loopAudioFile);
  if (config_.captureAudio) setAudioCapture(true, config_.audioDevice);
  if (!config_.midiFile.empty()) midiFile_ = std::make_unique<live::SmfPlayer>(live::readSmf(config_.midiFile));
  if (config_.midiPorts) midiPorts_ = std::make_unique<live::MidiInput>();
  if (config_.link) linkClock_ = std::make_unique<rig::LinkClock>(*config_.link);
}

LiveLink::~LiveLink() = default;

void LiveLink::setAudioCapture(bool on, const std::string& device) {
  config_.captureAudio = on;
  config_.audioDevice = device;
  capture_.reset();  // a device switch closes the old stream first
  if (on) {
    capture_ = std::make_unique<live::AudioCapture>(live::AudioCapture::Options{.device = device});
    if (!capture_->active()) capture_.reset();  // it said why, once
  }
  if (scene_) remap();
}

void LiveLink::setScene(const SceneInfo& scene, const std::vector<std::string>& saved, std::vector<std::string>* warnings) {
  scene_ = &scene;
  saved_.clear();
  for (const std::string& line : saved) {
    std::string why;
    auto mapping = live::parseMapping(line, &why);
    if (mapping && mapping->scene.empty()) mapping->scene = scene.name;
    if (mapping) why = live::checkMapping(*mapping, scene);
    if (!why.empty()) {
      if (warnings) warnings->push_back(fmt::format("mapping '{}' for {}: {}; skipped", line, scene.name, why));
      continue;
    }
    saved_.push_back(std::move(*mapping));
  }
  remap();
}

void LiveLink::remap() {
  vetted_ = false;
  std::vector<live::Mapping> mappings = saved_;
  for (const live::Mapping& mapping : commandLine_)
    if (mapping.scene == scene_->name) mappings.push_back(mapping);
  if (audioOn())
    for (const std::string& line : scene_->schema().audioMappings()) {
      auto mapping = live::parseMapping(line, nullptr);  // every scene's are checked by a unit test
      if (!mapping) continue;
      mapping->scene = scene_->name;
      const bool taken = std::any_of(mappings.begin(), mappings.end(), [&](const live::Mapping& m) { return m.target == mapping->target; });
      if (!taken && live::checkMapping(*mapping, *scene_).empty()) mappings.push_back(std::move(*mapping));
    }
  if (dmx_) {
    std::vector<std::string> sources;
    for (const live::Mapping& mapping : mappings) sources.push_back(mapping.source);
    sources.push_back(dmx_->patch().masterSource);
    sources.push_back(dmx_->patch().blackoutSource);
    dmx_->listen(lights::universesRead(sources));
  }
  modulator_.setMappings(*scene_, std::move(mappings));
}

void LiveLink::setDmxInput(lights::Lights* lights) {
  dmx_ = lights;
  if (scene_) remap();
}

void LiveLink::readInputs(double time) {
  sources_.setTime(time);
  std::optional<live::AudioFeatures> audio;
  const live::AudioAnalyser* analyser = nullptr;
  if (audioFile_) {
    const double fileTime = config_.audioFileClock ? config_.audioFileClock() : time;
    audio = audioFile_->at(fileTime);
    readFileLtc(fileTime);
    analyser = &audioFile_->analyser();
  } else if (capture_) {
    audio = capture_->take([&](std::span<const float> samples) { clocks_.ltcSamples(capture_->sampleRate(), samples); });
    analyser = capture_->analyser();
  }
  // The sound itself, for the scene's step (ISF's audio inputs): 6 KiB a step while sound comes in.
  soundWave_.clear();
  soundSpectrum_.clear();
  if (analyser) {
    const auto samples = analyser->recentSamples();
    soundWave_.assign(samples.begin(), samples.end());
    soundSpectrum_ = analyser->spectrum();
  }
  if (audio) {
    sources_.set("audio.bass", audio->bass);
    sources_.set("audio.mid", audio->mid);
    sources_.set("audio.high", audio->high);
    sources_.set("audio.level", audio->level);
    sources_.set("audio.onset", audio->onset);
    sources_.set("audio.beat", audio->beat);
    sources_.set("audio.tempo", audio->tempo / 240.0f);  // 0..1 spans 0..240 beats a minute
  }
  // A MIDI file's events apply at the first step at or after their time.
  if (midiFile_)
    for (const live::MidiMessage& message : midiFile_->until(time + 1e-9)) applyMidi(message, sources_);
  if (midiPorts_) {
    midiPorts_->poll();
    for (const live::MidiMessage& message : midiPorts_->drain()) applyMidi(message, sources_);
    clocks_.midiBytes(midiPorts_->drainSystem());
  }
  if (linkClock_) {
    const rig::LinkReading now = linkClock_->read();
    setLinkSources(now, linkReading_ ? std::optional(linkReading_->bar) : std::nullopt, linkClock_->quantum(), sources_);
    linkReading_ = now;
    for (const std::string& line : linkClock_->takeNews()) std::fprintf(stderr, "vitrine: link: %s\n", line.c_str());
  }
  // DMX in: what the lights thread received since the last step, as it stands now.
  if (dmx_)
    for (const lights::Lights::Input& in : dmx_->takeInput()) {
      dmxSources_.apply(in.universe, in.channels, sources_);
      dmxTaken_.push_back({in.universe, in.arrived, lights::Lights::clockSeconds()});
    }
  if (dmx_) playLights();
  clocks_.write(sources_, live::MidiInput::clockSeconds());
  // MIDI learn watches the controls a person moves: MIDI, a desk's DMX faders and gamepads (a clock
  // moves by itself; a 16-bit pair moves with its channels, which learn maps instead).
  for (const auto& [name, value] : sources_.values()) {
    const bool control = name.starts_with("midi.") || name.starts_with("pad.") || name.starts_with("dmx.");
    if (!control || name.starts_with("midi.clock.")) continue;
    const auto seen = controlsSeen_.find(name);
    const float was = seen == controlsSeen_.end() ? (name.find(".axis.") != std::string::npos ? 0.5f : 0.0f) : seen->second;
    const float by = std::abs(value - was);
    if (by > 0.02f && by >= movedBy_) moved_ = name, movedBy_ = by;
    controlsSeen_[name] = value;
  }
}

// LTC in the --audio-in file: the samples before `fileTime`, as the analysis hears them (looped when
// the file loops). Going back (the gallery's loop started again) or far ahead (a run started late)
// reads afresh from a little before the new time.
void LiveLink::readFileLtc(double fileTime) {
  const std::vector<float>& mono = audioFile_->mono();
  const double rate = audioFile_->clip().sampleRate;
  if (mono.empty() || !std::isfinite(fileTime) || fileTime <= 0.0) return;
  const auto end = uint64_t(std::min(std::ceil(fileTime * rate - 1e-6), 9.0e18));
  const auto lead = uint64_t(rate);  // a second: the reader knows the frame again within two
  if (end < ltcFed_ || end - ltcFed_ > 2 * lead) {
    clocks_.ltcRestart();
    ltcFed_ = end > lead ? end - lead : 0;
  }
  std::vector<float> chunk;
  while (ltcFed_ < end) {
    const uint64_t n = std::min<uint64_t>(end - ltcFed_, 4096);
    chunk.resize(size_t(n));
    for (uint64_t i = 0; i < n; ++i) {
      const uint64_t at = ltcFed_ + i;
      chunk[size_t(i)] = config_.loopAudioFile ? mono[size_t(at % mono.size())] : (at < mono.size() ? mono[size_t(at)] : 0.0f);
    }
    clocks_.ltcSamples(rate, chunk);
    ltcFed_ += n;
  }
}

void LiveLink::step(SceneRenderer& renderer, FrameInput& input, EventSink* events) {
  dmxTaken_.clear();
  readInputs(input.time);
  input.soundWave = soundWave_;
  input.soundSpectrum = soundSpectrum_;
  if (!scene_ || &renderer.info() != scene_) return;  // the scene showing has not been given yet
  // When a desk's frame arrived and when this step took it, on the steady clock: how late DMX in plays.
  if (events)
    for (const DmxTaken& taken : dmxTaken_)
      events->emit(input.time, scene_->name,
                   {"dmx", {{"universe", double(taken.universe)}, {"arrived", taken.arrived}, {"taken", taken.taken}}});
  if (!vetted_) vet(renderer);
  live::Modulated out = modulator_.step(sources_, renderer.parameters(), input.dt);
  if (!out.values.empty()) {
    const std::string why = renderer.applyParameters(out.values);
    if (!why.empty()) {
      if (lastRefusal_.empty())  // one line when refusals begin, not one a step while they last
        std::fprintf(stderr, "vitrine: live input: %s refuses %s\n", std::string(scene_->name).c_str(), why.c_str());
      lastRefusal_ = why;
    } else {
      lastRefusal_.clear();
    }
    if (why.empty() && events) {
      for (const auto& [key, value] : out.values) {
        // An init-capture: clang 14 (the sanitizer build) cannot capture a structured binding itself.
        const auto by = std::find_if(modulator_.mappings().rbegin(), modulator_.mappings().rend(),
                                     [&target = key](const live::Mapping& m) { return m.target == target; });
        events->emit(input.time, scene_->name, {"mapped", {{"key", key}, {"value", value}, {"by", by->source}}});
      }
    }
  }
  input.actions.insert(input.actions.end(), out.actions.begin(), out.actions.end());
}

namespace {

// The values a mapping drives its parameter between: its range, else the parameter's whole one.
std::optional<std::pair<std::string, std::string>> mappedEnds(const live::Mapping& mapping, const params::Param& param) {
  if (mapping.lo && mapping.hi) return std::pair(*mapping.lo, *mapping.hi);
  switch (param.kind) {
    case params::Kind::Float: return std::pair(params::formatFloat(float(param.min)), params::formatFloat(float(param.max)));
    case params::Kind::Int: return std::pair(fmt::to_string(int(param.min)), fmt::to_string(int(param.max)));
    case params::Kind::Bool: return std::pair(std::string("off"), std::string("on"));
    case params::Kind::Choice: return std::pair(param.choices.front(), param.choices.back());
    default: return std::nullopt;
  }
}

}  // namespace

void LiveLink::vet(SceneRenderer& renderer) {
  vetted_ = true;
  const params::Bound bound = renderer.parameters();
  std::vector<live::Mapping> kept;
  bool setAside = false;
  for (const live::Mapping& mapping : modulator_.mappings()) {
    const params::Param* param = bound.schema->find(mapping.target);
    const auto ends = param ? mappedEnds(mapping, *param) : std::nullopt;
    std::string why;
    // Judged with the other values as they are; a scene that refuses its present values (a picture that
    // will not load) says nothing about the mapping.
    if (ends) {
      const std::string now = param->format(bound.settings);
      if (renderer.applyParameters({{mapping.target, now}}).empty()) {
        why = renderer.applyParameters({{mapping.target, ends->first}});
        if (why.empty()) why = renderer.applyParameters({{mapping.target, ends->second}});
        renderer.applyParameters({{mapping.target, now}});
      }
    }
    if (why.empty()) {
      kept.push_back(mapping);
      continue;
    }
    setAside = true;
    std::fprintf(stderr, "vitrine: live input: the mapping %s is set aside: %s refuses %s\n",
                 live::formatMapping(mapping).c_str(), std::string(scene_->name).c_str(), why.c_str());
  }
  if (setAside) modulator_.setMappings(*scene_, std::move(kept));
}

// The patch's master and blackout sources, when they move (so the L key's blackout holds until the
// blackout source itself changes).
void LiveLink::playLights() {
  const auto moved = [&](const std::string& name, std::optional<float>& last) -> std::optional<float> {
    const auto value = sources_.values().find(name);
    if (name.empty() || value == sources_.values().end() || last == value->second) return std::nullopt;
    return last = value->second;
  };
  if (const auto master = moved(dmx_->patch().masterSource, lightsMaster_)) dmx_->setMaster(*master);
  if (const auto blackout = moved(dmx_->patch().blackoutSource, lightsBlackout_)) dmx_->setBlackout(*blackout >= 0.5f);
}

std::vector<std::string> LiveLink::mappingLines() const {
  std::vector<std::string> lines;
  for (const live::Mapping& mapping : modulator_.mappings()) lines.push_back(live::formatMapping(mapping));
  return lines;
}

std::vector<std::string> LiveLink::drivenKeys() const {
  std::vector<std::string> keys;
  for (const live::Mapping& mapping : modulator_.mappings())
    if (scene_ && !scene_->findAction(mapping.target)) keys.push_back(mapping.target);
  return keys;
}

std::optional<std::string> LiveLink::takeMovedControl() {
  movedBy_ = 0.0f;
  return std::exchange(moved_, std::nullopt);
}

std::vector<std::string> LiveLink::status() const {
  std::vector<std::string> lines;
  if (audioFile_) lines.push_back(fmt::format("audio in: {} ({:.1f} s{})", config_.audioFile, audioFile_->clip().seconds(), config_.loopAudioFile ? ", looped" : ""));
  else if (capture_) lines.push_back(capture_->status());
  else lines.push_back("audio in: off");
  if (midiFile_) lines.push_back("MIDI in: " + config_.midiFile);
  if (midiPorts_) lines.push_back(midiPorts_->status());
  if (dmx_) lines.push_back(dmx_->status());
  for (const rig::ClockStatus& clock : clockStatuses()) {
    const rig::RigLine line = rig::describeClock(clock);
    lines.push_back(line.name + ": " + line.text);
  }
  return lines;
}

const live::AudioClip* LiveLink::audioClip() const { return audioFile_ ? &audioFile_->clip() : nullptr; }

std::string LiveLink::fingerprintText() const {
  std::string text;
  for (const live::Mapping& mapping : commandLine_) text += live::formatMapping(mapping) + "\n";
  const std::pair<const std::string*, uintmax_t> files[] = {{&config_.audioFile, live::kMaxClipFileBytes},
                                                             {&config_.midiFile, live::kSmfMaxBytes}};
  for (const auto& [path, maxBytes] : files) {
    if (path->empty()) continue;
    try {
      text += *path + "\n" + readBoundedFile(*path, maxBytes);
    } catch (const FileRefused& refused) {
      throw Error(fmt::format("Cannot read {}: {}", *path, refused.why));
    }
  }
  return text;
}

std::unique_ptr<LiveLink> offlineLiveInput(const Options& options, const std::string& scene) {
  if (options.maps.empty() && options.audioIn.empty() && options.midiIn.empty()) return nullptr;
  return std::make_unique<LiveLink>(LiveConfig{.maps = options.maps, .runScene = scene, .audioFile = options.audioIn,
                                               .midiFile = options.midiIn});
}

std::vector<rig::ClockStatus> LiveLink::clockStatuses() const {
  std::vector<rig::ClockStatus> statuses = clocks_.statuses(live::MidiInput::clockSeconds());
  if (linkClock_) statuses.insert(statuses.begin(), linkClock_->status());
  return statuses;
}

}  // namespace vitrine::host
