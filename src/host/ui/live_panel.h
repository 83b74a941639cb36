#pragma once
// The menu's live input section (docs/LIVE.md): audio input on or off and its device, what each input
// is doing, the mappings playing the scene with their meters, a line to add one, MIDI learn, and a
// mapping file to save or load. Like the parameter panel it changes nothing itself: it returns what
// the user asked for, and the gallery applies it through the same checks as --map.
#include "live/modulator.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::host {

enum class LearnStep { Idle, ClickParameter, MoveControl };

struct LivePanelState {
  bool audioOn = false;
  bool audioFromFile = false;             // --audio-in: a file feeds the sources, the switch is not the user's
  std::string audioDevice;                // empty: the default output's monitor
  std::span<const std::string> devices;   // "INDEX: NAME" of every capture device
  std::vector<std::string> status;        // one line per input
  std::vector<live::MappingState> mappings;  // playing the scene now
  size_t userMappings = 0;                // the first this many are the user's own: removable
  LearnStep learn = LearnStep::Idle;
  std::string learnKey;                   // the parameter waiting for a control
  std::string message;                    // the last refusal or what was learnt
};

struct LivePanelChoice {
  std::optional<bool> audioOn;
  std::optional<std::string> audioDevice;
  std::optional<std::string> add;     // a mapping line typed
  std::optional<size_t> remove;       // one of the user's mappings
  bool learn = false, cancelLearn = false;
  std::optional<std::string> save, load;  // a mapping file
};

class LivePanel {
 public:
  LivePanelChoice draw(const LivePanelState& state);

 private:
  char line_[256] = {};
  char file_[256] = "mappings.map";
};

}  // namespace vitrine::host
