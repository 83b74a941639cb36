#include "host/gallery/gallery_live.h"

#include "core/error.h"
#include "host/scene_renderer.h"
#include "live/audio_capture.h"
#include "live/audio_clip.h"
#include "scenes/catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

namespace vitrine::host {

GalleryLive::GalleryLive(const Options& options, GallerySettings& settings, audio::AudioOutput& output,
                         std::string_view runScene)
    : settings_(settings), audioFromFile_(!options.audioIn.empty()) {
  // --audio-in-device names the device for this run (and turns capture on); else the saved choice.
  const bool named = !options.audioInDevice.empty();
  const std::string device = named ? (options.audioInDevice == "default" ? "" : options.audioInDevice) : settings.audioDevice();
  link_ = std::make_unique<LiveLink>(LiveConfig{.maps = options.maps, .runScene = std::string(runScene),
                                                .audioFile = options.audioIn, .loopAudioFile = true,
                                                .audioFileClock = [&output] { return output.musicSeconds(); },
                                                .captureAudio = !audioFromFile_ && (named || settings.audioInput()),
                                                .audioDevice = device, .midiPorts = true,
                                                .link = options.link ? std::optional(rig::LinkSettings{options.linkQuantum, options.linkTempo})
                                                                     : std::nullopt});
  if (const live::AudioClip* clip = link_->audioClip()) output.playMusic(live::stereo48k(*clip, 0.0, clip->seconds()));
  devices_ = live::AudioCapture::inputDevices();
}

void GalleryLive::showing(const SceneInfo& scene) {
  scene_ = &scene;
  std::vector<std::string> warnings;
  link_->setScene(scene, settings_.mappingsFor(scene.name), &warnings);
  remapped_ = true;
  for (const auto& warning : warnings) std::fprintf(stderr, "vitrine: settings: %s\n", warning.c_str());
  learn_ = LearnStep::Idle;
}

void GalleryLive::step(SceneRenderer& renderer, FrameInput& input) {
  gamepads_.read(link_->sources());
  link_->step(renderer, input, nullptr);
}

LivePanelState GalleryLive::panelState() const {
  LivePanelState state;
  state.audioOn = link_->audioOn();
  state.audioFromFile = audioFromFile_;
  state.audioDevice = settings_.audioDevice();
  state.devices = devices_;
  state.status = link_->status();
  state.mappings = link_->modulator().states();
  state.userMappings = scene_ ? std::min(settings_.mappingsFor(scene_->name).size(), state.mappings.size()) : 0;
  state.learn = learn_;
  state.learnKey = learnKey_;
  state.message = message_;
  return state;
}

void GalleryLive::setUserMappings(std::vector<std::string> lines) {
  settings_.setMappings(scene_->name, std::move(lines), GallerySettings::Clock::now());
  showing(*scene_);
}

bool GalleryLive::apply(const LivePanelChoice& choice, ParamPanel& parameters) {
  if (!scene_) return false;
  remapped_ = false;
  if (choice.audioOn || choice.audioDevice) {
    const bool on = choice.audioOn.value_or(link_->audioOn() || choice.audioDevice.has_value());
    const std::string device = choice.audioDevice.value_or(settings_.audioDevice());
    settings_.setAudioInput(on, device, GallerySettings::Clock::now());
    link_->setAudioCapture(on, device);
    remapped_ = true;  // the scene's audio mappings come and go with audio input
    message_ = on && !link_->audioOn() ? "no audio input could be opened (see the console)" : "";
  }
  const auto add = [&](const std::string& line) {
    std::string why;
    auto mapping = live::parseMapping(line, &why);
    if (mapping && mapping->scene.empty()) mapping->scene = scene_->name;
    if (mapping) why = live::checkMapping(*mapping, *scene_);
    if (!why.empty()) return message_ = fmt::format("{}: {}", line, why), false;
    std::vector<std::string> lines = settings_.mappingsFor(scene_->name);
    lines.push_back(live::formatMapping(*mapping));
    setUserMappings(std::move(lines));
    message_.clear();
    return true;
  };
  if (choice.add) add(*choice.add);
  if (choice.remove && *choice.remove < settings_.mappingsFor(scene_->name).size()) {
    std::vector<std::string> lines = settings_.mappingsFor(scene_->name);
    lines.erase(lines.begin() + std::ptrdiff_t(*choice.remove));
    setUserMappings(std::move(lines));
  }
  if (choice.save) {
    std::vector<live::Mapping> mine;
    for (const std::string& line : settings_.mappingsFor(scene_->name))
      if (auto mapping = live::parseMapping(line, nullptr)) mine.push_back(std::move(*mapping));
    try {
      live::saveMappingFile(*choice.save, mine);
      message_ = fmt::format("saved {} mappings to {}", mine.size(), *choice.save);
    } catch (const Error& e) {
      message_ = e.what();
    }
  }
  if (choice.load) {
    try {  // each scene the file names gets its mappings, after its own
      size_t count = 0;
      for (const live::Mapping& mapping : live::loadMappingFile(*choice.load)) {
        std::vector<std::string> lines = settings_.mappingsFor(mapping.scene);
        const std::string line = live::formatMapping(mapping);
        if (std::find(lines.begin(), lines.end(), line) != lines.end()) continue;
        lines.push_back(line);
        settings_.setMappings(mapping.scene, std::move(lines), GallerySettings::Clock::now());
        ++count;
      }
      showing(*scene_);
      message_ = fmt::format("loaded {} mappings from {}", count, *choice.load);
    } catch (const Error& e) {
      message_ = e.what();
    }
  }

  // MIDI learn: a click on a parameter, then the control that moves most.
  if (choice.cancelLearn) learn_ = LearnStep::Idle;
  if (choice.learn) {
    learn_ = LearnStep::ClickParameter;
    parameters.takeClicked();
    message_.clear();
  }
  if (learn_ == LearnStep::ClickParameter) {
    if (auto key = parameters.takeClicked()) {
      learnKey_ = *key;
      learn_ = LearnStep::MoveControl;
      link_->takeMovedControl();  // only what moves from now on
    }
  } else if (learn_ == LearnStep::MoveControl) {
    if (auto control = link_->takeMovedControl()) {
      learn_ = LearnStep::Idle;
      if (add(fmt::format("{}={}.{}", *control, scene_->name, learnKey_))) message_ = fmt::format("learnt {} for {}", *control, learnKey_);
    }
  }
  return remapped_;
}

}  // namespace vitrine::host
