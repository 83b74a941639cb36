#pragma once
#include <filesystem>
#include <functional>

namespace vitrine {
// Calls write(temporary) for a new, empty, hidden file beside target with a name no other writer
// shares (same extension last, so format-sniffing writers still work), then renames it over target:
// readers see the old file or a new one, never half, and concurrent writers do not collide. Errors
// are vitrine::Error with the operating system's reason; the temporary is removed on failure.
void replaceAtomically(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path& temporary)>& write);
}  // namespace vitrine
