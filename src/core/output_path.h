#pragma once
#include <filesystem>

namespace vitrine {
// Fails early, with the path in the message, when a file could not be written there: the folder is
// missing or not writable, or the path is a folder, a device, a fifo or a file with no write bit.
void checkWritable(const std::filesystem::path& path);
}  // namespace vitrine
