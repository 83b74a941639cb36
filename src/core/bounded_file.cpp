#include "core/bounded_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <utility>

#include "core/error.h"

namespace vitrine {

std::string_view fileKind(unsigned mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a fifo";
  if (S_ISSOCK(mode)) return "a socket";
  return "something other than a file";
}

std::string bytesInWords(uintmax_t bytes) {
  constexpr std::string_view units[] = {"bytes", "KiB", "MiB", "GiB"};
  size_t unit = 0;
  while (unit + 1 < std::size(units) && bytes >= 1024 && bytes % 1024 == 0) bytes /= 1024, ++unit;
  return fmt::format("{} {}", bytes, units[unit]);
}

BoundedFile::BoundedFile(const std::filesystem::path& path, uintmax_t maxBytes) : maxBytes_(maxBytes) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) {
    const int error = errno;
    throw FileRefused{error == ENOENT ? "it does not exist" : fmt::format("it cannot be opened: {}", osReason(error))};
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0 || !S_ISREG(info.st_mode)) {
    const mode_t mode = info.st_mode;
    ::close(fd_);
    throw FileRefused{fmt::format("it is {}, not a regular file", fileKind(mode))};
  }
  size_ = uintmax_t(info.st_size);
  if (size_ > maxBytes_) {
    ::close(fd_);
    throw FileRefused{fmt::format("it is larger than {}", bytesInWords(maxBytes_))};
  }
}

BoundedFile::~BoundedFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::string BoundedFile::readAll() {
  // One byte past the limit, in case the file grew since it was opened.
  std::string bytes(size_t(size_) + 1, '\0');
  size_t got = 0;
  for (;;) {
    if (got == bytes.size()) {
      if (bytes.size() > maxBytes_) throw FileRefused{fmt::format("it is larger than {}", bytesInWords(maxBytes_))};
      bytes.resize(std::min<uintmax_t>(maxBytes_ + 1, bytes.size() * 2));
    }
    const ssize_t n = ::read(fd_, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileRefused{fmt::format("it cannot be read: {}", osReason(errno))};
    if (n == 0) break;
    got += size_t(n);
  }
  bytes.resize(got);
  return bytes;
}

int BoundedFile::release() {
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
  return std::exchange(fd_, -1);
}

std::string readBoundedFile(const std::filesystem::path& path, uintmax_t maxBytes) {
  return BoundedFile(path, maxBytes).readAll();
}

void checkBoundedFile(const std::filesystem::path& path, uintmax_t maxBytes) { BoundedFile(path, maxBytes); }

}  // namespace vitrine
