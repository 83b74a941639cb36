// The command line's flags, each declared once (app/flags.h says who reads this table).
#include "app/flags.h"

#include "app/values.h"
#include "core/error.h"
#include "rig/link_clock.h"
#include "scenes/catalogue.h"
#include "scenes/pieces/piece_catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace vitrine::flags {
namespace {

// Stores for the common shapes: a member set to the value, switched on, or added to.
template <auto Member>
constexpr Store text = [](Options& o, std::string_view, const std::string& v) { o.*Member = v; };
template <auto Member>
constexpr Store on = [](Options& o, std::string_view, const std::string&) { o.*Member = true; };
template <auto Member>
constexpr Store append = [](Options& o, std::string_view, const std::string& v) { (o.*Member).push_back(v); };
// A listing mode; one of a scene, with its optional scene checked when given.
template <Mode M>
constexpr Store listing = [](Options& o, std::string_view, const std::string&) { o.mode = M; };
template <Mode M>
constexpr Store sceneListing = [](Options& o, std::string_view, const std::string& v) {
  if (!v.empty() && !findScene(v)) throw Error(unknownScene(v));
  o.mode = M;
  o.listParams = v;
};

constexpr unsigned kLive = kGallery | kHeadless | kRecord;  // the modes live input plays into
constexpr unsigned kFilm = kRecord | kEncode;

// The order is --help's and the man page's: flags of the same modes are shown together, in the order
// their first one appears here.
constexpr Flag kFlags[] = {
    // Every run of a scene.
    {.name = "--scene", .modes = kRuns, .metavar = "NAME", .value = Value::Scene, .requiredIn = kHeadless | kRecord,
     .help = "The scene to run, by name (vitrine --list-scenes). The gallery starts with the first; bench "
             "takes all, which is also its default.",
     .store = text<&Options::scene>},
    {.name = "--isf", .modes = kRuns, .metavar = "FILE", .value = Value::File, .repeatable = true,
     .help = "Shows an ISF generator (a .fs file, docs/ISF.md) as a scene after the built-in ones, its inputs as "
             "its parameters; the first one given is the scene to run unless --scene names another.",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           o.isf.push_back(v);
           if (const pieces::Piece* piece = pieces::findPieceByPath(v); piece && o.scene.empty()) o.scene = piece->name;
         }},
    {.name = "--size", .modes = kRuns, .metavar = "WxH", .value = Value::Text,
     .help = "The window's size in the gallery (at most 16384 a side), else the frames' size (record's "
             "default 1280x720); headless and bench sizes are checked against the device.",
     .store = [](Options& o, std::string_view, const std::string& v) { o.size = parseSize(v); }},
    {.name = "--seed", .modes = kRuns, .metavar = "S", .value = Value::Text,
     .help = "The seed of the scenes' random choices, a whole number from 0 to 4294967295.",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.seed = parseWhole(flag, v, 0); }},
    {.name = "--set", .modes = kRuns, .metavar = "[SCENE.]KEY=VALUE", .value = Value::Setting, .repeatable = true,
     .help = "Sets a scene parameter, with the panel's ranges (vitrine --list-params). KEY=VALUE applies to "
             "whichever scene runs, SCENE.KEY=VALUE (noodles.grid=32) to that scene only. All values given for "
             "a scene are judged together, on the final values. filter.NAME.KEY=VALUE sets an input of the "
             "--filter whose file is NAME (without its extension), transition.KEY=VALUE one of the --transition.",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           if (auto filter = parseFilterSet(v)) o.filterParameters.push_back(std::move(*filter));
           else if (auto transition = parseTransitionSet(v)) o.transitionParameters.push_back(std::move(*transition));
           else o.parameters.push_back(parseSet(v));
         }},
    {.name = "--filter", .modes = kRuns, .metavar = "FILE", .value = Value::File, .repeatable = true,
     .help = "An ISF filter (a .fs with an inputImage) over the picture of every scene the run shows, before "
             "the flash guard and the outputs; given again, the next one filters the first one's picture "
             "(docs/ISF.md). In the gallery it replaces the scenes' saved filters for the run.",
     .store = append<&Options::filters>},
    {.name = "--preset", .modes = kRuns, .metavar = "[SCENE.]NAME", .value = Value::Preset, .repeatable = true,
     .help = "Applies a named set of values before any --set: the scene's own presets first, then yours "
             "(saved from the panel, a remote or --save-preset, in the presets folder beside the settings "
             "file). SCENE.NAME applies to that scene only.",
     .store = [](Options& o, std::string_view, const std::string& v) { o.presets.push_back(parsePreset(v)); }},
    {.name = "--preset-file", .modes = kRuns, .metavar = "FILE", .value = Value::File, .repeatable = true,
     .help = "Applies a preset's file (as --export-preset and the panel's export write it) to its own scene.",
     .store = append<&Options::presetFiles>},
    {.name = "--device", .modes = kRuns, .metavar = "INDEX|NAME", .value = Value::Text,
     .help = "The Vulkan device, by index or part of its name (vitrine --list-devices); default: a discrete GPU "
             "if there is one.",
     .store = text<&Options::device>},
    {.name = "--validate", .modes = kRuns, .value = Value::None,
     .help = "Turns on the Khronos validation layer with synchronisation checks (as VITRINE_VALIDATION=1 does); "
             "any message then makes the run exit non-zero.",
     .store = on<&Options::validation>},
    {.name = "--reduced-motion", .modes = kRuns, .value = Value::None,
     .help = "Asks the scenes for calm: slower, gentler motion where a scene has it; turns the flash guard on.",
     .store = on<&Options::reducedMotion>},
    {.name = "--flash-guard", .modes = kRuns, .metavar = "on|off", .value = Value::Choice,
     .help = "on holds back what would flash more than three times a second over a large area (WCAG 2.3.1; "
             "docs/INSTALLATIONS.md). It is on by default with --kiosk and --reduced-motion, off otherwise.",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           const std::string state = lowercase(v);
           if (state != "on" && state != "off") throw Error(fmt::format("--flash-guard is on or off, not '{}'.", state));
           o.flashGuard = state == "on";
         }},

    // Live input (docs/LIVE.md).
    {.name = "--map", .modes = kLive, .metavar = "FILE|SOURCE=[SCENE.]KEY[:LO:HI]", .value = Value::File,
     .repeatable = true,
     .help = "Plays a parameter or an action from a source: audio.bass, midi.cc.1.21, pad.0.axis.1, osc.NAME, "
             "lfo.sine.8; or the mappings of a file (docs/LIVE.md).",
     .store = append<&Options::maps>},
    {.name = "--audio-in", .modes = kLive, .metavar = "FILE", .value = Value::File,
     .help = "Feeds a sound file to the audio sources (looped in the gallery, frame-exact in headless and record "
             "runs, whose audio.wav then carries it) and turns on the scenes' audio mappings.",
     .store = text<&Options::audioIn>},

    // The gallery and headless runs.
    {.name = "--remote", .modes = kGallery | kHeadless, .value = Value::None,
     .help = "Serves a control page for phones and listens for OSC on 127.0.0.1:8730; prints the page's address "
             "with its access token (docs/REMOTE.md).",
     .store = on<&Options::remote>},
    {.name = "--remote-bind", .modes = kGallery | kHeadless, .metavar = "ADDR:PORT", .value = Value::Text,
     .help = "Where --remote listens (and turns it on). Bound beyond loopback, OSC is taken only from "
             "--remote-allow networks or senders that sent the token.",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           o.remoteBind = v;
           o.remote = true;
         }},
    {.name = "--remote-allow", .modes = kGallery | kHeadless, .metavar = "CIDR", .value = Value::Text,
     .repeatable = true,
     .help = "A network (192.168.1.0/24) whose OSC senders need no token; needs --remote.",
     .store = append<&Options::remoteAllow>},
    {.name = "--output-warp", .modes = kGallery | kHeadless, .metavar = "FILE.json", .value = Value::File,
     .help = "Turns, mirrors, crops, corner-pins and edge-blends the output for a projector "
             "(docs/INSTALLATIONS.md).",
     .store = text<&Options::outputWarp>},
    {.name = "--lights", .modes = kGallery | kHeadless, .metavar = "FILE.json", .value = Value::File,
     .help = "Lights the room through olad (the Open Lighting Architecture): the patch maps the scenes' light "
             "signals to DMX fixtures and names the universes whose channels are the dmx.* sources "
             "(docs/LIGHTS.md). Headless, the last frame's lights are sent.",
     .store = text<&Options::lights>},

    {.name = "--stream", .modes = kGallery | kHeadless, .metavar = "URL", .value = Value::Text,
     .help = "Streams the picture and its sound live, h264 and AAC at 60 frames a second: srt://HOST:PORT and "
             "udp:// or rtp:// as MPEG-TS, rtmp://HOST/APP/KEY as FLV. A connection that fails or drops is tried "
             "again; the run goes on meanwhile (docs/RIG.md).",
     .store = text<&Options::stream>},
    {.name = "--stream-bitrate", .modes = kGallery | kHeadless, .metavar = "N[k|M]", .value = Value::Text,
     .help = "The stream's video bit rate (6M), at most that much in any second.",
     .store = [](Options& o, std::string_view, const std::string& v) { o.streamBitrate = film::parseBitrate(v); }},
    {.name = "--stream-latency", .modes = kGallery | kHeadless, .metavar = "MS", .value = Value::Text,
     .help = "The stream's latency in milliseconds (200), 20 to 10000: SRT's receive buffer, and how many frames "
             "may wait for the encoder before one is dropped.",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) { o.streamLatencyMs = parseWhole(flag, v, 20, 10000); }},

    // The gallery.
    {.name = "--fullscreen", .modes = kGallery, .value = Value::None, .help = "Starts fullscreen (F11 toggles).",
     .store = on<&Options::fullscreen>},
    {.name = "--no-vsync", .modes = kGallery, .value = Value::None,
     .help = "Presents as fast as the scene renders (V toggles).",
     .store = [](Options& o, std::string_view, const std::string&) { o.vsync = false; }},
    {.name = "--monitor", .modes = kGallery, .metavar = "INDEX|NAME", .value = Value::Text,
     .help = "Puts the window, and F11's fullscreen, on a monitor from --list-monitors (its index or part of its "
             "name).",
     .store = text<&Options::monitor>},
    {.name = "--span", .modes = kGallery, .value = Value::None,
     .help = "Stretches the window, without a frame, over every monitor (not with --monitor).",
     .store = on<&Options::span>},
    {.name = "--outputs", .modes = kGallery, .metavar = "FILE.json", .value = Value::File,
     .help = "Opens more windows (projectors), each fullscreen on a monitor or at a place, showing the same frame "
             "through its own warp; the scene still renders once.",
     .store = text<&Options::outputs>},
    {.name = "--pipewire", .modes = kGallery, .metavar = "NAME[@WxH]", .value = Value::Text,
     .help = "Publishes the whole frame as a PipeWire video source named NAME (OBS, GStreamer's pipewiresrc, a "
             "browser take it), offered at the window's size or WxH; the consumer may negotiate another size. "
             "Frames a consumer cannot take are dropped, never waited for (docs/RIG.md).",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) {
           const size_t at = v.rfind('@');
           o.pipewire = at == std::string::npos ? v : v.substr(0, at);
           if (o.pipewire.empty()) throw Error(fmt::format("{} needs a node name", flag));
           if (at == std::string::npos) return;
           try {
             o.pipewireSize = parseSize(v.substr(at + 1));
           } catch (const Error&) {
             throw Error(fmt::format("{} expects NAME or NAME@WIDTHxHEIGHT such as stage@1920x1080, not '{}'.", flag, v));
           }
         }},
    {.name = "--reset-settings", .modes = kGallery, .value = Value::None,
     .help = "Forgets the saved settings and the menu's place and folds.",
     .store = on<&Options::resetSettings>},
    {.name = "--kiosk", .modes = kGallery, .value = Value::None,
     .help = "Fullscreen, no UI, cycling through the scenes with a cross-fade; a touch holds the scene, cycling "
             "resumes after 30 s alone (the dwell when shorter, 10 s at least).",
     .store =
         [](Options& o, std::string_view, const std::string&) {
           o.kiosk = true;
           o.fullscreen = true;
         }},
    {.name = "--dwell", .modes = kGallery, .metavar = "SECONDS", .value = Value::Text,
     .help = "How long the kiosk shows each scene (45).",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.dwell = parsePositive(flag, v, 86400.0); }},
    {.name = "--playlist", .modes = kGallery, .metavar = "FILE", .value = Value::File,
     .help = "Gives the kiosk its lines of SCENE [PRESET] SECONDS instead (needs --kiosk, not with --dwell).",
     .store = text<&Options::playlist>},
    {.name = "--transition", .modes = kGallery, .metavar = "FILE", .value = Value::File,
     .help = "An ISF transition (startImage, endImage, progress) instead of the cross-fade: the kiosk's and "
             "the playlist's changes, and the gallery's scene switches, which then take its two seconds too.",
     .store = text<&Options::transition>},
    {.name = "--remote-saves", .modes = kGallery, .value = Value::None,
     .help = "Remote changes are written to the settings file too (needs --remote).",
     .store = on<&Options::remoteSaves>},
    {.name = "--audio-in-device", .modes = kGallery, .metavar = "NAME|INDEX|default", .value = Value::Text,
     .help = "Feeds the audio sources from a capture device, as --audio-in does from a file (not both).",
     .store = text<&Options::audioInDevice>},

    {.name = "--link", .modes = kGallery, .value = Value::None,
     .help = "Joins the Ableton Link session on the network: its tempo, beat, phase and bar become the link.* "
             "sources; alone, the gallery keeps its own tempo.",
     .store = on<&Options::link>},
    {.name = "--link-quantum", .modes = kGallery, .metavar = "BEATS", .value = Value::Text,
     .help = "Beats a bar in the Link session (4), from 1 to 64; joins it.",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) {
           o.linkQuantum = parseNumberIn(flag, v, rig::LinkClock::kMinQuantum, rig::LinkClock::kMaxQuantum);
           o.link = true;
         }},
    {.name = "--link-tempo", .modes = kGallery, .metavar = "BPM", .value = Value::Text,
     .help = "Leads the Link session at this tempo, from 20 to 999 beats a minute; joins it.",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) {
           o.linkTempo = parseNumberIn(flag, v, rig::LinkClock::kMinBpm, rig::LinkClock::kMaxBpm);
           o.link = true;
         }},
    {.name = "--link-wait-bar", .modes = kGallery, .value = Value::None,
     .help = "Scene switches (the kiosk's next line with its preset, a number key, a remote) and presets applied "
             "from the panel or a phone wait for the next bar of the Link session; joins it.",
     .store =
         [](Options& o, std::string_view, const std::string&) {
           o.linkWaitBar = true;
           o.link = true;
         }},

    // Headless runs.
    {.name = "--headless", .modes = kHeadless, .value = Value::None, .requiredIn = kHeadless,
     .help = "Renders with no window and writes the last frame to --out.",
     .store = [](Options& o, std::string_view, const std::string&) { o.mode = Mode::Headless; }},
    {.name = "--save-preset", .modes = kHeadless, .metavar = "NAME", .value = Value::Text,
     .help = "Keeps the run's values as your preset NAME, which --preset then finds.",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           if (v.empty()) throw Error("--save-preset expects a name for the preset, not ''.");
           o.savePreset = v;
         }},
    {.name = "--audio-out", .modes = kHeadless, .metavar = "FILE.wav", .value = Value::File,
     .help = "Writes the run's sound, rendered offline, as WAV.",
     .store = text<&Options::audioOut>},
    {.name = "--frames", .modes = kHeadless | kBench, .metavar = "N", .value = Value::Text,
     .help = "How many frames to render (headless: 1; bench: 200), a whole number from 1.",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.frames = parseWhole(flag, v, 1); }},
    {.name = "--time", .modes = kHeadless | kBench | kRecord, .metavar = "SECONDS", .value = Value::Text,
     .help = "The scene's time at the first frame, any finite number of seconds (0).",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.time = parseSeconds(flag, v); }},
    {.name = "--input", .modes = kHeadless | kRecord, .metavar = "FILE", .value = Value::File,
     .help = "Drives the run with a scripted cursor and keys, checked line by line (FILE:LINE in every error).",
     .store = text<&Options::input>},
    {.name = "--events", .modes = kHeadless | kRecord, .metavar = "FILE", .value = Value::File,
     .help = "Writes what the scene reported as JSON lines, when the run ends.",
     .store = text<&Options::events>},
    {.name = "--midi-in", .modes = kHeadless | kRecord, .metavar = "FILE.mid", .value = Value::File,
     .help = "Plays a MIDI file's events against simulation time.",
     .store = text<&Options::midiIn>},
    {.name = "--out", .modes = kHeadless | kRecord | kEncode | kExport, .metavar = "FILE", .value = Value::File,
     .requiredIn = kHeadless | kRecord | kEncode | kExport,
     .help = "Where the run writes: --headless an image, linear half-float .exr or 8-bit sRGB .png (the name "
             "decides, in any case); record a FOLDER of numbered frames, or a film FILM.mp4, .mov or .mkv; encode "
             "a film; --export-preset the preset's FILE.json.",
     .store = text<&Options::out>},

    // bench.
    {.name = "--json", .modes = kBench, .metavar = "FILE", .value = Value::File, .requiredIn = kBench,
     .help = "Where bench writes its timings (any name, but not a device, fifo or read-only file).",
     .store = text<&Options::out>},
    {.name = "--warmup", .modes = kBench, .metavar = "N", .value = Value::Text,
     .help = "Frames rendered before the timed ones (30), a whole number from 0.",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.warmup = parseWhole(flag, v, 0); }},
    {.name = "--publish", .modes = kBench, .value = Value::None,
     .help = "Adds a published output (as --pipewire's) of the bench's size and times its passes, publish and "
             "publish copy; no PipeWire daemon is needed.",
     .store = on<&Options::publish>},
    {.name = "--pipeline-stats", .modes = kBench, .value = Value::None,
     .help = "Adds the compiler's statistics and each pass's shader invocations to the JSON.",
     .store = on<&Options::pipelineStats>},

    // record.
    {.name = "--seconds", .modes = kRecord, .metavar = "S", .value = Value::Text, .requiredIn = kRecord,
     .help = "The film's length.",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) { o.seconds = parsePositive(flag, v, 86400.0); }},
    {.name = "--fps", .modes = kRecord, .metavar = "F", .value = Value::Text,
     .help = "Frames a second (30): each frame is 1/F s of the scene's time.",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) { o.fps = parsePositive(flag, v, kMaxRecordFps); }},
    {.name = "--spp", .modes = kRecord, .metavar = "K", .value = Value::Text,
     .help = "Samples a frame (1 to 256), spread over its interval and averaged: motion blur and anti-aliasing.",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.spp = parseWhole(flag, v, 1); }},
    {.name = "--range", .modes = kRecord, .metavar = "A:B", .value = Value::Text,
     .help = "Renders frames A to B-1 only, the same pixels whichever machine renders them (a folder only).",
     .store = [](Options& o, std::string_view, const std::string& v) { o.range = parseRange(v); }},
    {.name = "--checkpoint-every", .modes = kRecord, .metavar = "N", .value = Value::Text,
     .help = "Saves the simulation every N frames (FOLDER/checkpoint_NNNNNN.state); a run starts from the latest "
             "checkpoint at or before its first missing frame instead of simulating from frame 0.",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.checkpointEvery = parseWhole(flag, v, 1); }},
    {.name = "--checkpoints-only", .modes = kRecord, .value = Value::None,
     .help = "Writes the checkpoints without drawing a frame: a cheap first job before ranges on many machines.",
     .store = on<&Options::checkpointsOnly>},
    {.name = "--format", .modes = kRecord, .metavar = "exr|png", .value = Value::Choice,
     .help = "The frames' files in a folder (exr).",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           o.format = lowercase(v);
           if (o.format != "exr" && o.format != "png")
             throw Error(fmt::format("--format writes exr or png, not '{}'.", o.format));
         }},

    // Films: record and encode.
    {.name = "--codec", .modes = kFilm, .metavar = "h264|hevc|prores|prores4444|ffv1", .value = Value::Choice,
     .help = "The film's codec: by default h264 in .mp4, ProRes 422 HQ in .mov, lossless FFV1 in .mkv.",
     .store = [](Options& o, std::string_view, const std::string& v) { o.film.codec = film::parseCodec(v); }},
    {.name = "--crf", .modes = kFilm, .metavar = "N", .value = Value::Text,
     .help = "The quality, 0 to 51 (18 for h264, 20 for hevc); not with --bitrate.",
     .store = [](Options& o, std::string_view flag, const std::string& v) { o.film.crf = int(parseWhole(flag, v, 0, 51)); }},
    {.name = "--bitrate", .modes = kFilm, .metavar = "N[k|M]", .value = Value::Text,
     .help = "The bit rate instead of --crf.",
     .store = [](Options& o, std::string_view, const std::string& v) { o.film.bitrate = film::parseBitrate(v); }},
    {.name = "--encoder-preset", .modes = kFilm, .metavar = "ultrafast|...|medium|...|veryslow", .value = Value::Text,
     .help = "x264's or x265's preset for h264 and hevc (medium): a faster one encodes sooner into more bytes at the "
             "same --crf (docs/RIG.md).",
     .store = [](Options& o, std::string_view, const std::string& v) { o.film.preset = v; }},
    {.name = "--pix-fmt", .modes = kFilm, .metavar = "yuv420p|yuv444p|yuv420p10le|yuv444p10le", .value = Value::Choice,
     .help = "The film's pixel format.",
     .store = [](Options& o, std::string_view, const std::string& v) { o.film.pixelFormat = v; }},
    {.name = "--full-range", .modes = kFilm, .value = Value::None,
     .help = "Full-range BT.709 instead of limited range.",
     .store = [](Options& o, std::string_view, const std::string&) { o.film.fullRange = true; }},

    // compare: the golden metric's per-case loosening (tests/golden/cases.txt), so any binary checks a case
    // as the suite does (scripts/golden-cases).
    {.name = "--fail-fraction", .modes = kCompare, .metavar = "F", .value = Value::Text,
     .help = "The fraction of pixels that may differ, 0 to 1 (0.002).",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) {
           o.compareThresholds.failFraction = parseMetric(flag, v, 0.0, 1.0);
         }},
    {.name = "--hard-limit", .modes = kCompare, .metavar = "H", .value = Value::Text,
     .help = "The largest difference any pixel may have (0.25).",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) {
           o.compareThresholds.hardLimit = float(parseMetric(flag, v, 0.0, 1e9));
         }},
    {.name = "--lowpass", .modes = kCompare, .metavar = "N", .value = Value::Text,
     .help = "Also compares averages over N x N blocks, for pictures whose single pixels may flip (0 to 4096; "
             "0: off).",
     .store =
         [](Options& o, std::string_view flag, const std::string& v) {
           o.compareThresholds.block = int(parseMetric(flag, v, 0.0, 4096.0));
         }},

    {.name = "--export-preset", .modes = kExport, .metavar = "[SCENE.]NAME", .value = Value::Preset,
     .requiredIn = kExport,
     .help = "Writes one of your presets to --out, as a file --preset-file applies on any machine.",
     .store =
         [](Options& o, std::string_view, const std::string& v) {
           o.mode = Mode::ExportPreset;
           o.exportPreset = parsePreset(v);
         }},

    // The listings: each a mode of its own, taking what it needs (--validate) and ignoring the rest.
    {.name = "--list-params", .modes = kListing, .metavar = "[SCENE]", .value = Value::OptionalScene,
     .help = "Each scene's parameters (or one scene's) with type, range, default and help, its actions and its "
             "presets, yours among them.",
     .store = sceneListing<Mode::ListParams>},
    {.name = "--list-keys", .modes = kListing, .metavar = "[SCENE]", .value = Value::OptionalScene,
     .help = "Each scene's parameters (or one scene's) as SCENE.KEY, one a line: for scripts and completion.",
     .store = sceneListing<Mode::ListKeys>},
    {.name = "--list-presets", .modes = kListing, .metavar = "[SCENE]", .value = Value::OptionalScene,
     .help = "Each scene's presets (or one scene's), its own then yours, as SCENE.NAME, one a line.",
     .store = sceneListing<Mode::ListPresets>},
    {.name = "--list-scenes", .modes = kListing, .value = Value::None,
     .help = "The scenes: key, name and title.", .store = listing<Mode::ListScenes>},
    {.name = "--list-devices", .modes = kListing, .value = Value::None,
     .help = "The Vulkan devices, the default one marked.", .store = listing<Mode::ListDevices>},
    {.name = "--list-monitors", .modes = kListing, .value = Value::None,
     .help = "The monitors, for --monitor and --outputs.", .store = listing<Mode::ListMonitors>},
    {.name = "--help", .modes = kListing, .value = Value::None, .help = "This text.",
     .store = listing<Mode::Help>, .alias = "-h"},
    {.name = "--version", .modes = kListing, .value = Value::None, .help = "The version and the commit it was built from.",
     .store = listing<Mode::Version>},
    {.name = "--help-man", .modes = kListing, .value = Value::None,
     .help = "This text as a man page (roff), for packages.", .store = listing<Mode::HelpMan>},
    {.name = "--help-completion", .modes = kListing, .value = Value::None,
     .help = "The bash completion script, for packages.", .store = listing<Mode::HelpCompletion>},
};

