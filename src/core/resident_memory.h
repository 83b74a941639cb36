#pragma once
// The process's resident memory (VmRSS), which on a CPU device like lavapipe also holds every Vulkan
// allocation: what the soak watches, sampled by frames so that a fast GPU's short run is measured too.
#include <cstdint>
#include <optional>
#include <string>

namespace vitrine {

// Bytes resident now; none where /proc/self/status cannot tell (not Linux).
std::optional<uint64_t> residentBytes();

// Resident memory over a run of `frames` frames, sampled by frames, not seconds: after the first fifth
// (the soak's warm-up) and at twenty frames spread over the rest, for the peak. scripts/soak reads the
// line it makes.
class ResidentByFrames {
 public:
  explicit ResidentByFrames(uint32_t frames);
  uint32_t warmFrames() const { return warm_; }
  // Before frame `frame` is made.
  void before(uint32_t frame);
  // "resident memory: W MiB after frame N, peak P MiB, E MiB at the end", the end measured now; empty
  // when the run ended within its warm-up or the system cannot tell.
  std::string line() const;

 private:
  uint32_t warm_, every_, made_ = 0;
  std::optional<uint64_t> atWarm_, peak_;
};

}  // namespace vitrine
