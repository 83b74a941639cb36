#pragma once
// Where a desktop user keeps pictures, videos and documents: the XDG user folders (xdg-user-dirs), as
// `xdg-user-dir PICTURES` finds them. The installed gallery writes screenshots, captures and exported
// presets there, under Vitrine/, never into whatever folder it was started from.
#include <filesystem>
#include <string_view>

namespace vitrine {

enum class UserDir { Pictures, Videos, Documents };

// The folder $XDG_CONFIG_HOME/user-dirs.dirs names for `dir` (`XDG_PICTURES_DIR="$HOME/Bilder"`, $HOME
// expanded to `home`). Empty when `text` does not name it, or names it neither "$HOME/..." nor absolute,
// the only two forms the file's format allows.
std::filesystem::path userDirFromFile(std::string_view text, UserDir dir, const std::filesystem::path& home);

// $XDG_CONFIG_HOME when it is absolute (the Base Directory spec ignores a relative one), else $HOME/.config;
// empty when neither is set.
std::filesystem::path configHome();

// The user's folder for `dir`: what user-dirs.dirs names, else $HOME/Pictures, Videos or Documents; empty
// when HOME is not set (the caller then writes relative to the working directory).
std::filesystem::path userDir(UserDir dir);

// Where the gallery's own files of that kind go: userDir(dir)/Vitrine, else "Vitrine" in the working folder.
std::filesystem::path vitrineUserDir(UserDir dir);

}  // namespace vitrine
