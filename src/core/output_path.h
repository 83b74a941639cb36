#pragma once
#include <filesystem>

namespace vitrine {
// Fails early, with the path in the message, when a file could not be written there.
void checkWritable(const std::filesystem::path& path);
}  // namespace vitrine
