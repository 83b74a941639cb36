#include "core/user_dirs.h"

#include "core/bounded_file.h"

#include <cstdlib>
#include <string>

namespace vitrine {
namespace {

namespace fs = std::filesystem;

// user-dirs.dirs is a few hundred bytes; a larger one is not the file xdg-user-dirs writes.
constexpr uintmax_t kMaxUserDirsBytes = 64 * 1024;

// A folder's key in user-dirs.dirs and its folder under $HOME when the file names none.
struct DirNames {
  std::string_view key, fallback;
};
DirNames namesOf(UserDir dir) {
  switch (dir) {
    case UserDir::Pictures: return {"XDG_PICTURES_DIR", "Pictures"};
    case UserDir::Videos: return {"XDG_VIDEOS_DIR", "Videos"};
    case UserDir::Documents: return {"XDG_DOCUMENTS_DIR", "Documents"};
  }
  return {};
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// The shell's double-quoted word as the file writes it: quotes removed, backslash escapes undone.
std::string unquoted(std::string_view value) {
  if (value.size() < 2 || value.front() != '"' || value.back() != '"') return std::string(value);
  std::string out;
  for (size_t i = 1; i + 1 < value.size(); ++i) {
    if (value[i] == '\\' && i + 2 < value.size()) ++i;
    out += value[i];
  }
  return out;
}

fs::path environmentPath(const char* name) {
  const char* value = std::getenv(name);
  return value && *value ? fs::path(value) : fs::path();
}

}  // namespace

fs::path userDirFromFile(std::string_view text, UserDir dir, const fs::path& home) {
  fs::path found;
  while (!text.empty()) {  // the last assignment wins, as when the shell sources the file
    const size_t end = text.find('\n');
    const std::string_view line = trimmed(text.substr(0, end));
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    if (line.empty() || line.front() == '#') continue;
    const size_t equals = line.find('=');
    if (equals == std::string_view::npos || trimmed(line.substr(0, equals)) != namesOf(dir).key) continue;
    const std::string value = unquoted(trimmed(line.substr(equals + 1)));
    if (value == "$HOME" || value.starts_with("$HOME/")) {
      if (home.empty()) continue;
      const std::string rest = value.substr(std::string_view("$HOME").size());
      found = rest.size() > 1 ? home / rest.substr(1) : home;
    } else if (fs::path(value).is_absolute()) {
      found = value;
    }
  }
  return found;
}

fs::path configHome() {
  if (fs::path config = environmentPath("XDG_CONFIG_HOME"); config.is_absolute()) return config;
  if (fs::path home = environmentPath("HOME"); !home.empty()) return home / ".config";
  return {};
}

fs::path userDir(UserDir dir) {
  const fs::path home = environmentPath("HOME");
  if (const fs::path config = configHome(); !config.empty()) {
    try {
      const fs::path named = userDirFromFile(readBoundedFile(config / "user-dirs.dirs", kMaxUserDirsBytes), dir, home);
      if (!named.empty()) return named;
    } catch (const FileRefused&) {  // no such file (most machines without a desktop): the defaults
    }
  }
  return home.empty() ? fs::path() : home / namesOf(dir).fallback;
}

fs::path vitrineUserDir(UserDir dir) {
  const fs::path folder = userDir(dir);
  return folder.empty() ? fs::path("Vitrine") : folder / "Vitrine";
}

}  // namespace vitrine
