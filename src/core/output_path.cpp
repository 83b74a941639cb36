#include "core/output_path.h"

#include "core/bounded_file.h"
#include "core/error.h"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vitrine {

void checkWritable(const std::filesystem::path& path) {
  const auto parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec))
    throw Error(fmt::format("Cannot write {}: the folder {} does not exist.", path.string(), parent.string()));
  if (::access(parent.c_str(), W_OK) != 0)
    throw Error(fmt::format("Cannot write {}: the folder {} is not writable.", path.string(), parent.string()));
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return;  // a new file
  if (S_ISDIR(info.st_mode)) throw Error(fmt::format("Cannot write {}: it is a folder.", path.string()));
  // Outputs are replaced by a rename, which would put a file where a device or fifo was.
  if (!S_ISREG(info.st_mode))
    throw Error(fmt::format("Cannot write {}: it is {}, not a regular file.", path.string(), fileKind(info.st_mode)));
  // The mode bits, not access(W_OK): that always says yes to root, as in CI.
  if ((info.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
    throw Error(fmt::format("Cannot write {}: it is read-only (mode {:o}).", path.string(), info.st_mode & 07777));
}

}  // namespace vitrine