constexpr ModeInfo kModes[] = {
    {.bit = kGallery, .word = "", .title = "the gallery",
     .about = "A window showing one scene at a time, with a menu. Keys: 1-9 switch scene, Tab hides "
              "the UI, F1 or ? shows help, V toggles vsync, P pauses, . steps while paused, F5 restarts the scene, "
              "M mutes, F7 projector setup, F9 live capture, F11 fullscreen, F12 screenshot, Esc quits."},
    {.bit = kHeadless, .word = "--headless", .title = "--headless",
     .about = "Renders with no window: frame k shows time SECONDS + k/60, and the last frame is written."},
    {.bit = kRecord, .word = "record", .title = "record",
     .about = "Renders a film at a fixed 1/F s a frame: into a folder as frame_000000.exr ... (skipping frames "
              "already there; scenes with sound also write audio.wav, and record.json keeps the film's parameters, "
              "so a run resumes only the same film), or, to --out FILM.mp4, .mov or .mkv, encoded as it renders "
              "with the scene's sound (BT.709).",
     .mode = Mode::Record},
    {.bit = kEncode, .word = "encode", .operands = "FOLDER", .title = "encode",
     .about = "Turns a recorded sequence and its audio.wav into a film, as record does.", .mode = Mode::Encode},
    {.bit = kBench, .word = "bench", .title = "bench",
     .about = "Times every pass with GPU timestamps and writes medians and 95th percentiles as JSON.",
     .mode = Mode::Bench},
    {.bit = kCompare, .word = "compare", .operands = "REFERENCE.exr CANDIDATE.exr", .title = "compare",
     .about = "Applies the golden metric to two EXR files: exit 0 when they match, 2 when they do not, 1 when a "
              "file cannot be read.",
     .mode = Mode::Compare},
    {.bit = kExport, .word = "--export-preset", .title = "--export-preset",
     .about = "Writes one of your presets as a file."},
    {.bit = kListing, .word = "", .title = "the listings", .about = "Each prints its list and exits."},
};

}  // namespace

