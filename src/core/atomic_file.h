#pragma once
#include <filesystem>
#include <functional>
#include <span>
#include <vector>

namespace vitrine {
// Calls write(temporary) for a new, empty, hidden file beside target with a name no other writer
// shares (same extension last, so format-sniffing writers still work), then renames it over target:
// readers see the old file or a new one, never half, and concurrent writers do not collide. Errors
// are vitrine::Error with the operating system's reason; the temporary is removed on failure.
void replaceAtomically(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path& temporary)>& write);

// Writes `bytes` as target through replaceAtomically, checking every write(), the fsync and the close
// and that the file on disk holds every byte before it is renamed into place: on a full disk or past a
// file size limit the old target stays as it was and the error names the operating system's reason
// ("No space left on device"). Writers that encode to memory first (images) go through here.
void writeFileAtomically(const std::filesystem::path& target, std::span<const unsigned char> bytes);

// Throws vitrine::Error with the system's reason ("Read-only file system", "No space left on device")
// unless a file can be made and filled in `folder` now: checked before work whose output would go there.
void checkWritableFolder(const std::filesystem::path& folder);

// Removes the temporaries in `folder` that writers on this machine left when they died (killed, the
// power cut): those whose process no longer exists. Another live process's, or another machine's (a
// shared folder), are kept. Returns the paths removed.
std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& folder);
}  // namespace vitrine
