#include "core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <charconv>
#include <regex>
#include <cerrno>
#include <random>
#include <string>
#include <system_error>

#include "core/error.h"

namespace vitrine {
namespace {

constexpr size_t kMaxFileName = 255;  // NAME_MAX on every file system Vitrine writes to

// The longest prefix of `name` of at most `bytes` bytes that does not cut a UTF-8 character in two.
std::string utf8Prefix(const std::string& name, size_t bytes) {
  if (name.size() <= bytes) return name;
  while (bytes > 0 && (static_cast<unsigned char>(name[bytes]) & 0xC0) == 0x80) --bytes;
  return name.substr(0, bytes);
}

// ".NAME.UNIQUE.tmpEXT": hidden, beside the target, with the target's extension last (image writers
// pick the format from it), and short enough for the file system however long NAME is.
std::filesystem::path temporaryName(const std::filesystem::path& target, const std::string& unique) {
  const std::string name = target.filename().string();
  std::string extension = target.extension().string();
  const size_t fixed = 1 + 1 + unique.size() + 4;  // ".", ".", UNIQUE, ".tmp"
  if (fixed + extension.size() >= kMaxFileName) extension.clear();  // an absurd extension: nothing sniffs it
  const std::string kept = utf8Prefix(name, kMaxFileName - fixed - extension.size());
  return target.parent_path() / fmt::format(".{}.{}.tmp{}", kept, unique, extension);
}

// This machine's name as letters, digits and '-' only (at most 32), for temporary names: a folder
// shared between machines (a render farm's) holds temporaries of writers on several hosts.
const std::string& hostWord() {
  static const std::string word = [] {
    char name[256] = {};
    if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return std::string("host");
    std::string out;
    for (const char* c = name; *c && out.size() < 32; ++c)
      if (std::isalnum(static_cast<unsigned char>(*c)) || *c == '-') out += *c;
    return out.empty() ? std::string("host") : out;
  }();
  return word;
}

// Host, process id, a per-process counter and a random word: unique across threads, concurrent runs
// and machines; O_EXCL below settles the rare clash. removeStaleTemporaries reads the host and the
// process back.
std::string uniqueWord() {
  static std::atomic<uint32_t> counter{0};
  thread_local std::mt19937 random{std::random_device{}()};
  return fmt::format("{}-{:x}-{:x}-{:08x}", hostWord(), static_cast<unsigned long>(::getpid()), counter++, random());
}

// ".NAME.HOST-PID-COUNTER-RANDOM.tmp[EXT]" as temporaryName makes them: the host and the process.
const std::regex& temporaryPattern() {
  static const std::regex pattern(R"(^\..*\.([A-Za-z0-9-]+)-([0-9a-f]+)-[0-9a-f]+-[0-9a-f]{8}\.tmp(\.[^.]*)?$)");
  return pattern;
}

// Writes all of `bytes` to the new file `path`, flushes it to the disk and closes it, checking each
// step: a full disk or a file size limit shows up in one of them, with the operating system's reason.
void writeAll(const std::filesystem::path& path, const std::filesystem::path& target,
              std::span<const unsigned char> bytes) {
  auto fail = [&](int error) {
    throw Error(fmt::format("Cannot write {}: {}", target.string(), osReason(error)));
  };
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) fail(errno);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      const int error = wrote < 0 ? errno : ENOSPC;  // a write of nothing: the disk took no more
      ::close(fd);
      fail(error);
    }
    done += size_t(wrote);
  }
  if (::fsync(fd) != 0) {
    const int error = errno;
    ::close(fd);
    fail(error);
  }
  struct stat info {};
  const bool sized = ::fstat(fd, &info) == 0;
  if (::close(fd) != 0) fail(errno);
  if (!sized || uint64_t(info.st_size) != bytes.size())
    throw Error(fmt::format("Cannot write {}: {} of its {} bytes reached the disk", target.string(),
                            sized ? uint64_t(info.st_size) : 0, bytes.size()));
}

// Creates a new, empty file under a fresh temporary name (mode 0666 less the umask, as a plain
// create would) and returns its path. Throws with the operating system's reason.
std::filesystem::path createTemporary(const std::filesystem::path& target) {
  for (int attempt = 0;; ++attempt) {
    const auto temporary = temporaryName(target, uniqueWord());
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return temporary;
    }
    const int error = errno;  // before anything else can change it
    if (error != EEXIST || attempt >= 100)
      throw Error(fmt::format("Cannot write {}: {}", target.string(), osReason(error)));
  }
}

}  // namespace

void replaceAtomically(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path&)>& write) {
  const auto temporary = createTemporary(target);
  std::error_code ignored;
  try {
    write(temporary);
  } catch (...) {
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  std::error_code renamed;
  std::filesystem::rename(temporary, target, renamed);
  if (renamed) {
    std::filesystem::remove(temporary, ignored);
    throw Error(fmt::format("Cannot write {}: {}", target.string(), renamed.message()));
  }
}

}  // namespace vitrine

namespace vitrine {

void writeFileAtomically(const std::filesystem::path& target, std::span<const unsigned char> bytes) {
  replaceAtomically(target, [&](const std::filesystem::path& temporary) { writeAll(temporary, target, bytes); });
}

std::vector<std::filesystem::path> removeStaleTemporaries(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> removed;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    std::smatch match;
    if (!std::regex_match(name, match, temporaryPattern()) || match[1].str() != hostWord()) continue;
    // A process number too long for any system (a look-alike name someone else made) is not a writer's.
    const std::string digits = match[2].str();
    unsigned long pid = 0;
    if (const auto [end, failed] = std::from_chars(digits.data(), digits.data() + digits.size(), pid, 16);
        failed != std::errc() || end != digits.data() + digits.size())
      continue;
    // Signal 0 only asks whether the process exists; EPERM means it does, under another user.
    if (pid == 0 || pid > 0x7fffffffUL || ::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;
    std::error_code gone;
    if (entry.is_regular_file(gone) && std::filesystem::remove(entry.path(), gone)) removed.push_back(entry.path());
  }
  return removed;
}

}  // namespace vitrine

namespace vitrine {

void checkWritableFolder(const std::filesystem::path& folder) {
  // A file made and filled the way every output is (the temporary's name, so a probe left by a killed
  // run is removed like any stale temporary), then removed: the mode bits are not enough (root writes
  // through them; a read-only mount or a full disk stops everyone).
  const auto probe = temporaryName(folder / "probe", uniqueWord());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw Error(fmt::format("Cannot write into {}: {}.", folder.string(), osReason(errno)));
  ::close(fd);
  try {
    const std::vector<unsigned char> page(4096, 0);
    writeAll(probe, folder, page);
  } catch (const Error&) {
    std::error_code ignored;
    std::filesystem::remove(probe, ignored);
    throw;
  }
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

}  // namespace vitrine

namespace vitrine {

PendingFile::PendingFile(const std::filesystem::path& target) : target_(target), path_(createTemporary(target)) {}

PendingFile::~PendingFile() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove(path_, ignored);
}

void PendingFile::commit() {
  // The writer has closed it; flushed before the rename, so a power cut cannot leave the target's name
  // on a file whose blocks never reached the disk.
  const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int error = errno;
    if (fd >= 0) ::close(fd);
    throw Error(fmt::format("Cannot write {}: {}", target_.string(), osReason(error)));
  }
  ::close(fd);
  std::error_code renamed;
  std::filesystem::rename(path_, target_, renamed);
  if (renamed) throw Error(fmt::format("Cannot write {}: {}", target_.string(), renamed.message()));
  committed_ = true;
}

}  // namespace vitrine