std::span<const Flag> table() { return kFlags; }
std::span<const ModeInfo> modes() { return kModes; }

const Flag* find(std::string_view arg) {
  for (const Flag& flag : kFlags)
    if (flag.name == arg || (!flag.alias.empty() && flag.alias == arg)) return &flag;
  return nullptr;
}

const ModeInfo* subcommand(std::string_view word) {
  for (const ModeInfo& mode : kModes)
    if (mode.word == word && !word.empty() && !word.starts_with("-")) return &mode;
  return nullptr;
}

unsigned checkedBit(Mode mode) {
  switch (mode) {
    case Mode::Gallery: return kGallery;
    case Mode::Headless: return kHeadless;
    case Mode::Bench: return kBench;
    case Mode::Record: return kRecord;
    case Mode::Encode: return kEncode;
    case Mode::Compare: return kCompare;
    case Mode::ExportPreset: return kExport;
    default: return 0;  // the listings take what they need and ignore the rest
  }
}

std::string_view modeTitle(unsigned bit) {
  for (const ModeInfo& mode : kModes)
    if (mode.bit == bit) return mode.title;
  return {};
}

std::string modeHeading(const ModeInfo& mode) {
  std::string title(mode.title);
  if (title.starts_with("the ")) title.front() = 'T';  // a command or a flag stays as it is typed
  return title;
}

