#pragma once
// A parameter change that would freeze the window for seconds (a million more strands, a 256^3
// lattice) is not applied at once: the panel asks first, and a remote client is refused. Pure logic
// on the change's cost ratio (SceneRenderer::costRatio) and the frame time now.
#include <fmt/format.h>

#include <string>

namespace vitrine::host {

inline constexpr double kFreezeMs = 1500.0;  // a frame this long is a window that has stopped answering

// Empty when the change is fine; else a sentence saying what it would cost here.
inline std::string freezeWarning(double costRatio, double frameMs) {
  const double expected = costRatio * frameMs;
  if (costRatio <= 2.0 || expected < kFreezeMs) return {};
  return fmt::format("This change makes each frame about {:.0f} times the work: about {:.1f} s a frame here, "
                     "and the window would stop answering meanwhile.",
                     costRatio, expected / 1000.0);
}

}  // namespace vitrine::host
