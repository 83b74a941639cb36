#pragma once
// What the window asks of the glass this frame: the keys and the scene's actions read into requests,
// and files dropped on the window read into the background and panorama settings.
#include "scenes/glass/settings.h"
#include "scenes/scene.h"

#include <optional>

namespace vitrine::glass {

struct KeyRequests {
  bool shuffle = false;                    // Space, or the "shuffle" action
  bool nextPhoto = false;                  // R, or the "next_photo" action
  std::optional<DiamondView> diamondView;  // T, S, B, F: the diamond, seen from there
  bool zHeld = false;                      // three wavelengths without jitter while held
};

KeyRequests readKeys(const FrameInput& input);
// A view key shows the diamond from that view, whatever the shape was: a key that silently did nothing
// while pills or plates were showing read as a broken key.
void applyDiamondView(const KeyRequests& keys, Settings& settings);

// A dropped panorama (EXR) lights the scene when the environment is on; anything else is a backdrop.
void takeDroppedFiles(const FrameInput& input, Settings& settings);

}  // namespace vitrine::glass
