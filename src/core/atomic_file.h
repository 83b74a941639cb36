#pragma once
#include <filesystem>
#include <functional>

namespace vitrine {
// Calls write(temporary) for a hidden file beside target (same extension, so format-sniffing
// writers still work), then renames it over target: readers see the old file or the new, never half.
void replaceAtomically(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path& temporary)>& write);
}  // namespace vitrine