std::string joinAnd(const std::vector<std::string_view>& names) {
  std::string text;
  for (size_t n = 0; n < names.size(); ++n)
    text += fmt::format("{}{}", n == 0 ? "" : n + 1 == names.size() ? " and " : ", ", names[n]);
  return text;
}

std::string modeList(unsigned modes) {
  std::vector<std::string_view> names;
  for (const unsigned bit : {kGallery, kHeadless, kBench, kRecord, kEncode, kCompare})  // the runs, in this order
    if (modes & bit) names.push_back(modeTitle(bit));
  return joinAnd(names) + ((modes & ~unsigned(kExport | kListing)) == kGallery ? "" : " runs");
}

std::string repeatableList() {
  std::vector<std::string_view> names;
  for (const Flag& flag : kFlags)
    if (flag.repeatable) names.push_back(flag.name);
  return joinAnd(names);
}

std::vector<SynopsisItem> synopsis(const ModeInfo& mode) {
  std::vector<SynopsisItem> items;
  for (const bool required : {true, false})
    for (const Flag& flag : kFlags)
      if ((flag.modes & mode.bit) && flag.name != mode.word && bool(flag.requiredIn & mode.bit) == required)
        items.push_back({&flag, required});
  return items;
}

std::vector<FlagGroup> groups() {
  std::vector<FlagGroup> list;
  for (const Flag& flag : kFlags) {
    auto group = std::ranges::find(list, flag.modes, &FlagGroup::modes);
    if (group == list.end()) {
      std::string title = flag.modes == kListing  ? std::string("The listings: each prints and exits")
                          : flag.modes == kExport ? std::string("--export-preset")
                                                  : "For " + modeList(flag.modes);
      group = list.insert(list.end(), {flag.modes, std::move(title), {}});
    }
    group->flags.push_back(&flag);
  }
  return list;
}

}  // namespace vitrine::flags
