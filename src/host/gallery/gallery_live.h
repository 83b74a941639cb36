#pragma once
// Live input in the gallery (docs/LIVE.md): the run's LiveLink with the capture device, MIDI ports and
// gamepads, the user's mappings per scene kept in the settings file, the menu's live section, and MIDI
// learn (click a parameter, move a control). The gallery calls it at a scene switch, once a frame,
// before each step, and with what the menu returned.
#include "app/options.h"
#include "audio/engine.h"
#include "host/gallery/gallery_settings.h"
#include "host/gallery/gamepads.h"
#include "host/live_link.h"
#include "host/ui/live_panel.h"
#include "host/ui/param_panel.h"

#include <memory>
#include <string>
#include <vector>

namespace vitrine::host {

class GalleryLive {
 public:
  // `runScene`: the scene an unqualified --map line is for. Throws vitrine::Error for bad --map or --audio-in.
  // A sound file (--audio-in) plays through `output`, and its analysis follows what is heard.
  GalleryLive(const Options& options, GallerySettings& settings, audio::AudioOutput& output, std::string_view runScene);

  void showing(const SceneInfo& scene);  // a scene switch: its mappings from now on
  // Before each simulation step of the scene showing: gamepads, then the mapped values and actions.
  void step(SceneRenderer& renderer, FrameInput& input);
  LiveLink& link() { return *link_; }
  const LiveLink& link() const { return *link_; }
  // The keys mappings drive now: kept out of the settings file (their saved values stay).
  std::vector<std::string> drivenKeys() const { return link_->drivenKeys(); }
  std::vector<std::string> mappingLines() const { return link_->mappingLines(); }  // for the remote page

  LivePanel& panel() { return panel_; }
  LivePanelState panelState() const;
  // Applies what the menu returned; `parameters` tells MIDI learn which parameter was clicked. True
  // when the mappings playing the scene changed (the remote page lists them).
  bool apply(const LivePanelChoice& choice, ParamPanel& parameters);

 private:
  void setUserMappings(std::vector<std::string> lines);
  GallerySettings& settings_;
  bool audioFromFile_;
  std::unique_ptr<LiveLink> link_;
  Gamepads gamepads_;
  LivePanel panel_;
  std::vector<std::string> devices_;
  const SceneInfo* scene_ = nullptr;
  LearnStep learn_ = LearnStep::Idle;
  std::string learnKey_, message_;
  bool remapped_ = false;  // showing() ran during the current apply()
};

}  // namespace vitrine::host
