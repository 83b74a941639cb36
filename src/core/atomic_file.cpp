#include "core/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
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

// Process id, a per-process counter and a random word: unique across threads and concurrent runs;
// O_EXCL below settles the rare clash.
std::string uniqueWord() {
  static std::atomic<uint32_t> counter{0};
  thread_local std::mt19937 random{std::random_device{}()};
  return fmt::format("{:x}-{:x}-{:08x}", static_cast<unsigned long>(::getpid()), counter++, random());
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
      throw Error(fmt::format("Cannot write {}: {}", target.string(), std::system_category().message(error)));
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
