// The fuzz build links no scenes (their GPU code): a catalogue whose only action is neon's "release",
// enough for commandFromOsc to tell an action from a parameter.
#include "remote/catalogue.h"

namespace vitrine::remote {

Catalogue::Catalogue() = default;

bool Catalogue::hasAction(std::string_view scene, std::string_view action) const {
  return scene == "neon" && action == "release";
}

}  // namespace vitrine::remote
