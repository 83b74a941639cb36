#include "core/resident_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace vitrine {

std::optional<uint64_t> residentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.starts_with("VmRSS:")) return std::stoull(line.substr(6)) * 1024;  // "VmRSS:   123456 kB"
  return std::nullopt;
}

ResidentByFrames::ResidentByFrames(uint32_t frames)
    : warm_(std::max(frames / 5, 1u)), every_(std::max((frames - std::min(frames, warm_)) / 20, 1u)) {}

void ResidentByFrames::before(uint32_t frame) {
  made_ = frame + 1;
  if (frame == warm_) atWarm_ = residentBytes();
  if (frame >= warm_ && (frame - warm_) % every_ == 0)
    if (const auto now = residentBytes()) peak_ = std::max(peak_.value_or(0), *now);
}

std::string ResidentByFrames::line() const {
  const std::optional<uint64_t> end = residentBytes();
  if (!atWarm_ || !end || made_ <= warm_) return {};
  constexpr double kMiB = 1048576.0;
  return fmt::format("resident memory: {:.1f} MiB after frame {}, peak {:.1f} MiB, {:.1f} MiB at the end",
                     double(*atWarm_) / kMiB, warm_, double(std::max(peak_.value_or(0), *end)) / kMiB,
                     double(*end) / kMiB);
}

}  // namespace vitrine
