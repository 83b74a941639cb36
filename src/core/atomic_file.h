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

// A temporary beside `target` for a writer that fills it over a long time (a film's encoder, frame after
// frame) rather than in one call: named as replaceAtomically names its own (".film.mp4.HOST-PID-....tmp.mp4",
// so removeStaleTemporaries clears one a killed writer left), removed when destroyed unless commit() has
// flushed it to the disk and renamed it over the target. Until then the target is left as it was.
class PendingFile {
 public:
  explicit PendingFile(const std::filesystem::path& target);  // makes it, empty; throws vitrine::Error
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // fsync, then rename over the target. Throws vitrine::Error with the system's reason.
  void commit();

 private:
  std::filesystem::path target_, path_;
  bool committed_ = false;
};

// Throws vitrine::Error with the system's reason ("Read-only file system", "No space left on device")
// unless a file can be made and filled in `folder` now: checked before work whose output would go there.
void checkWritableFolder(const std::filesystem::path& folder);

// Removes the temporaries in `folder` that writers on this machine left when they died (killed, the
// power cut): those whose process no longer exists. Another live process's, or another machine's (a
// shared folder), are kept. Returns the paths removed.
std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& folder);
}  // namespace vitrine
