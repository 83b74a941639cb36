#include "core/user_dirs.h"

#include <gtest/gtest.h>

#include "support/scoped_env.h"
#include "support/temp_folder.h"

#include <fstream>

namespace vitrine {
namespace {

namespace fs = std::filesystem;
using test::ScopedEnv;

// What xdg-user-dirs-update writes, in a language whose folders are not English.
constexpr std::string_view kGermanDesktop = R"(# This file is written by xdg-user-dirs-update
# If you want to change or add directories, just edit the line you're
# interested in. All local changes will be retained on the next run.
XDG_DESKTOP_DIR="$HOME/Schreibtisch"
XDG_PICTURES_DIR="$HOME/Bilder"
XDG_VIDEOS_DIR="/srv/media/Videos mit \"Leerzeichen\""
)";

TEST(UserDirsFile, ExpandsHomeAndTakesAbsolutePathsAsWritten) {
  EXPECT_EQ(userDirFromFile(kGermanDesktop, UserDir::Pictures, "/home/anna"), fs::path("/home/anna/Bilder"));
  EXPECT_EQ(userDirFromFile(kGermanDesktop, UserDir::Videos, "/home/anna"),
            fs::path("/srv/media/Videos mit \"Leerzeichen\""));
}

TEST(UserDirsFile, IgnoresWhatTheFormatDoesNotAllow) {
  EXPECT_EQ(userDirFromFile("XDG_PICTURES_DIR=\"Bilder\"\n", UserDir::Pictures, "/home/anna"), fs::path());
  EXPECT_EQ(userDirFromFile("#XDG_PICTURES_DIR=\"/x\"\n", UserDir::Pictures, "/home/anna"), fs::path());
  EXPECT_EQ(userDirFromFile("XDG_PICTURES_DIR=\"$HOME/Bilder\"\n", UserDir::Pictures, ""), fs::path());
  EXPECT_EQ(userDirFromFile("", UserDir::Videos, "/home/anna"), fs::path());
  // "$HOME/" alone is the home folder itself (how a user turns a folder off).
  EXPECT_EQ(userDirFromFile("XDG_VIDEOS_DIR=\"$HOME/\"\r\n", UserDir::Videos, "/home/anna"), fs::path("/home/anna"));
  // Sourced by a shell, the last assignment wins.
  EXPECT_EQ(userDirFromFile("XDG_VIDEOS_DIR=\"/a\"\nXDG_VIDEOS_DIR=\"/b\"\n", UserDir::Videos, "/h"), fs::path("/b"));
}

class UserDirs : public test::TempFolderTest {};

TEST_F(UserDirs, ReadsTheFileInTheConfigHomeElseFallsBackToEnglishNames) {
  ScopedEnv home("HOME", (folder_ / "home").c_str());
  ScopedEnv config("XDG_CONFIG_HOME", (folder_ / "config").c_str());
  EXPECT_EQ(vitrineUserDir(UserDir::Pictures), folder_ / "home" / "Pictures" / "Vitrine");
  EXPECT_EQ(vitrineUserDir(UserDir::Videos), folder_ / "home" / "Videos" / "Vitrine");
  EXPECT_EQ(vitrineUserDir(UserDir::Documents), folder_ / "home" / "Documents" / "Vitrine");

  fs::create_directories(folder_ / "config");
  std::ofstream(folder_ / "config" / "user-dirs.dirs") << kGermanDesktop;
  EXPECT_EQ(vitrineUserDir(UserDir::Pictures), folder_ / "home" / "Bilder" / "Vitrine");
  EXPECT_EQ(userDir(UserDir::Videos), fs::path("/srv/media/Videos mit \"Leerzeichen\""));
}

TEST_F(UserDirs, ARelativeConfigHomeIsIgnoredAndNoHomeMeansTheWorkingFolder) {
  fs::create_directories(folder_ / ".config");
  std::ofstream(folder_ / ".config" / "user-dirs.dirs") << "XDG_PICTURES_DIR=\"$HOME/Fotos\"\n";
  {
    ScopedEnv home("HOME", folder_.c_str());
    ScopedEnv config("XDG_CONFIG_HOME", "relative/config");
    EXPECT_EQ(configHome(), folder_ / ".config");
    EXPECT_EQ(vitrineUserDir(UserDir::Pictures), folder_ / "Fotos" / "Vitrine");
  }
  ScopedEnv home("HOME", nullptr);
  ScopedEnv config("XDG_CONFIG_HOME", nullptr);
  EXPECT_EQ(vitrineUserDir(UserDir::Videos), fs::path("Vitrine"));
}

}  // namespace
}  // namespace vitrine
