#pragma once
// The host's end of live input (docs/LIVE.md): the run's inputs (a sound file or a capture device, a
// MIDI file or the MIDI ports, OSC values, gamepads the gallery reads), the mappings of the scene
// showing, and once a simulation step, before the scene's update, the mapped values applied through
// the schema and the mapped actions added to the step's input. Shared by the gallery, headless and
// record runs; headless and record take only files, so a run is frame-exact and reproducible.
#include "frame/frame_input.h"
#include "host/live_clocks.h"
#include "lights/dmx_sources.h"
#include "live/modulator.h"
#include "live/source_bank.h"
#include "rig/clock_status.h"
#include "rig/link_clock.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {
class EventSink;
struct Options;
struct SceneInfo;
}  // namespace vitrine

namespace vitrine::live {
struct AudioClip;
class AudioFileInput;
class AudioCapture;
class SmfPlayer;
class MidiInput;
}  // namespace vitrine::live

namespace vitrine::lights {
class Lights;
}

namespace vitrine::host {

class SceneRenderer;

struct LiveConfig {
  std::vector<std::string> maps;  // --map: mapping files and lines, in order
  std::string runScene;           // the scene an unqualified --map line targets
  std::string audioFile;          // --audio-in
  bool loopAudioFile = false;     // the gallery loops it
  // Where in the sound file the analysis is (seconds): the gallery's is what the speakers played;
  // none: the simulation time, frame-exact (headless, record).
  std::function<double()> audioFileClock;
  bool captureAudio = false;      // capture from `audioDevice` (the gallery, audio input on)
  std::string audioDevice;        // empty: the default output's monitor, where there is one
  std::string midiFile;           // --midi-in
  bool midiPorts = false;         // the gallery: every MIDI port, hot-plugged
  std::optional<rig::LinkSettings> link;  // --link: the Ableton Link session (the gallery)
};

class LiveLink {
 public:
  // Reads the --map files and lines and the input files; throws vitrine::Error naming what is wrong.
  explicit LiveLink(LiveConfig config);
  ~LiveLink();
  LiveLink(const LiveLink&) = delete;
  LiveLink& operator=(const LiveLink&) = delete;

  // The scene showing from now on, with the user's own mapping lines for it (the settings file; a bad
  // line is skipped with a reason in *warnings). --map's join them, and while audio input is on, the
  // scene's audio mappings whose target no other mapping drives.
  void setScene(const SceneInfo& scene, const std::vector<std::string>& saved = {},
                std::vector<std::string>* warnings = nullptr);
  // One simulation step, before the scene's update: the sources at `input.time`, the mapped values
  // applied to the renderer's scene, fired actions appended to input.actions. Each applied value is
  // reported to `events` as {"event": "mapped", "key", "value", "by"}.
  void step(SceneRenderer& renderer, FrameInput& input, EventSink* events);
  // The sources at simulation time `time` (step's first half): files, devices, and MIDI learn's watch.
  void readInputs(double time);

  live::SourceBank& sources() { return sources_; }                // OSC and gamepads write here between steps
  const live::Modulator& modulator() const { return modulator_; }
  const std::vector<live::Mapping>& commandLineMappings() const { return commandLine_; }
  std::vector<std::string> mappingLines() const;  // the mappings playing the scene, as text (the remote page)
  // Keys of the scene showing that a mapping drives now (kept out of the settings file).
  std::vector<std::string> drivenKeys() const;

  bool audioOn() const { return audioFile_ != nullptr || capture_ != nullptr; }
  // The gallery's switch: capture from `device` (empty: the default monitor) or stop. A sound file
  // given with --audio-in stays what feeds the sources.
  void setAudioCapture(bool on, const std::string& device);
  // DMX in (--lights): the universes the patch and the mappings name are read from `lights` (it must
  // outlive this; null: none) as the dmx.* sources.
  void setDmxInput(lights::Lights* lights);
  // MIDI learn: the MIDI control, DMX channel or gamepad input that moved most since the last call, if any moved.
  std::optional<std::string> takeMovedControl();
  std::vector<std::string> status() const;  // one line per input, for the panel
  // The show's clocks this run follows (Link, MIDI clock, timecode), each as it stands now.
  std::vector<rig::ClockStatus> clockStatuses() const;
  // The Link session the link.* sources read (null without --link), and its reading at the last step.
  rig::LinkClock* linkClock() { return linkClock_.get(); }
  const std::optional<rig::LinkReading>& linkReading() const { return linkReading_; }
  // The show's clocks heard (MIDI clock, MIDI timecode, LTC): their statuses, the timecode to chase.
  const LiveClocks& clocks() const { return clocks_; }
  // The --audio-in file, for a film's sound track; null without one.
  const live::AudioClip* audioClip() const;
  // What feeds a run, for a recording's manifest: the mapping lines and the input files' bytes, hashed.
  std::string fingerprintText() const;

 private:
  void remap();
  void readFileLtc(double fileTime);
  // Sets aside, with one line each, the mappings whose range the scene showing refuses (bloom's
  // thresholds must rise: amber mapped up to 1 is inside amber's own range, but not below rose).
  void vet(SceneRenderer& renderer);
  LiveConfig config_;
  std::vector<live::Mapping> commandLine_;
  std::vector<live::Mapping> saved_;
  const SceneInfo* scene_ = nullptr;
  live::SourceBank sources_;
  live::Modulator modulator_;
  std::unique_ptr<live::AudioFileInput> audioFile_;
  std::unique_ptr<live::AudioCapture> capture_;
  std::vector<float> soundWave_, soundSpectrum_;  // the latest readInputs' sound, for the step's input
  std::unique_ptr<live::SmfPlayer> midiFile_;
  std::unique_ptr<live::MidiInput> midiPorts_;
  std::unique_ptr<rig::LinkClock> linkClock_;
  lights::Lights* dmx_ = nullptr;
  lights::DmxSources dmxSources_;
  struct DmxTaken {
    uint32_t universe;
    double arrived, taken;  // steady clock seconds
  };
  std::vector<DmxTaken> dmxTaken_;  // this step's DMX frames, for --events
  void playLights();
  std::optional<float> lightsMaster_, lightsBlackout_;  // the master and blackout sources as last applied
  std::optional<rig::LinkReading> linkReading_;
  LiveClocks clocks_;
  uint64_t ltcFed_ = 0;  // samples of the --audio-in file given to the LTC reader
  std::map<std::string, float, std::less<>> controlsSeen_;  // MIDI learn: the controls' last values
  std::optional<std::string> moved_;
  float movedBy_ = 0.0f;
  bool vetted_ = false;       // the mappings playing now have been judged against the live scene
  std::string lastRefusal_;   // while the scene refuses the mapped values: said once, when it begins
};

// The Link session's reading as the link.* sources (docs/LIVE.md), each 0..1: link.tempo (0..240 BPM),
// link.beat and link.phase (rising through each beat and each bar), link.pulse and link.bar (1 for the
// step a beat or a bar begins on; `lastBar`: the bar of the previous step's reading), link.playing.
void setLinkSources(const rig::LinkReading& now, std::optional<int64_t> lastBar, double quantum, live::SourceBank& sources);

// The offline runs' live input (headless, record): the --map, --audio-in and --midi-in files for
// `scene`, frame-exact; null when the command line asks for none. Throws vitrine::Error for bad input.
std::unique_ptr<LiveLink> offlineLiveInput(const Options& options, const std::string& scene);

}  // namespace vitrine::host
