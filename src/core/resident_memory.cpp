#include "core/resident_memory.h"

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

}  // namespace vitrine
