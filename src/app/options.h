#pragma once
// The command line, parsed into one value. Bad input is a vitrine::Error with a sentence that says
// what was wrong and what would be right; main turns it into a non-zero exit. The flags themselves are
// declared in app/flags.cpp; --help, the man page and the completion script in app/help.h.
#include "film/film_format.h"
#include "image/image_compare.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vitrine {

enum class Mode {
  Gallery, Headless, Bench, Record, Encode, Compare, ListDevices, ListMonitors, ListScenes, ListParams, ListKeys, ListPresets,
  ExportPreset, Help, HelpMan, HelpCompletion, Version
};

// One --set or --preset: "SCENE.KEY=VALUE" applies to that scene only, "KEY=VALUE" to whichever runs.
struct SceneSetting {
  std::string scene;  // empty: not qualified
  std::string key;    // --set: the parameter; --preset: the preset's name
  std::string value;  // --set: its value; --preset: empty
  bool operator==(const SceneSetting&) const = default;
};

// One --set filter.NAME.KEY=VALUE: a parameter of the filters loaded from NAME (the file's name without
// its extension) in the chain after the scene.
struct FilterSetting {
  std::string filter;  // NAME
  std::string key;
  std::string value;
  bool operator==(const FilterSetting&) const = default;
};

struct Options {
  Mode mode = Mode::Gallery;
  std::string scene;                 // empty: the first in the registry (gallery), "all" (bench)
  std::string device;                // --device INDEX|NAME
  bool validation = false;           // --validate, or VITRINE_VALIDATION=1
  bool pipelineStats = false;        // bench --pipeline-stats: compiler statistics, invocations a pass
  bool reducedMotion = false;
  std::optional<bool> flashGuard;    // --flash-guard on|off; unset: flashGuardOn() decides
  uint32_t seed = 0;
  std::optional<VkExtent2D> size;    // --size WxH (window size in the gallery)
  uint32_t frames = 1;
  double time = 0.0;
  std::string out;                   // --out (headless image) / --json (bench)
  uint32_t warmup = 30;              // bench
  bool fullscreen = false;
  bool vsync = true;
  std::vector<SceneSetting> parameters;  // --set [SCENE.]KEY=VALUE, in command-line order
  std::vector<SceneSetting> presets;     // --preset [SCENE.]NAME, in command-line order
  std::vector<std::string> filters;      // --filter FILE: ISF filters after every scene of the run, in order
  std::vector<FilterSetting> filterParameters;  // --set filter.NAME.KEY=VALUE, in command-line order
  std::string transition;                // --transition FILE (gallery): an ISF transition for scene changes
  std::vector<std::pair<std::string, std::string>> transitionParameters;  // --set transition.KEY=VALUE
  std::vector<std::string> isf;      // --isf FILE: ISF generators shown as scenes (registered before parsing)
  std::vector<std::string> presetFiles;  // --preset-file FILE: a preset's file, applied to its own scene
  std::string savePreset;                // --save-preset NAME (headless): the run's values kept as the user's preset
  SceneSetting exportPreset;             // --export-preset [SCENE.]NAME --out FILE: a user's preset written out
  std::vector<std::string> compare;  // compare REF CANDIDATE
  CompareThresholds compareThresholds;  // compare --fail-fraction F --hard-limit H --lowpass N
  std::string listParams;            // --list-params, --list-keys, --list-presets [SCENE]: empty for every scene
  std::string input;                 // --input FILE (headless): scripted input
  std::string events;                // --events FILE (headless): the scene's events, as JSON lines
  bool resetSettings = false;        // --reset-settings (gallery)
  std::string monitor;               // --monitor N|NAME (gallery): where the window and fullscreen go
  std::string outputWarp;            // --output-warp FILE (gallery, headless): the output's turn, pin, blend
  std::string outputs;               // --outputs FILE (gallery): more windows showing the frame (projectors)
  std::string pipewire;              // --pipewire NAME[@WxH] (gallery): the frame published as a PipeWire node
  std::optional<VkExtent2D> pipewireSize;  // its size offered first; unset: the window's
  bool publish = false;              // bench --publish: a published output of the bench's size, timed
  bool span = false;                 // --span (gallery): the window covers every monitor, without a frame
  std::string audioOut;              // --audio-out FILE.wav (headless): the run's sound, offline
  // record: a numbered sequence of frames into the folder --out.
  double fps = 30.0;                 // --fps F
  double seconds = 0.0;              // --seconds S: the film's length
  uint32_t spp = 1;                  // --spp K: sub-frame samples averaged into each frame
  std::optional<std::pair<uint32_t, uint32_t>> range;  // --range A:B: only frames A .. B-1
  std::string format = "exr";        // --format exr|png
  uint32_t checkpointEvery = 0;      // --checkpoint-every N: the simulation saved every N frames (0: never)
  bool checkpointsOnly = false;      // --checkpoints-only: simulate and write checkpoints, draw no frame
  // Films: record --out NAME.mp4|.mov|.mkv encodes as it renders; encode FOLDER turns a sequence into one.
  film::FilmRequest film;            // --codec, --crf, --bitrate, --pix-fmt, --full-range
  std::string sequence;              // encode FOLDER: a recorded sequence with its record.json
  // The gallery for installations.
  bool kiosk = false;                // --kiosk: fullscreen, no UI, cycling through the scenes
  double dwell = 45.0;               // --dwell SECONDS: how long each scene shows in kiosk mode
  std::string playlist;              // --playlist FILE: the kiosk shows its entries instead (host/gallery/playlist.h)
  bool remote = false;               // --remote: OSC and the web control page (gallery and headless)
  std::string remoteBind = "127.0.0.1:8730";  // --remote-bind ADDR:PORT
  std::vector<std::string> remoteAllow;  // --remote-allow CIDR (repeatable): OSC senders needing no token
  bool remoteSaves = false;          // --remote-saves: remote changes are written to the settings file too
  // Live input (docs/LIVE.md).
  std::vector<std::string> maps;     // --map FILE or --map SOURCE=[SCENE.]KEY[:LO:HI] ..., in order
  std::string lights;                // --lights FILE.json: the lights' patch (docs/LIGHTS.md)
  std::string audioIn;               // --audio-in FILE: a sound file drives the audio sources
  std::string audioInDevice;         // --audio-in-device NAME|INDEX|default (gallery): capture from it
  std::string midiIn;                // --midi-in FILE.mid (headless, record): MIDI events on simulation time
  // A live stream of the picture and its sound (gallery, headless): film/stream_sender.h.
  std::string stream;                // --stream URL: srt://, rtmp://, rtp://, udp://
  int64_t streamBitrate = 6'000'000; // --stream-bitrate N[k|M]: the video's bits a second
  uint32_t streamLatencyMs = 200;    // --stream-latency MS: SRT's latency, the stream's queue
  // Ableton Link (gallery; docs/RIG.md): any of these flags joins the session.
  bool link = false;                 // --link: the link.* sources
  double linkQuantum = 4.0;          // --link-quantum BEATS: beats a bar
  std::optional<double> linkTempo;   // --link-tempo BPM: the tempo the gallery leads with
  bool linkWaitBar = false;          // --link-wait-bar: scene switches wait for the next bar
};

// Whether frames go through the flash guard (docs/INSTALLATIONS.md): as --flash-guard says, else on in
// kiosk mode and with --reduced-motion, where nobody may be there to look away, or somebody asked for calm.
inline bool flashGuardOn(const Options& options) {
  return options.flashGuard.value_or(options.kiosk || options.reducedMotion);
}

// A record run's frame size when --size is not given.
inline constexpr VkExtent2D kRecordSize{1280, 720};
inline constexpr double kMaxRecordFps = 1000.0;  // record's --fps, and a record.json's fps
inline constexpr uint32_t kMaxRecordSpp = 256;   // record's --spp, and a record.json's spp

Options parseOptions(int argc, const char* const* argv);
// The --set pairs that apply to `scene`, in command-line order: those naming it, and the unqualified
// ones when `unqualifiedToo` (the scene the run is about: --scene's).
std::vector<std::pair<std::string, std::string>> parametersFor(const Options& options, std::string_view scene,
                                                               bool unqualifiedToo);
// The --preset names that apply to `scene`, likewise.
std::vector<std::string> presetsFor(const Options& options, std::string_view scene, bool unqualifiedToo);
VkExtent2D parseSize(const std::string& text);  // "1920x1080"

}  // namespace vitrine
