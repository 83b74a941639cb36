#include "core/output_path.h"

#include "core/error.h"

#include <fmt/format.h>
#include <unistd.h>

namespace vitrine {

void checkWritable(const std::filesystem::path& path) {
  const auto parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::error_code ec;
  if (!std::filesystem::is_directory(parent, ec))
    throw Error(fmt::format("Cannot write {}: the folder {} does not exist.", path.string(), parent.string()));
  if (::access(parent.c_str(), W_OK) != 0)
    throw Error(fmt::format("Cannot write {}: the folder {} is not writable.", path.string(), parent.string()));
  if (std::filesystem::is_directory(path, ec))
    throw Error(fmt::format("Cannot write {}: it is a folder.", path.string()));
}

}  // namespace vitrine
